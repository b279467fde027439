// Helpers for preprocessor tests.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glsl/lex/preprocessor.h"
#include "source/source_manager.h"

namespace shaderport::glsl::testing {

struct PpRun {
  std::unique_ptr<SourceManager> sources = std::make_unique<SourceManager>();
  PreprocessResult result;
};

// Preprocesses `texts` as files "f0.glsl", "f1.glsl", ... of one translation unit.
inline PpRun RunPp(const std::vector<std::string>& texts, std::vector<std::string> predefined = {},
                   uint32_t max_identifier_length = 0, std::vector<int64_t> first_lines = {}) {
  PpRun run;
  std::vector<const SourceFile*> files;
  for (size_t i = 0; i < texts.size(); ++i) {
    files.push_back(&run.sources->Add("f" + std::to_string(i) + ".glsl", texts[i]));
  }
  PreprocessOptions options;
  options.predefined = std::move(predefined);
  options.max_identifier_length = max_identifier_length;
  options.first_lines = std::move(first_lines);
  run.result = Preprocess(files, options);
  return run;
}

inline PpRun RunPp(const std::string& text, std::vector<std::string> predefined = {}) {
  return RunPp(std::vector<std::string>{text}, std::move(predefined));
}

// The output tokens' text joined by single spaces (without the end of file).
inline std::string Joined(const PreprocessResult& r) {
  std::string out;
  for (const PpToken& t : r.tokens) {
    if (t.kind == TokenKind::kEndOfFile) break;
    if (!out.empty()) out += ' ';
    out += t.text;
  }
  return out;
}

inline std::vector<std::string> RuleIds(const PreprocessResult& r) {
  std::vector<std::string> out;
  for (const auto& d : r.diagnostics) out.push_back(d.rule_id);
  return out;
}

inline size_t ErrorCount(const PreprocessResult& r) {
  size_t n = 0;
  for (const auto& d : r.diagnostics) n += d.severity == Severity::kError;
  return n;
}

}  // namespace shaderport::glsl::testing
