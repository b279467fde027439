// Writes new code into a JSON project in place: only the code strings change, and
// within them the bytes a fix kept are copied with their original JSON spelling
// (escapes such as \/ or \u00e9 stay as they were).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "driver/project/shadertoy_project.h"
#include "source/edit.h"

namespace shaderport::driver::project {

struct CodeReplacement {
  const ProjectPass* pass = nullptr;  // read from `document` (its origin is used)
  std::string_view text;              // the new code
  const SourceMap* map = nullptr;     // text -> pass.code
};

// Replacements must not share a pass.
std::string RewriteCodeStrings(std::string_view document,
                               std::vector<CodeReplacement> replacements);

}  // namespace shaderport::driver::project
