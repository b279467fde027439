// What a word means in a given GLSL ES version, read from keywords.def.
#pragma once

#include <string_view>

namespace shaderport::glsl {

enum class WordStatus : uint8_t { kIdentifier, kKeyword, kReserved };

enum class WordRole : uint8_t {
  kNone,                // only reserved
  kType,                // a built-in type name
  kQualifier,           // storage, interpolation, invariant or layout qualifier
  kPrecisionQualifier,  // lowp, mediump, highp
  kPrecision,           // the `precision` statement keyword
  kControl,             // if, for, return, switch, ...
  kStruct,
  kBoolLiteral,
};

struct WordInfo {
  WordStatus status = WordStatus::kIdentifier;
  WordRole role = WordRole::kNone;  // kNone unless status is kKeyword
};

/// Classifies `word` for `version` (100 or 300; other numbers count as 300 from 300 up).
WordInfo ClassifyWord(std::string_view word, int version);

}  // namespace shaderport::glsl
