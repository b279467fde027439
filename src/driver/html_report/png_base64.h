// Pictures for the HTML report: PNG bytes in memory and `data:` URIs, so that the
// report is one file with no external resources.
#pragma once

#include <string>
#include <string_view>

namespace shaderport::driver {

// Standard base64 (RFC 4648, with padding).
std::string Base64Encode(std::string_view bytes);

// "data:image/png;base64,..." for `png` bytes.
std::string PngDataUri(std::string_view png);

}  // namespace shaderport::driver
