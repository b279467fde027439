#include "token_mutator.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <random>

namespace shaderport::fuzz {
namespace {

bool IsIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsIdent(char c) { return IsIdentStart(c) || IsDigit(c); }
bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }

// Longest first, so that "<<=" wins over "<<" and "<".
constexpr std::array<std::string_view, 22> kOperators = {
    "<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&",
    "||",  "^^",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "##"};

// Tokens worth dropping in: what shader code is made of, and what the rules look for.
constexpr std::array<std::string_view, 48> kVocabulary = {"float",
                                                          "vec2",
                                                          "vec3",
                                                          "vec4",
                                                          "int",
                                                          "ivec2",
                                                          "mat3",
                                                          "sampler2D",
                                                          "uniform",
                                                          "in",
                                                          "out",
                                                          "inout",
                                                          "const",
                                                          "highp",
                                                          "mediump",
                                                          "precision",
                                                          "void",
                                                          "return",
                                                          "for",
                                                          "if",
                                                          "else",
                                                          "while",
                                                          "discard",
                                                          "struct",
                                                          "texture",
                                                          "texture2D",
                                                          "mix",
                                                          "clamp",
                                                          "normalize",
                                                          "gl_FragColor",
                                                          "gl_FragCoord",
                                                          "fragColor",
                                                          "iTime",
                                                          "iResolution",
                                                          "iMouse",
                                                          "iChannel0",
                                                          "mainImage",
                                                          "main",
                                                          "#define",
                                                          "#version 300 es\n",
                                                          "#ifdef",
                                                          "#endif\n",
                                                          "1.0",
                                                          "0",
                                                          "(",
                                                          ")",
                                                          ";",
                                                          "{"};

size_t ScanToken(std::string_view text, size_t p, bool line_start) {
  const size_t n = text.size();
  const char c = text[p];
  if (IsBlank(c)) {
    size_t e = p;
    while (e < n && IsBlank(text[e])) ++e;
    return e;
  }
  if (c == '#' && line_start) {  // a directive: to the end of the line, with continuations
    size_t e = p;
    while (e < n && text[e] != '\n') e += (text[e] == '\\' && e + 1 < n) ? 2 : 1;
    return e;
  }
  if (c == '/' && p + 1 < n && text[p + 1] == '/') {
    const size_t e = text.find('\n', p);
    return e == std::string_view::npos ? n : e;
  }
  if (c == '/' && p + 1 < n && text[p + 1] == '*') {
    const size_t e = text.find("*/", p + 2);
    return e == std::string_view::npos ? n : e + 2;
  }
  if (IsIdentStart(c)) {
    size_t e = p;
    while (e < n && IsIdent(text[e])) ++e;
    return e;
  }
  if (IsDigit(c) || (c == '.' && p + 1 < n && IsDigit(text[p + 1]))) {
    size_t e = p;
    while (e < n &&
           (IsIdent(text[e]) || text[e] == '.' ||
            ((text[e] == '+' || text[e] == '-') && (text[e - 1] == 'e' || text[e - 1] == 'E'))))
      ++e;
    return e;
  }
  for (std::string_view op : kOperators) {
    if (text.substr(p, op.size()) == op) return p + op.size();
  }
  return p + 1;
}

std::string Join(const std::vector<std::string_view>& tokens, size_t begin, size_t end) {
  std::string out;
  for (size_t i = begin; i < end && i < tokens.size(); ++i) out += tokens[i];
  return out;
}

}  // namespace

std::vector<std::string_view> TokenizeGlsl(std::string_view text) {
  std::vector<std::string_view> tokens;
  bool line_start = true;
  for (size_t p = 0; p < text.size();) {
    const size_t e = ScanToken(text, p, line_start);
    const std::string_view token = text.substr(p, e - p);
    // Only blanks may stand between a line's start and a directive's '#'.
    if (token.find('\n') != std::string_view::npos) {
      line_start = true;
    } else if (!IsBlank(token.front())) {
      line_start = false;
    }
    tokens.push_back(token);
    p = e;
  }
  return tokens;
}

std::string MutateTokens(std::string_view text, const std::vector<std::string>& donors,
                         uint32_t seed, size_t max_size) {
  std::minstd_rand rng(seed);
  auto pick = [&rng](size_t bound) { return bound == 0 ? 0 : rng() % bound; };
  const std::vector<std::string_view> tokens = TokenizeGlsl(text);
  const size_t n = tokens.size();
  const size_t at = pick(n + 1);
  const size_t run = 1 + pick(std::min<size_t>(8, n - std::min(at, n)) + 1);
  const size_t run_end = std::min(n, at + run);
  auto donor = [&]() -> std::string {
    if (donors.empty()) return std::string(kVocabulary[pick(kVocabulary.size())]);
    return donors[pick(donors.size())];
  };
  std::string out;
  switch (pick(6)) {
    case 0:  // delete a run
      out = Join(tokens, 0, at) + Join(tokens, run_end, n);
      break;
    case 1:  // duplicate a run
      out = Join(tokens, 0, run_end) + Join(tokens, at, n);
      break;
    case 2: {  // swap two tokens
      std::vector<std::string_view> swapped = tokens;
      if (n > 1) std::swap(swapped[pick(n)], swapped[pick(n)]);
      out = Join(swapped, 0, n);
      break;
    }
    case 3:  // replace a run with a vocabulary token
      out = Join(tokens, 0, at) + " " + std::string(kVocabulary[pick(kVocabulary.size())]) + " " +
            Join(tokens, run_end, n);
      break;
    case 4:  // insert a token run of a real shader
      out = Join(tokens, 0, at) + donor() + Join(tokens, at, n);
      break;
    default:  // replace a run with a token run of a real shader
      out = Join(tokens, 0, at) + donor() + Join(tokens, run_end, n);
      break;
  }
  if (out.size() > max_size) out.resize(max_size);
  return out;
}

std::string CrossOverTokens(std::string_view first, std::string_view second, uint32_t seed,
                            size_t max_size) {
  std::minstd_rand rng(seed);
  auto pick = [&rng](size_t bound) { return bound == 0 ? 0 : rng() % bound; };
  const std::vector<std::string_view> a = TokenizeGlsl(first);
  const std::vector<std::string_view> b = TokenizeGlsl(second);
  const size_t cut = pick(a.size() + 1);
  const size_t resume = cut + pick(a.size() - cut + 1);
  const size_t from = pick(b.size() + 1);
  const size_t to = from + pick(std::min<size_t>(64, b.size() - from) + 1);
  std::string out = Join(a, 0, cut) + Join(b, from, to) + Join(a, resume, a.size());
  if (out.size() > max_size) out.resize(max_size);
  return out;
}

}  // namespace shaderport::fuzz

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

// Token runs harvested from the inputs the mutator is given: the seed corpus is
// real shaders, so most runs are real code.
std::vector<std::string>& Donors() {
  static std::vector<std::string> donors;
  return donors;
}

void Harvest(std::string_view text, uint32_t seed) {
  constexpr size_t kMaxDonors = 4096;
  const auto tokens = shaderport::fuzz::TokenizeGlsl(text);
  if (tokens.empty()) return;
  std::minstd_rand rng(seed ^ 0x9e3779b9u);
  const size_t at = rng() % tokens.size();
  const size_t end = std::min(tokens.size(), at + 1 + rng() % 16);
  std::string run;
  for (size_t i = at; i < end; ++i) run += tokens[i];
  auto& donors = Donors();
  if (donors.size() < kMaxDonors) {
    donors.push_back(std::move(run));
  } else {
    donors[rng() % kMaxDonors] = std::move(run);
  }
}

size_t Store(const std::string& text, uint8_t* data, size_t max_size) {
  const size_t size = std::min(text.size(), max_size);
  if (size > 0) std::memcpy(data, text.data(), size);
  return size;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size,
                                          unsigned int seed) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Harvest(text, seed);
  // A quarter of the time libFuzzer's own byte mutations (and its dictionary).
  if (seed % 4 == 0) return LLVMFuzzerMutate(data, size, max_size);
  return Store(shaderport::fuzz::MutateTokens(text, Donors(), seed, max_size), data, max_size);
}

extern "C" size_t LLVMFuzzerCustomCrossOver(const uint8_t* data1, size_t size1,
                                            const uint8_t* data2, size_t size2, uint8_t* out,
                                            size_t max_out_size, unsigned int seed) {
  const std::string_view first(reinterpret_cast<const char*>(data1), size1);
  const std::string_view second(reinterpret_cast<const char*>(data2), size2);
  return Store(shaderport::fuzz::CrossOverTokens(first, second, seed, max_out_size), out,
               max_out_size);
}
