// libFuzzer's custom mutator for the JSON project targets: half of the mutations are
// structured (json_mutations.h: a member of another type, a missing member, a value of
// the wrong shape, which byte flips seldom make in a document that still parses), the
// other half are libFuzzer's own. Include it in exactly one fuzz target source.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "json_mutations.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);
extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size,
                                          unsigned int seed) {
  std::mt19937_64 random(seed);
  if (random() % 2 == 0) {
    const nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
    if (!document.is_discarded()) {
      const std::string mutated = shaderport::fuzz::MutateJson(document, random).dump();
      if (mutated.size() <= max_size) {
        std::memcpy(data, mutated.data(), mutated.size());
        return mutated.size();
      }
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}
