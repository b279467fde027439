// One file's findings as the result cache stores them: a compact binary entry
// (magic, format version, key, payload, checksum) whose ranges are byte offsets
// into the file itself, its ShaderToy Common file or generated text stored in
// the entry. Decoding trusts nothing: a truncated, altered or foreign entry is
// rejected, never half-read.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driver/cache_key.h"
#include "report/check_report.h"
#include "source/source_manager.h"

namespace shaderport::driver {

// Bumped whenever the layout changes; entries of another version are misses.
inline constexpr uint32_t kCacheEntryVersion =
    4;  // 2: harness and target; 3: fix's repairs; 4: channels

struct CachedText {
  std::string name;
  std::string text;
};

struct CacheEntry {
  std::string dialect;
  std::string stage;
  std::string harness;
  std::string target;
  std::string channels;
  std::vector<CachedText> generated;  // synthetic files the ranges point into, in creation order
  // Range file ids here are kSelfFile, kCommonFile, kFirstGenerated + i or kNoFile.
  DiagnosticList diagnostics;
};

inline constexpr FileId kSelfFile = 0;
inline constexpr FileId kCommonFile = 1;
inline constexpr FileId kFirstGenerated = 2;

// nullopt when some range points into a file the entry cannot rebuild (another
// original file): such a report is simply not cached.
std::optional<std::string> EncodeCacheEntry(const FileReport& report, const SourceFile* common,
                                            const SourceManager& sources, const CacheKey& key);

// nullopt for anything but a complete, intact entry written for `key`.
std::optional<CacheEntry> DecodeCacheEntry(std::string_view bytes, const CacheKey& key);

// False when the entry points into a Common file the job does not have.
bool EntryFits(const CacheEntry& entry, const SourceFile* common);

// Registers the file (and the entry's generated text) in `sources` and returns
// the report CheckFile gave. The entry must fit the job (EntryFits).
FileReport RestoreReport(CacheEntry entry, std::string path, std::string text,
                         const SourceFile* common, SourceManager& sources);

}  // namespace shaderport::driver
