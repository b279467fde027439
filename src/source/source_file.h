// A file of shader text and the byte ranges that point into it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport {

// Identifies a SourceFile within one run (index into a SourceManager).
using FileId = uint32_t;
inline constexpr FileId kNoFile = UINT32_MAX;

// A half-open byte range [begin, end) in one file.
struct SourceRange {
  FileId file = kNoFile;
  uint32_t begin = 0;
  uint32_t end = 0;

  bool Valid() const { return file != kNoFile; }
  uint32_t Size() const { return end - begin; }
  bool Contains(const SourceRange& other) const {
    return file == other.file && begin <= other.begin && other.end <= end;
  }
  friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

// 1-based line and column; the column counts bytes, as clang and glslang do.
struct LineColumn {
  uint32_t line = 1;
  uint32_t column = 1;
  friend bool operator==(const LineColumn&, const LineColumn&) = default;
};

class SourceFile;

// Where a file's text sits inside another file: a pass of a ShaderToy JSON project
// is a string in the JSON document, and CI formats point at the document's bytes.
struct Embedding {
  std::shared_ptr<const SourceFile> container;  // the document (its own name and text)
  std::string logical_name;                     // e.g. "Buffer A"
  // Container offset of each byte of the text; one more entry for the end.
  std::vector<uint32_t> offsets;

  uint32_t ContainerOffset(uint32_t offset) const {
    if (offsets.empty()) return offset;
    return offsets[offset < offsets.size() ? offset : offsets.size() - 1];
  }
};

// Owns the text of one file (original or synthetic) and answers line questions
// about it. Line and column are computed on demand from byte offsets.
class SourceFile {
 public:
  SourceFile(FileId id, std::string name, std::string text, bool synthetic = false);

  FileId Id() const { return id_; }
  const std::string& Name() const { return name_; }
  std::string_view Text() const { return text_; }
  bool IsSynthetic() const { return synthetic_; }
  // Set when the text is part of another file (nullptr otherwise).
  const Embedding* Embedded() const { return embedding_.get(); }
  void SetEmbedding(std::shared_ptr<const Embedding> embedding) {
    embedding_ = std::move(embedding);
  }

  uint32_t LineCount() const { return static_cast<uint32_t>(line_starts_.size()); }
  LineColumn LocationOf(uint32_t offset) const;
  // Byte offset of the first byte of a 1-based line (clamped to the file).
  uint32_t LineStart(uint32_t line) const;
  // The text of a 1-based line without its line terminator.
  std::string_view LineText(uint32_t line) const;
  // Byte offset of (line, column), clamped to the line.
  uint32_t OffsetOf(LineColumn location) const;
  SourceRange WholeRange() const { return {id_, 0, static_cast<uint32_t>(text_.size())}; }
  // Frees the text and line table (the name stays): for a file nothing will read
  // again, so that a run over thousands of files does not hold them all.
  void ReleaseText() {
    std::string().swap(text_);
    std::vector<uint32_t>{0}.swap(line_starts_);
  }

 private:
  FileId id_;
  std::string name_;
  std::string text_;
  bool synthetic_;
  std::vector<uint32_t> line_starts_;
  std::shared_ptr<const Embedding> embedding_;
};

}  // namespace shaderport
