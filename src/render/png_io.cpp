// Uses libpng's simplified API, which reports errors through the png_image struct
// instead of longjmp.
#include "render/png_io.h"

#include <png.h>

#include <cstring>

namespace shaderport::render {

bool WritePng(const std::string& path, const ImageRgba8& image, std::string& error) {
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  png.width = image.width;
  png.height = image.height;
  png.format = PNG_FORMAT_RGBA;
  if (image.pixels.size() != size_t{image.width} * image.height * 4) {
    error = "image buffer has the wrong size";
    return false;
  }
  if (!png_image_write_to_file(&png, path.c_str(), 0, image.pixels.data(), 0, nullptr)) {
    error = "cannot write " + path + ": " + png.message;
    return false;
  }
  return true;
}

bool ReadPng(const std::string& path, ImageRgba8& image, std::string& error) {
  png_image png;
  std::memset(&png, 0, sizeof(png));
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
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

}  // namespace shaderport::render
