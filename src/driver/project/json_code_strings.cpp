#include "driver/project/json_code_strings.h"

#include <cstdio>

namespace shaderport::driver::project {
namespace {

struct Frame {
  bool object = false;
  bool expect_key = true;  // objects: the next string is a member name
  size_t index = 0;        // arrays: the element being read
  std::string key;         // objects: the current member's name
};

// RFC 6901: "~" -> "~0", "/" -> "~1".
void AppendPointerToken(std::string& pointer, std::string_view token) {
  pointer += '/';
  for (char c : token) {
    if (c == '~') {
      pointer += "~0";
    } else if (c == '/') {
      pointer += "~1";
    } else {
      pointer += c;
    }
  }
}

std::string PointerOf(const std::vector<Frame>& stack) {
  std::string pointer;
  for (const Frame& frame : stack)
    AppendPointerToken(pointer, frame.object ? frame.key : std::to_string(frame.index));
  return pointer;
}

// Offset one past the closing quote of the string starting at `at` (a quote).
size_t StringEnd(std::string_view json, size_t at) {
  size_t i = at + 1;
  while (i < json.size() && json[i] != '"') i += json[i] == '\\' ? 2 : 1;
  return i < json.size() ? i + 1 : json.size();
}

unsigned HexValue(std::string_view digits) {
  unsigned value = 0;
  for (char c : digits) {
    value <<= 4U;
    if (c >= '0' && c <= '9') value |= static_cast<unsigned>(c - '0');
    if (c >= 'a' && c <= 'f') value |= static_cast<unsigned>(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') value |= static_cast<unsigned>(c - 'A' + 10);
  }
  return value;
}

void AppendUtf8(std::string& out, unsigned code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

}  // namespace

namespace {

// Calls `on_value(stack, begin, end)` for every value of the document, in order, with
// the stack of the containers around it (an object's frame holds the member's key).
// `end` is one past a string or scalar; for a container, its opening bracket + 1.
template <typename OnValue>
void WalkValues(std::string_view json, OnValue on_value) {
  std::vector<Frame> stack;
  // Marks the end of a value: an array moves to its next element.
  auto value_done = [&] {
    if (stack.empty()) return;
    if (stack.back().object) {
      stack.back().expect_key = true;
    } else {
      ++stack.back().index;
    }
  };
  size_t i = 0;
  while (i < json.size()) {
    const char c = json[i];
    if (c == '{' || c == '[') {
      on_value(stack, i, i + 1);
      Frame frame;
      frame.object = c == '{';
      stack.push_back(frame);
      ++i;
    } else if (c == '}' || c == ']') {
      if (!stack.empty()) stack.pop_back();
      value_done();
      ++i;
    } else if (c == '"') {
      const size_t end = StringEnd(json, i);
      if (!stack.empty() && stack.back().object && stack.back().expect_key) {
        stack.back().key =
            DecodeWithOffsets(json, {static_cast<uint32_t>(i), static_cast<uint32_t>(end)}).text;
        stack.back().expect_key = false;
      } else {
        on_value(stack, i, end);
        value_done();
      }
      i = end;
    } else if (c == ',' || c == ':' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
    } else {
      // A number or literal: runs to the next delimiter.
      const size_t begin = i;
      while (i < json.size() && json[i] != ',' && json[i] != '}' && json[i] != ']' &&
             json[i] != ' ' && json[i] != '\n' && json[i] != '\r' && json[i] != '\t')
        ++i;
      on_value(stack, begin, i);
      value_done();
    }
  }
}

}  // namespace

std::map<std::string, JsonLiteral> FindStringValues(std::string_view json, std::string_view key) {
  std::map<std::string, JsonLiteral> found;
  WalkValues(json, [&](const std::vector<Frame>& stack, size_t begin, size_t end) {
    if (json[begin] == '"' && !stack.empty() && stack.back().object && stack.back().key == key)
      found.emplace(PointerOf(stack),
                    JsonLiteral{static_cast<uint32_t>(begin), static_cast<uint32_t>(end)});
  });
  return found;
}

std::map<std::string, uint32_t> FindValueOffsets(std::string_view json,
                                                 const std::set<std::string>& pointers) {
  std::map<std::string, uint32_t> found;
  if (pointers.empty()) return found;
  WalkValues(json, [&](const std::vector<Frame>& stack, size_t begin, size_t) {
    std::string pointer = PointerOf(stack);
    if (pointers.count(pointer) != 0)
      found.emplace(std::move(pointer), static_cast<uint32_t>(begin));
  });
  return found;
}

DecodedString DecodeWithOffsets(std::string_view json, JsonLiteral literal) {
  DecodedString out;
  const size_t end =
      literal.end > literal.begin ? literal.end - 1 : literal.begin;  // closing quote
  out.text.reserve(end - literal.begin);
  out.offsets.reserve(end - literal.begin + 1);
  size_t i = literal.begin + 1;
  auto emit = [&](size_t from, size_t before) {
    while (out.offsets.size() < before) out.offsets.push_back(static_cast<uint32_t>(from));
  };
  while (i < end) {
    const size_t start = i;
    if (json[i] != '\\') {
      out.text += json[i];
      ++i;
    } else if (i + 1 < end && json[i + 1] == 'u' && i + 6 <= end) {
      unsigned code_point = HexValue(json.substr(i + 2, 4));
      i += 6;
      if (code_point >= 0xD800 && code_point < 0xDC00 && i + 6 <= end && json[i] == '\\' &&
          json[i + 1] == 'u') {
        const unsigned low = HexValue(json.substr(i + 2, 4));
        if (low >= 0xDC00 && low < 0xE000) {
          code_point = 0x10000 + ((code_point - 0xD800) << 10U) + (low - 0xDC00);
          i += 6;
        }
      }
      AppendUtf8(out.text, code_point);
    } else if (i + 1 < end) {
      const char escaped = json[i + 1];
      const char decoded = escaped == 'n'   ? '\n'
                           : escaped == 't' ? '\t'
                           : escaped == 'r' ? '\r'
                           : escaped == 'b' ? '\b'
                           : escaped == 'f' ? '\f'
                                            : escaped;  // " \ /
      out.text += decoded;
      i += 2;
    } else {
      ++i;  // a lone backslash at the end: invalid JSON, not reached after parsing
    }
    emit(start, out.text.size());
  }
  out.offsets.push_back(static_cast<uint32_t>(end));
  return out;
}

std::string EncodeJsonString(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8 + 2);
  out += '"';
  for (char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  out += '"';
  return out;
}

}  // namespace shaderport::driver::project
