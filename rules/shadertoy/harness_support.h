// What the harness rules share: the harness's entry point found in the code,
// fresh names, where declarations go, and which sampler each channel needs.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "model/harness_dialect.h"
#include "rule/harness_dialect_detect.h"
#include "rule/rule_context.h"

namespace shaderport::rules::harness {

// The dialect's entry point the code defines (first in the dialect's order), if any.
const model::EntryPoint* DefinedEntryPoint(const model::HarnessDialect& dialect,
                                           const rule::CodeInterface& code);

// The FunctionDeclaration (with a body) of `name` in this file, if any.
const glsl::FunctionDeclaration* FindDefinition(const rule::RuleContext& context,
                                                std::string_view name);

// Hands out names no identifier of the shader (or an earlier handed-out name) uses.
class FreshNames {
 public:
  explicit FreshNames(const rule::RuleContext& context);
  std::string Make(std::string_view base);

 private:
  bool Taken(std::string_view name) const;
  std::set<std::string, std::less<>> used_;
};

// Offset just after the leading #version and #extension lines; nullopt when the
// file has no #version yet (port/version adds it at offset 0 first: waiting a
// round keeps the two insertions from competing for the same offset).
std::optional<uint32_t> AfterVersionLines(const rule::RuleContext& context);

// Names given to `#define` anywhere in the file (active or not).
std::set<std::string, std::less<>> DefinedMacros(const rule::RuleContext& context);

// How the code samples one channel.
struct ChannelUse {
  uint32_t first_2d = glsl::kNoNode;    // a call with a 2-component coordinate
  uint32_t first_cube = glsl::kNoNode;  // a 3-component coordinate, or textureCube*
  bool Conflicting() const { return first_2d != glsl::kNoNode && first_cube != glsl::kNoNode; }
  // Sampled only as a cube map: what an untold channel is taken to be.
  bool OnlyCube() const { return first_cube != glsl::kNoNode && first_2d == glsl::kNoNode; }
};

// How the code samples each of the channels named `names` (empty: no such channel).
std::array<ChannelUse, 4> ReadChannelUses(const glsl::SyntaxTree& tree,
                                          const glsl::SemanticModel& model,
                                          const std::array<std::string, 4>& names);

// The names of the dialect's channel variables by channel number ("" where none).
std::array<std::string, 4> ChannelNames(const model::HarnessDialect& dialect);

// Sampler type of each provided channel (index = ProvidedVariable::channel): from
// the settings when told, else cube when the code samples it only with 3-component
// coordinates, else 2D. sampler3D only when told (a 3D coordinate looks like a cube's).
struct ChannelChoice {
  std::string type;  // "sampler2D", "samplerCube", "sampler3D"
  bool told = false;
  ChannelUse use;
};
std::array<ChannelChoice, 4> ChooseChannels(const rule::RuleContext& context,
                                            const model::HarnessDialect& dialect);

// The chosen type for one provided variable (its own type unless it is a channel).
std::string TypeFor(const model::ProvidedVariable& variable,
                    const std::array<ChannelChoice, 4>& channels);

}  // namespace shaderport::rules::harness
