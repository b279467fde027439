// An open document checked as `shaderport check --stdin --stdin-filename PATH` would
// check it, and its findings in LSP terms (positions in the document's own text).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/dialect.h"

namespace shaderport::driver::lsp {

struct DocumentFinding {
  nlohmann::json diagnostic;  // an LSP Diagnostic
  nlohmann::json edits;       // its fix-its as TextEdits in the document (array)
  bool safe = false;          // its fix-its are safe ones: what `shaderport fix` applies
};

struct DocumentCheck {
  std::vector<DocumentFinding> findings;
  // What the verdict is against, for people: "shadertoy fragment shader, harness
  // shadertoy, target webgl2" (the file's decision, as `explain-file` shows it).
  std::string decision;
  // The same, as fields for the `shaderport/status` notification.
  std::string dialect, stage, harness, target;
  std::vector<std::string> channels;    // ShaderToy code: iChannel0..3's sampler types
  Severity fail_on = Severity::kError;  // findings at or above it fail `check`
  bool fails = false;                   // some finding at or above fail_on
  bool rendered = false;                // the picture was rendered and checked too
};

// What a check should do besides check, from the client's settings.
struct DocumentCheckSettings {
  std::optional<model::Target> target;  // the WebGL context (else decided per file)
  std::optional<Severity> fail_on;      // else the file's .shaderport.toml, else error
  bool render = false;                  // smoke-render and check the picture (check --render)
};

// `uri` names the document in related information; `rules_with_sections` (sorted)
// picks each rule's documentation link.
DocumentCheck CheckDocument(const std::filesystem::path& path, std::string_view uri,
                            const std::string& text,
                            const std::vector<std::string>& rules_with_sections,
                            const DocumentCheckSettings& settings = {});

// What `shaderport fix` writes for the document ("" when it changes nothing or
// cannot: the text is not read, or the fixes did not settle).
std::string FixDocument(const std::filesystem::path& path, const std::string& text);

// What `shaderport port` writes for the document: WebGL2 that compiles ("" when the
// port changes nothing, does not compile, or the document is a project).
std::string PortDocument(const std::filesystem::path& path, const std::string& text);

// A URI for a file path: file:// with the path percent-encoded.
std::string UriOfPath(const std::filesystem::path& path);

}  // namespace shaderport::driver::lsp
