// Owns every SourceFile of a run, original and synthetic, so that ranges can
// be resolved to names and lines when diagnostics are printed.
#pragma once

#include <deque>
#include <memory>
#include <mutex>
#include <string>

#include "source/source_file.h"

namespace shaderport {

// Thread-safe: files of a parallel run are added from several threads.
class SourceManager {
 public:
  // Files are never moved once added: references stay valid.
  const SourceFile& Add(std::string name, std::string text, bool synthetic = false) {
    const std::lock_guard lock(mutex_);
    files_.emplace_back(static_cast<FileId>(files_.size()), std::move(name), std::move(text),
                        synthetic);
    return files_.back();
  }
  // A file whose text is part of another file (see Embedding).
  const SourceFile& AddEmbedded(std::string name, std::string text,
                                std::shared_ptr<const Embedding> embedding) {
    const std::lock_guard lock(mutex_);
    files_.emplace_back(static_cast<FileId>(files_.size()), std::move(name), std::move(text));
    files_.back().SetEmbedding(std::move(embedding));
    return files_.back();
  }
  const SourceFile& Get(FileId id) const {
    const std::lock_guard lock(mutex_);
    return files_.at(id);
  }
  size_t Size() const {
    const std::lock_guard lock(mutex_);
    return files_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::deque<SourceFile> files_;
};

}  // namespace shaderport
