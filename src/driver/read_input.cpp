#include "driver/read_input.h"

#include <fstream>
#include <system_error>

#include "base/limits.h"

namespace shaderport::driver {
namespace {

InputText Reject(std::string rule_id, std::string message) {
  return {std::nullopt, std::move(rule_id), std::move(message)};
}

// Share of control bytes (other than whitespace) in the first few KiB: text has
// almost none, binary data many.
bool LooksBinary(std::string_view text) {
  if (text.find('\0') != std::string_view::npos) return true;
  const std::string_view head = text.substr(0, 4096);
  size_t control = 0;
  for (const char c : head) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 && byte != '\n' && byte != '\r' && byte != '\t' && byte != '\f' &&
        byte != '\v') {
      ++control;
    }
  }
  return control * 10 > head.size();
}

}  // namespace

InputText ClassifyInputText(std::string text) {
  if (text.size() > limits::kMaxFileBytes) {
    return Reject(
        "input/too-large",
        "file is larger than the " + std::to_string(limits::kMaxFileBytes >> 20) + " MiB limit");
  }
  if (text.empty()) return Reject("input/empty", "file is empty");
  if (LooksBinary(text)) {
    return Reject("input/binary", "file looks like binary data, not shader source");
  }
  return {std::move(text), "", ""};
}

InputText ReadInputFile(const std::filesystem::path& path) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (error) return Reject("input/unreadable", "cannot read file: " + error.message());
  if (size > limits::kMaxFileBytes) {
    return Reject("input/too-large",
                  "file is " + std::to_string(size >> 20) + " MiB, larger than the " +
                      std::to_string(limits::kMaxFileBytes >> 20) + " MiB limit");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return Reject("input/unreadable", "cannot open file");
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (static_cast<size_t>(in.gcount()) != size) {
    return Reject("input/unreadable", "file changed size while being read");
  }
  return ClassifyInputText(std::move(text));
}

InputText ReadInputStream(std::istream& in) {
  std::string text;
  char buffer[65536];
  while (text.size() <= limits::kMaxFileBytes && in.read(buffer, sizeof buffer).gcount() > 0) {
    text.append(buffer, static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) return Reject("input/unreadable", "cannot read standard input");
  if (text.size() > limits::kMaxFileBytes) {
    return Reject("input/too-large", "standard input is larger than the " +
                                         std::to_string(limits::kMaxFileBytes >> 20) +
                                         " MiB limit");
  }
  return ClassifyInputText(std::move(text));
}

}  // namespace shaderport::driver
