// The GLSL extensions a shader can use: those its WebGL context offers
// (webgl_context_extensions.def) that its page enabled with getExtension. shaderport
// assumes a page enables whatever its context offers, as ShaderToy does, unless told
// which ones (`check --enabled-extensions`).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/target.h"

namespace shaderport::model {

// True when a WebGL context of `target` offers the GLSL extension `name`.
bool ContextOffersExtension(std::string_view name, Target target);
// True when some WebGL context offers it: a name `--enabled-extensions` may list.
bool IsWebglExtension(std::string_view name);

// The extensions a page enabled, by GLSL name (GL_OES_standard_derivatives).
class EnabledExtensions {
 public:
  EnabledExtensions() = default;  // every one its context offers
  static EnabledExtensions Only(std::vector<std::string> names);

  bool EnablesAll() const { return !names_.has_value(); }
  bool Enables(std::string_view name) const;
  // "all", or the names sorted and joined by ',' ("none" when empty).
  std::string Describe() const;

 private:
  std::optional<std::vector<std::string>> names_;  // sorted, unique
};

// "none", or names separated by ',' (spaces around them ignored), each one a WebGL
// context offers; nullopt and `error` set otherwise.
std::optional<EnabledExtensions> ParseEnabledExtensions(std::string_view text, std::string& error);

// The extension is there for the shader: its context offers it and its page enabled it.
bool ExtensionAvailable(std::string_view name, Target target, const EnabledExtensions& enabled);

}  // namespace shaderport::model
