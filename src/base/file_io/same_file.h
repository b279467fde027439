// Whether an output would replace one of the command's inputs, asked by file
// identity (device and inode), so that "s.frag", "./s.frag", a symlink and a hard
// link to it are all the same file.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <span>

namespace shaderport::file_io {

struct FileIdentity {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileIdentity&) const = default;
};

// The identity of the file `path` names, symlinks followed; nullopt when it does
// not exist (a new output replaces nothing).
std::optional<FileIdentity> IdentityOf(const std::filesystem::path& path);

// The first of `inputs` that `output` is the same file as, or nullopt.
std::optional<std::filesystem::path> InputReplacedBy(const std::filesystem::path& output,
                                                     std::span<const std::filesystem::path> inputs);

}  // namespace shaderport::file_io
