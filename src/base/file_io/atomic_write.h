// Replacing a file's text so that a crash at any moment leaves either the old
// or the new text, never a mixture or nothing.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <string_view>

namespace shaderport::file_io {

struct AtomicWriteOptions {
  // Stage the new text in an anonymous O_TMPFILE inode, which a killed process
  // cannot leave behind. false forces the named temporary that is otherwise
  // used only where the file system has no O_TMPFILE (tests of that path).
  bool anonymous_temporary = true;
  // fsync the new text and the directory before returning. Only a file whose
  // reader detects a torn copy (the result cache checksums each entry, a torn one
  // is a miss) may skip it: it costs a disk flush per file.
  bool sync_to_disk = true;
  // The user named the target (-o, --html, an input of fix -i): its symlinks are
  // followed and a device or FIFO (/dev/null) is written as a stream. false for
  // files shaderport names itself (result cache entries), where a symlink, device or
  // FIFO was planted by someone else: it is refused, never written through.
  bool user_named_target = true;
};

// A named temporary older than this is removed by the next write in its directory.
inline constexpr std::chrono::minutes kStaleTemporaryAge{10};

// Writes `text` to the file `path` names, following symlinks (the link stays a
// link): the new text goes to a temporary in the file's directory, is fsynced,
// renamed over the file, and the directory is fsynced. The mode, and the owner
// where permitted, of the file it replaces are kept. An existing target that is
// read-only is refused, also for root (its mode has no write bit), as is one the
// caller may not write. A character device or FIFO (/dev/null, /dev/stdout) is a
// stream, not a file to keep: it is written directly (a FIFO without a reader is
// an error, not a hang). On any failure the old file is untouched, no
// temporary is left, and the reason is returned; "" on success. Blocks
// SIGXFSZ while writing, so a file-size limit gives an error, not a dead process.
std::string WriteFileAtomically(const std::filesystem::path& path, std::string_view text,
                                const AtomicWriteOptions& options = {});

// True for the names of the temporaries WriteFileAtomically makes:
// ".NAME.shaderport-PID-XXXXXX.tmp" (X: a letter or digit).
bool IsAtomicWriteTemporary(std::string_view file_name);

}  // namespace shaderport::file_io
