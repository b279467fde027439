// PNG files through libpng: 8-bit RGBA, rows top-down.
#pragma once

#include <string>

#include "render/render_request.h"

namespace shaderport::render {

// False with `error` set when the file cannot be written.
bool WritePng(const std::string& path, const ImageRgba8& image, std::string& error);
// Any PNG colour type and bit depth is converted to 8-bit RGBA.
bool ReadPng(const std::string& path, ImageRgba8& image, std::string& error);

}  // namespace shaderport::render
