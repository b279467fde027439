// "Did you mean" for a mistyped name from a closed set (commands, options, rule
// ids, option values): the closest name by edit distance, when it is close enough
// to be a typo.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace shaderport {

// Optimal string alignment distance: insertions, deletions, substitutions and
// swaps of two adjacent characters each cost 1; letters compare case-blind.
size_t EditDistance(std::string_view a, std::string_view b);

// The candidate nearest to `typed`, if at most max(1, length of `typed` / 3) edits
// away (as clang's "did you mean"); the first of equally near ones. Failing that,
// the only candidate that `typed` (two letters or more) abbreviates. nullopt when
// none is that near, or when `typed` is itself a candidate.
std::optional<std::string> ClosestName(std::string_view typed,
                                       std::span<const std::string> candidates);

}  // namespace shaderport
