// Our own front end on one input: lexer, preprocessor, parser and, on request,
// the semantic model, set up for the file's dialect (ShaderToy code sees the
// site's uniforms and its Common code).
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "driver/dialect.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/parser.h"
#include "source/source_manager.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {

struct FrontEndResult {
  glsl::LexedFile lexed;                // the file alone (comments, suppressions)
  glsl::PreprocessResult preprocessed;  // Common (if any) then the file
  glsl::ParseResult parsed;
  // ShaderToy's generated uniforms, parsed; shared by every file of the run with
  // the same channels (see SourceManager::Memo).
  std::shared_ptr<const glsl::ParseResult> header;
  std::optional<glsl::SemanticModel> model;  // when analysis was asked for
  DiagnosticList diagnostics;                // lexer (of Common too), preprocessor, parser
  // ShaderToy: the line each part (Common, the file) starts on in the site's one text.
  std::vector<std::pair<FileId, int64_t>> first_lines;

  bool HasErrors() const { return shaderport::HasErrors(diagnostics); }
};

struct FrontEndOptions {
  bool analyze = false;
  model::ChannelKinds channels{};
  // Longest identifier; 0 picks the limit from the #version (see PreprocessOptions).
  uint32_t max_identifier_length = 0;
  // A harness other than ShaderToy (FileDecision::harness_header): the code sees its
  // declarations, and is parsed as the version its prelude sets (0: its own).
  std::string_view harness_header;
  int harness_version = 0;
};

// `sources` receives the generated ShaderToy header when the dialect needs it.
FrontEndResult RunFrontEnd(const SourceFile& file, const SourceFile* common,
                           const DetectedKind& kind, SourceManager& sources,
                           const FrontEndOptions& options = {});

// The same with `file` lexed by the caller (glsl::Lex(file)): a file is lexed once
// for detection, the front end, suppressions and glslang's message mapping.
FrontEndResult RunFrontEnd(const SourceFile& file, glsl::LexedFile lexed, const SourceFile* common,
                           const DetectedKind& kind, SourceManager& sources,
                           const FrontEndOptions& options = {});

}  // namespace shaderport::driver
