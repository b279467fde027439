#include "model/webgl_extensions.h"

#include <algorithm>
#include <array>

namespace shaderport::model {
namespace {

struct Offered {
  std::string_view name;
  bool webgl1;
  bool webgl2;
};

constexpr std::array kOffered = {
#define WEBGL_EXTENSION(name, in_webgl1, in_webgl2) Offered{#name, in_webgl1, in_webgl2},
#include "model/webgl_context_extensions.def"
#undef WEBGL_EXTENSION
};

const Offered* Find(std::string_view name) {
  for (const Offered& offered : kOffered) {
    if (offered.name == name) return &offered;
  }
  return nullptr;
}

}  // namespace

bool ContextOffersExtension(std::string_view name, Target target) {
  const Offered* offered = Find(name);
  if (offered == nullptr) return false;
  return target == Target::kWebGL2 ? offered->webgl2 : offered->webgl1;
}

bool IsWebglExtension(std::string_view name) { return Find(name) != nullptr; }

EnabledExtensions EnabledExtensions::Only(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  EnabledExtensions enabled;
  enabled.names_ = std::move(names);
  return enabled;
}

bool EnabledExtensions::Enables(std::string_view name) const {
  return !names_ || std::binary_search(names_->begin(), names_->end(), name);
}

std::string EnabledExtensions::Describe() const {
  if (!names_) return "all";
  if (names_->empty()) return "none";
  std::string joined;
  for (const std::string& name : *names_) {
    if (!joined.empty()) joined += ',';
    joined += name;
  }
  return joined;
}

std::optional<EnabledExtensions> ParseEnabledExtensions(std::string_view text, std::string& error) {
  const auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  if (trim(text) == "none") return EnabledExtensions::Only({});
  std::vector<std::string> names;
  while (true) {
    const size_t comma = text.find(',');
    const std::string_view name = trim(text.substr(0, comma));
    if (!IsWebglExtension(name)) {
      std::string known;
      for (const Offered& offered : kOffered)
        known += std::string(known.empty() ? "" : ", ") + std::string(offered.name);
      // A name is echoed up to 80 bytes: the value may be anything a script passed.
      const std::string shown =
          name.size() > 80 ? std::string(name.substr(0, 80)) + "..." : std::string(name);
      error = "unknown extension '" + shown +
              "' in --enabled-extensions (expected 'none' or GLSL names a WebGL context "
              "offers: " +
              known + ")";
      return std::nullopt;
    }
    names.emplace_back(name);
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return EnabledExtensions::Only(std::move(names));
}

bool ExtensionAvailable(std::string_view name, Target target, const EnabledExtensions& enabled) {
  return ContextOffersExtension(name, target) && enabled.Enables(name);
}

}  // namespace shaderport::model
