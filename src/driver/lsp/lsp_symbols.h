// The outline of a document and the declaration a name refers to, from shaderport's
// front end over the document alone (ShaderToy code read as GLSL ES 3.00, as the site
// compiles it; the site's own uniforms have no declaration to go to).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace shaderport::driver::lsp {

// DocumentSymbol[]: functions (definitions), global variables and constants, structs.
nlohmann::json DocumentSymbols(const std::filesystem::path& path, const std::string& text);

// The range of the declaration of the name at byte `offset` of `text` (a variable,
// parameter, function or struct of the document); nothing for a built-in or no name.
std::optional<nlohmann::json> DefinitionRange(const std::filesystem::path& path,
                                              const std::string& text, uint32_t offset);

// The ranges of every use of the name at byte `offset` and of its declaration
// (when `with_declaration`), within the document; empty for no name or a built-in.
nlohmann::json ReferenceRanges(const std::filesystem::path& path, const std::string& text,
                               uint32_t offset, bool with_declaration);

// Hover text (Markdown) for the name at byte `offset`: the declared type of a
// variable, parameter or function of the document, a built-in function's overloads
// in the document's GLSL ES version, or what a harness (ShaderToy) provides; nothing
// elsewhere.
std::optional<std::string> HoverText(const std::filesystem::path& path, const std::string& text,
                                     uint32_t offset);

// CompletionItem[] for the document: its own functions, structs and variables (each
// name once), the built-in functions and variables of its GLSL ES version and stage,
// and what shadertoy.com provides when the document is a ShaderToy pass. The client
// filters by what is typed.
nlohmann::json CompletionItems(const std::filesystem::path& path, const std::string& text);

}  // namespace shaderport::driver::lsp
