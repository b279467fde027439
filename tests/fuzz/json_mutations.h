// Structured mutations of a JSON document for the project readers' fuzz targets
// and their unit test: a value replaced by one of another type (a string "0" for a
// channel number), a member removed, or a value wrapped in the wrong shape (an
// object where a list is read, a list where an object is). Byte mutations alone
// rarely make a well-formed document with one member of the wrong type.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shaderport::fuzz {

// Every value below the root, parents before their children.
inline void CollectPointers(const nlohmann::json& value, const nlohmann::json::json_pointer& at,
                            std::vector<nlohmann::json::json_pointer>& out) {
  if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      out.push_back(at / key);
      CollectPointers(member, at / key, out);
    }
  } else if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i) {
      out.push_back(at / i);
      CollectPointers(value[i], at / i, out);
    }
  }
}

inline std::vector<nlohmann::json::json_pointer> AllPointers(const nlohmann::json& document) {
  std::vector<nlohmann::json::json_pointer> pointers;
  CollectPointers(document, nlohmann::json::json_pointer(), pointers);
  return pointers;
}

// Values of every other type and edge of range, for a type swap.
inline std::vector<nlohmann::json> TypeSwaps(const nlohmann::json& value) {
  std::vector<nlohmann::json> swaps = {"0",
                                       0,
                                       -1,
                                       4,
                                       1.5,
                                       4294967296.0,
                                       18446744073709551615ULL,
                                       -9223372036854775807LL - 1,
                                       true,
                                       nullptr,
                                       nlohmann::json::array(),
                                       nlohmann::json::object()};
  if (value.is_string()) {
    swaps.push_back(value.get<std::string>().size());  // a number where a string was
  } else {
    swaps.push_back(value.dump());  // the value as a string: "0", "[1]"
  }
  return swaps;
}

// The wrong shapes: the value wrapped in a list, or in an object.
inline std::vector<nlohmann::json> WrongShapes(const nlohmann::json& value) {
  return {nlohmann::json::array({value}), nlohmann::json{{"value", value}}};
}

enum class JsonMutation { kTypeSwap, kRemoveMember, kWrongShape };

// `document` with the value at `at` changed by `mutation` (choosing among the
// variants with `variant`); false when it does not apply (removing an array element).
inline bool MutateAt(nlohmann::json& document, const nlohmann::json::json_pointer& at,
                     JsonMutation mutation, uint64_t variant) {
  nlohmann::json& value = document[at];
  switch (mutation) {
    case JsonMutation::kTypeSwap: {
      const std::vector<nlohmann::json> swaps = TypeSwaps(value);
      value = swaps[variant % swaps.size()];
      return true;
    }
    case JsonMutation::kWrongShape: {
      const std::vector<nlohmann::json> shapes = WrongShapes(value);
      value = shapes[variant % shapes.size()];
      return true;
    }
    case JsonMutation::kRemoveMember: {
      nlohmann::json& parent = document[at.parent_pointer()];
      if (!parent.is_object()) return false;
      parent.erase(at.back());
      return true;
    }
  }
  return false;
}

// One random structured mutation of `document` (unchanged when it has no values).
template <typename Random>
nlohmann::json MutateJson(nlohmann::json document, Random& random) {
  const std::vector<nlohmann::json::json_pointer> pointers = AllPointers(document);
  if (pointers.empty()) return document;
  const auto& at = pointers[random() % pointers.size()];
  const auto mutation = static_cast<JsonMutation>(random() % 3);
  MutateAt(document, at, mutation, random());
  return document;
}

}  // namespace shaderport::fuzz
