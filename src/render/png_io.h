// PNG images through libpng: 8-bit RGBA, rows top-down.
#pragma once

#include <string>

#include "render/render_request.h"

namespace shaderport::render {

// The image as PNG bytes (8-bit RGBA, no time chunk: equal images give equal bytes);
// empty when the image is malformed or libpng fails. Files are written by the
// caller (base/file_io/atomic_write.h), never here.
std::string EncodePng(const ImageRgba8& image);
// Any PNG colour type and bit depth is converted to 8-bit RGBA.
bool ReadPng(const std::string& path, ImageRgba8& image, std::string& error);

}  // namespace shaderport::render
