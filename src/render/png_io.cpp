// Uses libpng's simplified API, which reports errors through the png_image struct
// instead of longjmp.
#include "render/png_io.h"

#include <fcntl.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "base/file_io/read_regular_file.h"
#include "base/limits.h"

namespace shaderport::render {

std::string EncodePng(const ImageRgba8& image) {
  if (image.width == 0 || image.height == 0 || image.width > kMaxRenderSide ||
      image.height > kMaxRenderSide ||
      image.pixels.size() != size_t{image.width} * image.height * 4) {
    return "";
  }
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width;
  png.height = image.height;
  png.format = PNG_FORMAT_RGBA;
  // First call sizes the buffer, second fills it.
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.pixels.data(), 0, nullptr)) {
    return "";
  }
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.pixels.data(), 0, nullptr)) {
    return "";
  }
  bytes.resize(size);
  return bytes;
}

namespace {

// The file opened for reading, or null with `error` set: only a regular file, and
// opened without blocking, so a FIFO named as a channel cannot hang the run.
FILE* OpenRegularFile(const std::string& path, std::string& error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    error = "cannot read " + path + ": " + std::strerror(errno);
    return nullptr;
  }
  struct stat info {};
  FILE* file = nullptr;
  const bool regular = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode);
  const bool small = static_cast<uintmax_t>(info.st_size) <= limits::kMaxImageBytes;
  if (regular && small) file = ::fdopen(fd, "rb");
  if (file == nullptr) {
    error = "cannot read " + path + ": " +
            (!regular ? std::string("not a regular file")
                      : "larger than the " + file_io::SizeLimitText(limits::kMaxImageBytes) +
                            " limit for an image");
    ::close(fd);
  }
  return file;
}

// The PNG in `file` (left open) into `image`.
bool ReadPngFrom(FILE* file, const std::string& path, png_image& png, ImageRgba8& image,
                 std::string& error) {
  if (!png_image_begin_read_from_stdio(&png, file)) {
    error = "cannot read " + path + ": " + png.message;
    return false;
  }
  if (png.width == 0 || png.height == 0 || png.width > kMaxRenderSide ||
      png.height > kMaxRenderSide) {
    png_image_free(&png);
    error = path + ": image size must be 1..4096 per side";
    return false;
  }
  png.format = PNG_FORMAT_RGBA;
  image.width = png.width;
  image.height = png.height;
  image.pixels.assign(PNG_IMAGE_SIZE(png), 0);
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    error = "cannot decode " + path + ": " + png.message;
    png_image_free(&png);
    return false;
  }
  return true;
}

}  // namespace

bool ReadPng(const std::string& path, ImageRgba8& image, std::string& error) {
  FILE* file = OpenRegularFile(path, error);
  if (file == nullptr) return false;
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  const bool read = ReadPngFrom(file, path, png, image, error);
  std::fclose(file);
  return read;
}

}  // namespace shaderport::render
