#include "driver/file_decision.h"

#include <string_view>

#include "driver/front_end.h"
#include "model/shipped_dialects.h"
#include "rule/harness_dialect_detect.h"
#include "rules/shadertoy/harness_support.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

// As explain-file has always named passes: the cube map pass by its entry point's word.
std::string_view PassName(model::PassKind pass) {
  return pass == model::PassKind::kCube ? "cubemap" : model::PassKindName(pass);
}

bool HasVersionDirective(const glsl::LexedFile& lexed) {
  const auto& tokens = lexed.tokens;
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    if (tokens[i].kind == glsl::TokenKind::kHash && tokens[i + 1].text == "version" &&
        !tokens[i + 1].at_line_start) {
      return true;
    }
  }
  return false;
}

// By the code's own #version, whatever the dialect says about how it is written.
model::Target TargetOfCode(const glsl::LexedFile& lexed, const std::filesystem::path& path) {
  return DetectKind(lexed, path).dialect == Dialect::kWebGL1 ? model::Target::kWebGL1
                                                             : model::Target::kWebGL2;
}

void DecideTarget(FileDecision& decision, const glsl::LexedFile& lexed,
                  const std::filesystem::path& path, const DecisionGiven& given) {
  std::string because;
  if (given.target) {
    decision.target = *given.target;
    because = "given by " + given.target_from;
  } else if (decision.IsShaderToy()) {
    decision.target = model::Target::kWebGL2;
    because = "shadertoy.com compiles every pass in a WebGL2 context";
  } else if (decision.harness_version != 0) {
    decision.target =
        decision.harness_version == 300 ? model::Target::kWebGL2 : model::Target::kWebGL1;
    because = "the " + decision.harness->name + " harness compiles it as GLSL ES " +
              (decision.harness_version == 300 ? "3.00" : "1.00");
  } else {
    decision.target = TargetOfCode(lexed, path);
    because = decision.target == model::Target::kWebGL2 ? "the code's #version 300 es"
                                                        : "GLSL ES 1.00 code runs in WebGL1";
  }
  std::erase_if(decision.reasons, [](const DecisionReason& r) { return r.part == "target"; });
  decision.reasons.push_back({"target", std::string(TargetName(decision.target)), because});
}

// What a harness other than ShaderToy puts before this code: its prelude (without
// its #version when the code has one), defines and the variables the code uses.
std::string HarnessHeader(const model::HarnessDialect& harness, const rule::CodeInterface& code,
                          bool code_has_version, int version) {
  std::string header;
  if (!harness.prelude.empty()) {
    size_t start = 0;
    while (start < harness.prelude.size()) {
      size_t end = harness.prelude.find('\n', start);
      if (end == std::string::npos) end = harness.prelude.size();
      const std::string_view line = std::string_view(harness.prelude).substr(start, end - start);
      const bool is_version = line.find("#version") != std::string_view::npos;
      if (!line.empty() && !(is_version && code_has_version)) {
        header.append(line);
        header += '\n';
      }
      start = end + 1;
    }
  }
  for (const std::string& define : harness.defines) header += "#define " + define + "\n";
  for (const model::ProvidedVariable& provided : harness.provides) {
    const bool used = code.free_identifiers.contains(provided.name) &&
                      !code.globals.contains(provided.name) &&
                      !code.functions.contains(provided.name);
    if (harness.declare != model::DeclareMode::kAll && !used) continue;
    std::string declaration = model::DeclarationOf(provided);
    if (version < 300) {
      // GLSL ES 1.00 has no file-scope in/out: an input is a varying, an output is gl_FragColor.
      if (provided.storage == model::ProvidedStorage::kOutput) continue;
      if (provided.storage == model::ProvidedStorage::kInput)
        declaration = "varying" + declaration.substr(2);
    }
    header += declaration + "\n";
  }
  return header;
}

}  // namespace

FileDecision DecideFromTokens(const glsl::LexedFile& lexed, const std::filesystem::path& path,
                              const DecisionGiven& given) {
  FileDecision decision;
  decision.kind = DetectKind(lexed, path);
  std::string dialect_because(decision.kind.dialect_because);
  std::string stage_because(decision.kind.stage_because);
  if (given.dialect) {
    decision.kind.dialect = *given.dialect;
    dialect_because = "given by " + given.dialect_from;
  }
  if (given.stage) {
    decision.kind.stage = *given.stage;
    stage_because = "given by " + given.stage_from;
  }
  if (given.pass) {
    decision.kind.dialect = Dialect::kShaderToy;
    decision.kind.stage = model::Stage::kFragment;
    decision.kind.pass = *given.pass;
    dialect_because = stage_because = "a tab of a ShaderToy project";
  }
  decision.reasons.push_back(
      {"dialect", std::string(DialectName(decision.kind.dialect)), dialect_because});
  if (decision.IsShaderToy()) {
    decision.reasons.push_back({"pass", std::string(PassName(decision.kind.pass)),
                                given.pass ? "a tab of a ShaderToy project" : dialect_because});
  }
  decision.reasons.push_back({"stage", std::string(StageName(decision.kind.stage)), stage_because});
  if (given.harness != nullptr && !decision.IsShaderToy()) {
    decision.harness = given.harness;
    decision.harness_version = HasVersionDirective(lexed) ? 0 : given.harness->PreludeVersion();
    decision.reasons.push_back({"harness", given.harness->name, "given by " + given.dialect_from});
  } else if (decision.IsShaderToy()) {
    decision.harness = model::FindBuiltinDialect("shadertoy");
    decision.reasons.push_back({"harness", "shadertoy", "ShaderToy code"});
  }
  for (size_t i = 0; i < decision.channels.size(); ++i) {
    if (given.channels[i]) decision.channels[i] = *given.channels[i];
  }
  DecideTarget(decision, lexed, path, given);
  return decision;
}

bool DecideFromTree(FileDecision& decision, const glsl::LexedFile& lexed,
                    const glsl::SyntaxTree& tree, const glsl::SemanticModel& model,
                    const DecisionGiven& given) {
  bool again = false;
  const bool has_version = HasVersionDirective(lexed);
  // A harness completes code that uses its names; a forced dialect, or a #version
  // line (the hosts put theirs first), says the code stands alone.
  const bool detect = decision.harness == nullptr && !given.dialect && !has_version;
  const rule::CodeInterface code = detect || decision.harness != nullptr
                                       ? rule::ReadCodeInterface(tree, model)
                                       : rule::CodeInterface{};
  if (detect) {
    if (auto match = rule::DetectDialect(model::BuiltinDialects(), code)) {
      if (!match->dialect->NameMatches("shadertoy")) {
        decision.harness = match->dialect;
        decision.harness_version = match->dialect->PreludeVersion();
        std::string because;
        for (const std::string& evidence : match->evidence) {
          because += (because.empty() ? "" : ", ") + evidence;
        }
        decision.reasons.push_back({"harness", match->dialect->name, because});
      }
    }
  }
  if (decision.harness != nullptr && !decision.IsShaderToy()) {
    const int version = decision.harness_version != 0 ? decision.harness_version
                        : DetectKind(lexed, "").dialect == Dialect::kWebGL1 ? 100
                                                                            : 300;
    decision.harness_header = HarnessHeader(*decision.harness, code, has_version, version);
    again = !decision.harness_header.empty();
    DecideTarget(decision, lexed, "", given);
  }
  if (decision.harness != nullptr) {
    const auto names = rules::harness::ChannelNames(*decision.harness);
    const auto uses = rules::harness::ReadChannelUses(tree, model, names);
    for (size_t i = 0; i < decision.channels.size(); ++i) {
      const std::string& name = names[i];
      if (name.empty()) continue;
      if (given.channels[i]) {
        if (uses[i].first_2d != glsl::kNoNode || uses[i].first_cube != glsl::kNoNode) {
          decision.reasons.push_back({name,
                                      std::string(model::ChannelKindName(decision.channels[i])),
                                      "given by " + given.channels_from});
        }
        continue;
      }
      if (uses[i].OnlyCube()) {
        decision.channels[i] = model::ChannelKind::kCube;
        decision.reasons.push_back({name, "cube", "sampled only with 3-component coordinates"});
        again = true;
      } else if (uses[i].first_2d != glsl::kNoNode) {
        decision.reasons.push_back({name, "2d", "sampled with 2-component coordinates"});
      }
    }
  }
  return again;
}

validate::ValidationRequest ComposeForGlslang(const FileDecision& decision, const SourceFile& file,
                                              const SourceFile* common, SourceManager& sources) {
  if (!decision.IsShaderToy()) {
    validate::ValidationRequest request;
    if (!decision.harness_header.empty()) {
      // The harness's own lines come first, as its page compiles the code.
      const std::string name = decision.harness->name + "-header";
      const SourceFile& header = sources.Add("<" + name + ">", decision.harness_header, true);
      request.parts.push_back({name, header.Text(), header.Id(), validate::PartKind::kGenerated});
    }
    request.parts.push_back({file.Name(), file.Text(), file.Id(), validate::PartKind::kUser});
    request.stage = decision.kind.stage;
    request.default_version = 100;  // no #version means GLSL ES 1.00, as in WebGL
    return request;
  }
  const bool is_common = decision.kind.pass == model::PassKind::kCommon;
  validate::ValidationRequest request = validate::ComposeShaderToyRequest(
      sources, decision.kind.pass, decision.channels, is_common ? nullptr : common, file);
  // Common code has no entry point of its own: the site only compiles it inside
  // a pass, so here it is compiled but not linked.
  if (is_common) request.link = false;
  return request;
}

FileDecision DecideFile(const SourceFile& file, const SourceFile* common,
                        const DecisionGiven& given, SourceManager& sources) {
  glsl::LexedFile lexed = glsl::Lex(file);
  FileDecision decision = DecideFromTokens(lexed, file.Name(), given);
  FrontEndOptions options;
  options.analyze = true;
  options.channels = decision.channels;
  const FrontEndResult front =
      RunFrontEnd(file, std::move(lexed), decision.IsShaderToy() ? common : nullptr, decision.kind,
                  sources, options);
  if (front.model) DecideFromTree(decision, front.lexed, front.parsed.tree, *front.model, given);
  return decision;
}

}  // namespace shaderport::driver
