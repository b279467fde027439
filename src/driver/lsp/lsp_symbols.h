// Navigation over a document's code (ProjectCode): its outline, where a name is
// declared, every use of it (a Common name across the project's passes), hover and
// completion. ShaderToy code is read as GLSL ES 3.00, as the site compiles it; the
// site's own uniforms have no declaration to go to.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/lsp/lsp_project.h"

namespace shaderport::driver::lsp {

// DocumentSymbol[]: functions (definitions), global variables and constants, structs;
// a JSON project's passes each hold their own.
nlohmann::json DocumentSymbols(const ProjectCode& code);

// The Location of the declaration of the name at byte `offset` of the document (in
// the document, or in the Common its pass sees); nothing for a built-in or no name.
std::optional<nlohmann::json> DefinitionLocation(const ProjectCode& code, uint32_t offset);

// The Locations of every use of the name at byte `offset` and of its declaration
// (when `with_declaration`): a global of Common is also found in every pass that
// sees it. Empty for no name or a built-in.
nlohmann::json ReferenceLocations(const ProjectCode& code, uint32_t offset, bool with_declaration);

// Hover text (Markdown) for byte `offset`: the declared type of a variable, parameter
// or function (of the document or its Common), a built-in function's overloads in the
// code's GLSL ES version, what a harness (ShaderToy) provides and what the site feeds
// it, or else the type of
// the innermost expression there; nothing elsewhere. A ShaderToy channel is shown
// with the sampler type of `channel_kinds` (iChannel0..3 as last checked: "2d").
std::optional<std::string> HoverText(const ProjectCode& code, uint32_t offset,
                                     const std::vector<std::string>& channel_kinds = {});

// CompletionItem[] at byte `offset`: the names in scope there (locals and parameters
// declared before it, globals, Common's globals for a pass), the built-in functions
// and variables of the code's GLSL ES version and stage, and what shadertoy.com
// provides for a ShaderToy pass. The client filters by what is typed.
nlohmann::json CompletionItems(const ProjectCode& code, uint32_t offset);

}  // namespace shaderport::driver::lsp
