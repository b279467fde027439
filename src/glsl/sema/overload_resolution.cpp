#include "glsl/sema/overload_resolution.h"

#include <optional>
#include <vector>

namespace shaderport::glsl {
namespace {

template <typename Param, typename TypeOf>
ArgumentMatch Match(std::span<const Param> parameters, std::span<const Type> arguments,
                    TypeOf type_of) {
  if (parameters.size() != arguments.size()) return ArgumentMatch::kNone;
  bool uncertain = false;
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (arguments[i].IsUnknown()) {
      uncertain = true;
    } else if (!(arguments[i] == type_of(parameters[i]))) {
      return ArgumentMatch::kNone;
    }
  }
  return uncertain ? ArgumentMatch::kUncertain : ArgumentMatch::kExact;
}

// Resolves among `candidates` (only those available in `version` and `stage` when
// `available_only`); nullopt when none matches.
std::optional<BuiltinCallMatch> ResolveAmong(std::span<const BuiltinFunction* const> candidates,
                                             std::span<const Type> arguments, bool available_only,
                                             int version, model::Stage stage) {
  const BuiltinFunction* uncertain = nullptr;
  bool uncertain_types_agree = true;
  for (const BuiltinFunction* f : candidates) {
    if (available_only && !f->AvailableIn(version, stage)) continue;
    ArgumentMatch m = MatchArguments(f->params, arguments);
    if (m == ArgumentMatch::kExact) return BuiltinCallMatch{f, false, true};
    if (m == ArgumentMatch::kUncertain) {
      if (uncertain == nullptr) {
        uncertain = f;
      } else if (!(uncertain->return_type == f->return_type)) {
        uncertain_types_agree = false;
      }
    }
  }
  if (uncertain == nullptr) return std::nullopt;
  if (!uncertain_types_agree) return BuiltinCallMatch{nullptr, true, true};
  return BuiltinCallMatch{uncertain, true, true};
}

}  // namespace

ArgumentMatch MatchArguments(std::span<const Type> parameters, std::span<const Type> arguments) {
  return Match(parameters, arguments, [](const Type& t) { return t; });
}

ArgumentMatch MatchArguments(std::span<const BuiltinParam> parameters,
                             std::span<const Type> arguments) {
  return Match(parameters, arguments, [](const BuiltinParam& p) { return p.type; });
}

BuiltinCallMatch ResolveBuiltinCall(std::string_view name, std::span<const Type> arguments,
                                    int version, model::Stage stage) {
  return ResolveBuiltinCall(BuiltinOverloadList(name), arguments, version, stage);
}

BuiltinCallMatch ResolveBuiltinCall(std::span<const BuiltinFunction* const> all,
                                    std::span<const Type> arguments, int version,
                                    model::Stage stage) {
  // Runs for every built-in call (and again per promotion tried): no copies of the list.
  if (std::optional<BuiltinCallMatch> m = ResolveAmong(all, arguments, true, version, stage)) {
    return *m;
  }
  if (std::optional<BuiltinCallMatch> m = ResolveAmong(all, arguments, false, version, stage)) {
    m->available = false;
    return *m;
  }
  return {};
}

}  // namespace shaderport::glsl
