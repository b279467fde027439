// Byte-exact access to string values inside a JSON document: where each one sits,
// which document byte each decoded byte came from, and how to write a string back.
// nlohmann::json decodes values but forgets positions; findings and in-place edits
// of a project's code need them.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::driver::project {

struct JsonLiteral {
  uint32_t begin = 0;  // the opening quote
  uint32_t end = 0;    // one past the closing quote
};

// Every string value whose member name is `key`, by JSON pointer (RFC 6901), e.g.
// "/Shader/renderpass/2/code". `json` must be a valid document (parse it first).
std::map<std::string, JsonLiteral> FindStringValues(std::string_view json, std::string_view key);

// The offset of the first byte of each value whose JSON pointer is in `pointers`
// (one scan of the text). `json` must be a valid document.
std::map<std::string, uint32_t> FindValueOffsets(std::string_view json,
                                                 const std::set<std::string>& pointers);

struct DecodedString {
  std::string text;
  // Document offset of each decoded byte; one more entry, the closing quote.
  std::vector<uint32_t> offsets;
};

// Decodes the literal at `literal` (escapes, \u surrogate pairs to UTF-8).
DecodedString DecodeWithOffsets(std::string_view json, JsonLiteral literal);

// `text` as a JSON string literal with its quotes: `"` `\` and control characters
// escaped (\n \t \r \b \f, \u00XX otherwise), other bytes as they are.
std::string EncodeJsonString(std::string_view text);

}  // namespace shaderport::driver::project
