#include "driver/channel_notes.h"

#include <string>

#include "rules/shadertoy/harness_support.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

// Where the channel's type came from, as the decision recorded it.
std::string Origin(const FileDecision& decision, const std::string& name) {
  for (const DecisionReason& reason : decision.reasons) {
    if (reason.part == name) return reason.because;
  }
  return "the default";
}

bool Overlaps(const SourceRange& a, const SourceRange& b) {
  return a.file == b.file && a.begin <= b.end && b.begin <= a.end;
}

}  // namespace

void ExplainChannelErrors(const FrontEndResult& front, const FileDecision& decision,
                          DiagnosticList& diagnostics) {
  if (decision.harness == nullptr || !front.model) return;
  const auto names = rules::harness::ChannelNames(*decision.harness);
  const auto uses = rules::harness::ReadChannelUses(front.parsed.tree, *front.model, names);
  const glsl::SyntaxTree& tree = front.parsed.tree;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) continue;
    const bool flat = decision.channels[i] == model::ChannelKind::k2D;
    // The sampling that the channel's type does not fit.
    const uint32_t misfit = flat ? uses[i].first_cube : uses[i].first_2d;
    if (misfit == glsl::kNoNode || misfit >= tree.NodeCount()) continue;
    const SourceRange call = tree.NodeAt(misfit).range;
    const std::string note =
        names[i] + " is a " + std::string(model::ChannelKindName(decision.channels[i])) +
        " texture here (" + Origin(decision, names[i]) + "), and this samples it with a " +
        (flat ? "3-component coordinate, as a cube map or 3D texture is"
              : "2-component coordinate, as a 2D texture is") +
        ": give it as --channel " + std::to_string(i) + "=" + (flat ? "cube" : "2d") +
        " (or the project's input of that kind) if that is what the site feeds it";
    for (Diagnostic& diagnostic : diagnostics) {
      if (diagnostic.severity != Severity::kError || !diagnostic.rule_id.starts_with("glslang/") ||
          !Overlaps(diagnostic.range, call)) {
        continue;
      }
      diagnostic.notes.push_back({call, note});
    }
  }
}

}  // namespace shaderport::driver
