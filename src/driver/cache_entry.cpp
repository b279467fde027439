#include "driver/cache_entry.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace shaderport::driver {
namespace {

constexpr std::string_view kMagic = "SPRC";
// Far above any real entry (diagnostics are capped per file): a length beyond it
// is corruption, not data.
constexpr uint32_t kMaxEntryBytes = 64u << 20;

class Writer {
 public:
  void U8(uint8_t value) { bytes_.push_back(static_cast<char>(value)); }
  void U32(uint32_t value) { Raw(&value, sizeof value); }
  void U64(uint64_t value) { Raw(&value, sizeof value); }
  void Text(std::string_view text) {
    U32(static_cast<uint32_t>(text.size()));
    bytes_.append(text);
  }
  std::string& Bytes() { return bytes_; }

 private:
  void Raw(const void* data, size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  std::string bytes_;
};

// Every read is bounds-checked; after the first failure all reads fail.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  bool Ok() const { return ok_; }
  bool AtEnd() const { return at_ == bytes_.size(); }
  uint8_t U8() {
    uint8_t value = 0;
    Raw(&value, sizeof value);
    return value;
  }
  uint32_t U32() {
    uint32_t value = 0;
    Raw(&value, sizeof value);
    return value;
  }
  uint64_t U64() {
    uint64_t value = 0;
    Raw(&value, sizeof value);
    return value;
  }
  std::string Text() {
    const uint32_t size = U32();
    if (!Has(size)) return {};
    std::string text(bytes_.substr(at_, size));
    at_ += size;
    return text;
  }
  // A count of items, each at least `min_item_bytes` long: bounded by what is left.
  uint32_t Count(size_t min_item_bytes) {
    const uint32_t count = U32();
    if (ok_ && static_cast<uint64_t>(count) * min_item_bytes > bytes_.size() - at_) ok_ = false;
    return ok_ ? count : 0;
  }

 private:
  bool Has(size_t size) {
    if (ok_ && size > bytes_.size() - at_) ok_ = false;
    return ok_;
  }
  void Raw(void* out, size_t size) {
    if (!Has(size)) return;
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  std::string_view bytes_;
  size_t at_ = 0;
  bool ok_ = true;
};

uint64_t Checksum(std::string_view bytes) { return KeyHasher().Add(bytes).Finish().low; }

// Maps the run's file ids to the entry's, collecting generated files on the way.
class FileTable {
 public:
  FileTable(const FileReport& report, const SourceFile* common, const SourceManager& sources)
      : self_(report.file->Id()),
        common_(common != nullptr ? common->Id() : kNoFile),
        sources_(sources) {}

  bool Map(SourceRange& range) {
    if (!range.Valid()) return true;
    if (range.file == self_) {
      range.file = kSelfFile;
    } else if (range.file == common_) {
      range.file = kCommonFile;
    } else if (range.file < sources_.Size() && sources_.Get(range.file).IsSynthetic()) {
      generated_.emplace(range.file, 0);
      original_.push_back(&range);
    } else {
      return false;
    }
    return true;
  }

  // Generated files keep their creation order, so diagnostics sort as they did.
  std::vector<CachedText> Generated() {
    std::vector<CachedText> texts;
    for (auto& [id, index] : generated_) {
      index = kFirstGenerated + static_cast<FileId>(texts.size());
      const SourceFile& file = sources_.Get(id);
      texts.push_back({file.Name(), std::string(file.Text())});
    }
    for (SourceRange* range : original_) range->file = generated_.at(range->file);
    return texts;
  }

 private:
  FileId self_;
  FileId common_;
  const SourceManager& sources_;
  std::map<FileId, FileId> generated_;  // run id -> entry id
  std::vector<SourceRange*> original_;
};

void WriteRange(Writer& out, const SourceRange& range) {
  out.U32(range.file);
  out.U32(range.begin);
  out.U32(range.end);
}

// Clears `ok` when the range names a file the entry does not have.
SourceRange ReadRange(Reader& in, size_t generated_count, bool& ok) {
  SourceRange range;
  range.file = in.U32();
  range.begin = in.U32();
  range.end = in.U32();
  ok = ok && (range.file == kNoFile || range.file < kFirstGenerated + generated_count);
  return range;
}

}  // namespace

std::optional<std::string> EncodeCacheEntry(const FileReport& report, const SourceFile* common,
                                            const SourceManager& sources, const CacheKey& key) {
  if (report.file == nullptr) return std::nullopt;
  DiagnosticList diagnostics = report.diagnostics;
  FileTable table(report, common, sources);
  for (Diagnostic& diagnostic : diagnostics) {
    bool mapped = table.Map(diagnostic.range);
    for (DiagnosticNote& note : diagnostic.notes) mapped = mapped && table.Map(note.range);
    for (FixIt& fix : diagnostic.fixes) mapped = mapped && table.Map(fix.range);
    if (!mapped) return std::nullopt;
  }
  const std::vector<CachedText> generated = table.Generated();

  Writer out;
  out.Bytes().append(kMagic);
  out.U32(kCacheEntryVersion);
  out.U64(key.high);
  out.U64(key.low);
  const size_t payload_size_at = out.Bytes().size();
  out.U32(0);  // payload size, patched below
  const size_t payload_at = out.Bytes().size();
  out.Text(report.dialect);
  out.Text(report.stage);
  out.Text(report.harness);
  out.Text(report.target);
  out.Text(report.channels);
  out.U32(static_cast<uint32_t>(generated.size()));
  for (const CachedText& file : generated) {
    out.Text(file.name);
    out.Text(file.text);
  }
  out.U32(static_cast<uint32_t>(diagnostics.size()));
  for (const Diagnostic& diagnostic : diagnostics) {
    out.U8(static_cast<uint8_t>(diagnostic.severity));
    out.Text(diagnostic.rule_id);
    WriteRange(out, diagnostic.range);
    out.Text(diagnostic.message);
    out.U32(static_cast<uint32_t>(diagnostic.notes.size()));
    for (const DiagnosticNote& note : diagnostic.notes) {
      WriteRange(out, note.range);
      out.Text(note.message);
    }
    out.U32(static_cast<uint32_t>(diagnostic.fixes.size()));
    for (const FixIt& fix : diagnostic.fixes) {
      WriteRange(out, fix.range);
      out.Text(fix.replacement);
      out.U8(static_cast<uint8_t>(fix.safety));
    }
  }
  std::string& bytes = out.Bytes();
  const size_t payload_size = bytes.size() - payload_at;
  if (payload_size > kMaxEntryBytes) return std::nullopt;
  const auto size32 = static_cast<uint32_t>(payload_size);
  std::memcpy(bytes.data() + payload_size_at, &size32, sizeof size32);
  out.U64(Checksum(bytes));
  return std::move(bytes);
}

std::optional<CacheEntry> DecodeCacheEntry(std::string_view bytes, const CacheKey& key) {
  constexpr size_t kHeader = 4 + 4 + 16 + 4;
  constexpr size_t kTrailer = 8;
  if (bytes.size() < kHeader + kTrailer || bytes.substr(0, 4) != kMagic) return std::nullopt;
  uint64_t stored_checksum = 0;
  std::memcpy(&stored_checksum, bytes.data() + bytes.size() - kTrailer, kTrailer);
  if (stored_checksum != Checksum(bytes.substr(0, bytes.size() - kTrailer))) return std::nullopt;

  Reader header(bytes.substr(4, kHeader - 4));
  const uint32_t version = header.U32();
  const CacheKey stored_key{header.U64(), header.U64()};
  const uint32_t payload_size = header.U32();
  if (version != kCacheEntryVersion || stored_key != key ||
      payload_size != bytes.size() - kHeader - kTrailer) {
    return std::nullopt;
  }
  Reader in(bytes.substr(kHeader, payload_size));
  CacheEntry entry;
  entry.dialect = in.Text();
  entry.stage = in.Text();
  entry.harness = in.Text();
  entry.target = in.Text();
  entry.channels = in.Text();
  const uint32_t generated_count = in.Count(8);
  for (uint32_t i = 0; i < generated_count && in.Ok(); ++i) {
    CachedText file;
    file.name = in.Text();
    file.text = in.Text();
    entry.generated.push_back(std::move(file));
  }
  const uint32_t diagnostic_count = in.Count(1 + 4 + 12 + 4 + 4 + 4);
  bool ranges_ok = true;
  for (uint32_t i = 0; i < diagnostic_count && in.Ok(); ++i) {
    Diagnostic diagnostic;
    const uint8_t severity = in.U8();
    diagnostic.severity = static_cast<Severity>(std::min<uint8_t>(severity, 2));
    ranges_ok = ranges_ok && severity <= 2;
    diagnostic.rule_id = in.Text();
    diagnostic.range = ReadRange(in, generated_count, ranges_ok);
    diagnostic.message = in.Text();
    const uint32_t notes = in.Count(12 + 4);
    for (uint32_t n = 0; n < notes && in.Ok(); ++n) {
      DiagnosticNote note;
      note.range = ReadRange(in, generated_count, ranges_ok);
      note.message = in.Text();
      diagnostic.notes.push_back(std::move(note));
    }
    const uint32_t fixes = in.Count(12 + 4 + 1);
    for (uint32_t f = 0; f < fixes && in.Ok(); ++f) {
      FixIt fix;
      fix.range = ReadRange(in, generated_count, ranges_ok);
      fix.replacement = in.Text();
      const uint8_t safety = in.U8();
      ranges_ok = ranges_ok && safety <= 1;
      fix.safety = safety == 0 ? FixSafety::kSafe : FixSafety::kSuggestion;
      diagnostic.fixes.push_back(std::move(fix));
    }
    entry.diagnostics.push_back(std::move(diagnostic));
  }
  if (!in.Ok() || !in.AtEnd() || !ranges_ok) return std::nullopt;
  return entry;
}

bool EntryFits(const CacheEntry& entry, const SourceFile* common) {
  if (common != nullptr) return true;
  auto needs_common = [](const SourceRange& range) { return range.file == kCommonFile; };
  for (const Diagnostic& diagnostic : entry.diagnostics) {
    if (needs_common(diagnostic.range)) return false;
    for (const DiagnosticNote& note : diagnostic.notes) {
      if (needs_common(note.range)) return false;
    }
    for (const FixIt& fix : diagnostic.fixes) {
      if (needs_common(fix.range)) return false;
    }
  }
  return true;
}

FileReport RestoreReport(CacheEntry entry, std::string path, std::string text,
                         const SourceFile* common, SourceManager& sources) {
  FileReport report;
  report.file = &sources.Add(std::move(path), std::move(text));
  report.dialect = std::move(entry.dialect);
  report.stage = std::move(entry.stage);
  report.harness = std::move(entry.harness);
  report.target = std::move(entry.target);
  report.channels = std::move(entry.channels);
  std::vector<FileId> ids = {report.file->Id(), common != nullptr ? common->Id() : kNoFile};
  for (CachedText& file : entry.generated) {
    ids.push_back(sources.Add(std::move(file.name), std::move(file.text), true).Id());
  }
  auto restore = [&](SourceRange& range) {
    if (range.Valid()) range.file = ids[range.file];
  };
  for (Diagnostic& diagnostic : entry.diagnostics) {
    restore(diagnostic.range);
    for (DiagnosticNote& note : diagnostic.notes) restore(note.range);
    for (FixIt& fix : diagnostic.fixes) restore(fix.range);
  }
  report.diagnostics = std::move(entry.diagnostics);
  return report;
}

}  // namespace shaderport::driver
