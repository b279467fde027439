#include "toolchain/spirv_tools.h"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace shaderport::toolchain {
namespace {

constexpr spv_target_env kEnv = SPV_ENV_OPENGL_4_5;

// Collects SPIRV-Tools' messages (errors and worse) into one string.
spvtools::MessageConsumer Collect(std::string& out) {
  return [&out](spv_message_level_t level, const char*, const spv_position_t& position,
                const char* message) {
    if (level > SPV_MSG_ERROR) return;
    if (!out.empty()) out += '\n';
    out += "word " + std::to_string(position.index) + ": " + message;
  };
}

}  // namespace

std::optional<OptimizeLevel> OptimizeLevelFromName(const std::string& name) {
  if (name == "O") return OptimizeLevel::kPerformance;
  if (name == "Os") return OptimizeLevel::kSize;
  return std::nullopt;
}

std::string ValidateSpirv(const SpirvWords& words) {
  spvtools::SpirvTools tools(kEnv);
  std::string messages;
  tools.SetMessageConsumer(Collect(messages));
  if (tools.Validate(words)) return "";
  return messages.empty() ? "the module is invalid" : messages;
}

OptimizeOutcome OptimizeSpirv(const SpirvWords& words, OptimizeLevel level) {
  spvtools::Optimizer optimizer(kEnv);
  OptimizeOutcome outcome;
  optimizer.SetMessageConsumer(Collect(outcome.error));
  if (level == OptimizeLevel::kPerformance) {
    optimizer.RegisterPerformancePasses();
  } else {
    optimizer.RegisterSizePasses();
  }
  if (!optimizer.Run(words.data(), words.size(), &outcome.words)) {
    outcome.words.clear();
    if (outcome.error.empty()) outcome.error = "the optimiser failed";
  }
  return outcome;
}

std::string DisassembleSpirv(const SpirvWords& words) {
  spvtools::SpirvTools tools(kEnv);
  std::string text;
  std::string ignored;
  tools.SetMessageConsumer(Collect(ignored));
  const uint32_t options =
      SPV_BINARY_TO_TEXT_OPTION_INDENT | SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES;
  if (!tools.Disassemble(words, &text, options)) return "";
  return text;
}

SpirvWords InlineAllCalls(const SpirvWords& words) {
  spvtools::Optimizer optimizer(kEnv);
  std::string ignored;
  optimizer.SetMessageConsumer(Collect(ignored));
  optimizer.RegisterPass(spvtools::CreateInlineExhaustivePass());
  SpirvWords inlined;
  if (!optimizer.Run(words.data(), words.size(), &inlined)) return words;
  return inlined;
}

}  // namespace shaderport::toolchain
