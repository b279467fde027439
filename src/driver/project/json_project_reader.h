// Reads ShaderToy projects from JSON: the site's API export ({"Shader": {"info",
// "renderpass"}}, bare {"info", "renderpass"}, or a list of either) and the corpus
// record format ({"id", "name", "passes": [...]}); a .jsonl file holds one record or
// export per line. Nothing is thrown: problems are reported with their offset.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "driver/project/shadertoy_project.h"

namespace shaderport::driver::project {

struct ProjectProblem {
  uint32_t offset = 0;  // in the document
  std::string message;
};

struct ProjectDocument {
  std::vector<ShaderToyProject> projects;
  std::vector<ProjectProblem> problems;  // each an error of the user's file
};

// One JSON document: an object (export or record) or an array of them.
ProjectDocument ReadShaderToyJson(std::string_view text);

// One document per non-blank line; offsets stay offsets in `text`.
ProjectDocument ReadShaderToyJsonLines(std::string_view text);

}  // namespace shaderport::driver::project
