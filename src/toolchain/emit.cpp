#include "toolchain/emit.h"

#include <array>
#include <utility>

#include "base/large_stack.h"
#include "base/limits.h"
#include "toolchain/cross_compile.h"
#include "toolchain/inlined_size.h"
#include "toolchain/reflect.h"
#include "toolchain/spirv_compile.h"
#include "toolchain/spirv_tools.h"

namespace shaderport::toolchain {
namespace {

constexpr std::array<std::pair<EmitKind, const char*>, 7> kNames = {{
    {EmitKind::kEssl, "essl"},
    {EmitKind::kSpirv, "spirv"},
    {EmitKind::kSpvasm, "spvasm"},
    {EmitKind::kHlsl, "hlsl"},
    {EmitKind::kMsl, "msl"},
    {EmitKind::kEsslRoundtrip, "essl-roundtrip"},
    {EmitKind::kReflect, "reflect"},
}};

void Report(EmitResult& result, const SourceFile& file, const char* rule_id, std::string message) {
  result.diagnostics.push_back(
      {Severity::kError, rule_id, {file.Id(), 0, 0}, std::move(message), {}, {}});
}

// Option errors are the user's, reported before any work is done.
bool CheckOptions(const SourceFile& file, const EmitOptions& options, EmitResult& result) {
  if (options.optimize && !OptimizeLevelFromName(*options.optimize)) {
    Report(result, file, "spirv/unknown-optimization",
           "unknown optimisation level '" + *options.optimize + "': use O or Os");
  }
  if (options.kind == EmitKind::kHlsl &&
      (options.hlsl_shader_model < 30 || options.hlsl_shader_model > 67)) {
    Report(result, file, "spirv/unsupported-option",
           "HLSL shader model " + std::to_string(options.hlsl_shader_model) + " is outside 30..67");
  }
  if (options.kind == EmitKind::kMsl &&
      (options.msl_version < 10000 || options.msl_version > 30000)) {
    Report(result, file, "spirv/unsupported-option",
           "MSL version " + std::to_string(options.msl_version) + " is outside 10000..30000");
  }
  return !HasErrors(result.diagnostics);
}

std::string AsBytes(const SpirvWords& words) {
  std::string bytes;
  bytes.reserve(words.size() * 4);
  for (const uint32_t word : words) {  // SPIR-V files are little endian, whatever the host
    for (int shift = 0; shift < 32; shift += 8) bytes += static_cast<char>((word >> shift) & 0xff);
  }
  return bytes;
}

// The largest entry point, counted with every call inlined, SPIRV-Cross is given for
// `kind` (UINT64_MAX: SPIRV-Cross is not used). Its reflection walks are far slower per
// visit than its code generation (100,000 instructions: 52 s against 0.1 s).
uint64_t CrossCompileLimit(EmitKind kind) {
  if (kind == EmitKind::kReflect) return limits::kMaxInlinedInstructions;
  if (kind == EmitKind::kHlsl || kind == EmitKind::kMsl || kind == EmitKind::kEsslRoundtrip) {
    return limits::kMaxCrossCompiledInstructions;
  }
  return UINT64_MAX;
}

void EmitFromModule(const SourceFile& file, const EmitOptions& options, model::Stage stage,
                    const SpirvWords& module, const SpirvWords& unoptimized, EmitResult& result) {
  CrossOptions cross;
  cross.hlsl_shader_model = options.hlsl_shader_model;
  cross.msl_version = options.msl_version;
  CrossOutcome crossed;
  switch (options.kind) {
    case EmitKind::kEssl:
      break;
    case EmitKind::kSpirv:
      result.output = AsBytes(module);
      result.binary = true;
      return;
    case EmitKind::kSpvasm:
      result.output = DisassembleSpirv(module);
      if (result.output.empty()) Report(result, file, "internal/error", "spirv-dis failed");
      return;
    case EmitKind::kReflect: {
      // Reflection describes the shader as written: optimisation would drop unused names.
      const ReflectOutcome reflected = Reflect(unoptimized, stage, options.shadertoy);
      result.output = reflected.json;
      if (!reflected.error.empty()) {
        Report(result, file, "spirv/cross-compile-failed", "SPIRV-Cross: " + reflected.error);
      }
      return;
    }
    case EmitKind::kHlsl:
      crossed = CrossCompile(module, CrossTarget::kHlsl, cross);
      break;
    case EmitKind::kMsl:
      crossed = CrossCompile(module, CrossTarget::kMsl, cross);
      break;
    case EmitKind::kEsslRoundtrip:
      crossed = CrossCompile(module, CrossTarget::kEssl300, cross);
      break;
  }
  result.output = crossed.text;
  if (!crossed.error.empty()) {
    Report(result, file, "spirv/cross-compile-failed", "SPIRV-Cross: " + crossed.error);
  }
}

// spirv-opt's -O and -Os passes inline every call first, and SPIRV-Cross walks a callee's
// body again at every call: functions that each call the next twice grow exponentially
// (1.2 KB of GLSL kept both busy for minutes). The size with every call inlined is
// counted from the call graph. Past spirv-opt's limit the module is not optimised (a
// warning, `optimise` becomes false); past SPIRV-Cross's there is no output (an error,
// false is returned).
bool WithinInliningLimits(const SourceFile& file, const SpirvWords& words, EmitKind kind,
                          bool& optimise, EmitResult& result) {
  const uint64_t cross_limit = CrossCompileLimit(kind);
  if (!optimise && cross_limit == UINT64_MAX) return true;
  const uint64_t inlined = InlinedInstructionCount(words);
  const auto report = [&](Severity severity, uint64_t limit, const std::string& outcome) {
    const std::string count = inlined == UINT64_MAX ? "more than 2^64" : std::to_string(inlined);
    result.diagnostics.push_back({severity,
                                  "spirv/inlining-too-large",
                                  {file.Id(), 0, 0},
                                  outcome + ": with every call inlined the entry point has " +
                                      count + " SPIR-V instructions, more than the " +
                                      std::to_string(limit) + " allowed (docs/limits.md)",
                                  {},
                                  {}});
  };
  if (inlined > cross_limit) {
    report(Severity::kError, cross_limit, "SPIRV-Cross was not run");
    return false;
  }
  if (optimise && inlined > limits::kMaxInlinedInstructions) {
    report(Severity::kWarning, limits::kMaxInlinedInstructions,
           "not optimised (the unoptimised module is used)");
    optimise = false;
  }
  return true;
}

void EmitSpirvKinds(const SourceFile& file, model::Stage stage, const EmitOptions& options,
                    EmitResult& result) {
  SpirvCompilation compiled = CompileToSpirv(file, stage);
  result.diagnostics = std::move(compiled.diagnostics);
  if (HasErrors(result.diagnostics)) return;
  result.words_before = result.words_after = compiled.words.size();
  if (const std::string invalid = ValidateSpirv(compiled.words); !invalid.empty()) {
    Report(result, file, "spirv/invalid-module", "spirv-val rejects glslang's module: " + invalid);
    return;
  }
  SpirvWords optimized;
  bool optimise = options.optimize.has_value();
  if (!WithinInliningLimits(file, compiled.words, options.kind, optimise, result)) return;
  if (optimise) {
    OptimizeOutcome outcome =
        OptimizeSpirv(compiled.words, *OptimizeLevelFromName(*options.optimize));
    if (outcome.words.empty()) {
      Report(result, file, "spirv/optimizer-failed", "spirv-opt: " + outcome.error);
      return;
    }
    if (const std::string invalid = ValidateSpirv(outcome.words); !invalid.empty()) {
      Report(result, file, "spirv/invalid-module",
             "spirv-val rejects the optimised module: " + invalid);
      return;
    }
    optimized = std::move(outcome.words);
    result.words_after = optimized.size();
  }
  // Unoptimised SPIR-V cross-compiles to readable code; --opt asks for the optimised one.
  const SpirvWords& module = optimise ? optimized : compiled.words;
  EmitFromModule(file, options, stage, module, compiled.words, result);
  if (HasErrors(result.diagnostics)) result.output.clear();
}

}  // namespace

std::optional<EmitKind> EmitKindFromName(std::string_view name) {
  for (const auto& [kind, kind_name] : kNames) {
    if (name == kind_name) return kind;
  }
  return std::nullopt;
}

const char* EmitKindName(EmitKind kind) {
  for (const auto& [known, name] : kNames) {
    if (known == kind) return name;
  }
  return "essl";
}

std::string EmitExtension(EmitKind kind, model::Stage stage) {
  switch (kind) {
    case EmitKind::kEssl:
    case EmitKind::kEsslRoundtrip:
      return stage == model::Stage::kVertex ? ".vert" : ".frag";
    case EmitKind::kSpirv:
      return ".spv";
    case EmitKind::kSpvasm:
      return ".spvasm";
    case EmitKind::kHlsl:
      return ".hlsl";
    case EmitKind::kMsl:
      return ".metal";
    case EmitKind::kReflect:
      return ".json";
  }
  return "";
}

EmitResult Emit(const SourceFile& file, model::Stage stage, const EmitOptions& options) {
  EmitResult result;
  if (!CheckOptions(file, options, result)) return result;
  if (options.kind == EmitKind::kEssl) {
    result.output = std::string(file.Text());
    return result;
  }
  const bool ran = RunOnLargeStack([&] { EmitSpirvKinds(file, stage, options, result); });
  if (!ran) Report(result, file, "internal/error", "could not start the SPIR-V worker thread");
  return result;
}

}  // namespace shaderport::toolchain
