// `shaderport summary`: what the front end makes of each shader, one row a file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace shaderport::driver {

struct SummaryRow {
  std::string path;
  std::string dialect;
  std::string stage;
  std::string problem;  // input error ("" when the file was read)
  size_t bytes = 0;
  size_t tokens = 0;       // lexed, trivia excluded
  size_t nodes = 0;        // syntax tree nodes
  size_t expressions = 0;  // expression nodes
  size_t typed = 0;        // expressions with a known type
  size_t mismatches = 0;   // strict-typing mistakes the semantic model found
  size_t errors = 0;       // front-end errors (lexer, preprocessor, parser)
};

std::vector<SummaryRow> Summarize(const std::vector<std::filesystem::path>& paths, unsigned jobs,
                                  std::vector<std::string>& path_errors);

}  // namespace shaderport::driver
