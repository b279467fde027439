// Owns every SourceFile of a run, original and synthetic, so that ranges can
// be resolved to names and lines when diagnostics are printed.
#pragma once

#include <deque>
#include <functional>
#include <map>
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

  // SourceFile::ReleaseText of file `id`. The caller must be the only reader of that file.
  void ReleaseText(FileId id) {
    const std::lock_guard lock(mutex_);
    files_.at(id).ReleaseText();
  }

  // Immutable data derived from files of this manager, made once per key and then
  // shared for the manager's life (the parsed ShaderToy header is the same for every
  // pass with the same channels). `make` runs under a lock of its own and may Add().
  std::shared_ptr<const void> Memo(const std::string& key,
                                   const std::function<std::shared_ptr<const void>()>& make) {
    const std::lock_guard lock(memo_mutex_);
    std::shared_ptr<const void>& slot = memo_[key];
    if (!slot) slot = make();
    return slot;
  }

 private:
  mutable std::mutex mutex_;
  std::deque<SourceFile> files_;
  std::mutex memo_mutex_;
  std::map<std::string, std::shared_ptr<const void>> memo_;
};

}  // namespace shaderport
