#include "driver/tree_depth.h"

#include <algorithm>
#include <string>

#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"
#include "source/source_file.h"

namespace shaderport::driver {

uint32_t SyntaxTreeDepth(std::string_view text, int version) {
  const SourceFile file(0, "<depth>", std::string(text));
  const SourceFile* files[] = {&file};
  const glsl::PreprocessResult preprocessed = glsl::Preprocess(files);
  glsl::ParseOptions options;
  options.version = version;
  const glsl::ParseResult parsed = glsl::Parse(preprocessed, options);
  uint32_t deepest = 0;
  glsl::VisitPreorder(parsed.tree, [&](const glsl::Node&, uint32_t depth) {
    deepest = std::max(deepest, depth);
    return true;
  });
  return deepest;
}

}  // namespace shaderport::driver
