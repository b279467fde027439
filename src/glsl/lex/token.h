// Tokens of GLSL ES source, shared by the lexer, the preprocessor and the parser.
#pragma once

#include <cstdint>
#include <string_view>

#include "source/source_file.h"

namespace shaderport::glsl {

enum class TokenKind : uint8_t {
  kEndOfFile,
  kIdentifier,    // every word, keywords included: the parser classifies them by version
  kIntLiteral,    // 1, 0x1F, 017 (with or without a u/U suffix: see kUintLiteral)
  kUintLiteral,   // 1u, 0x1Fu
  kFloatLiteral,  // 1.0, 1., .5, 1e3, 1.0f
  kPunctuator,    // see Punct
  kHash,          // '#' that starts a directive (first token on its line)
  kInvalid,       // a byte that starts no token (e.g. '$', '@', a NUL or non-ASCII byte)
};

enum class Punct : uint8_t {
  kNone,
  kLeftParen,
  kRightParen,
  kLeftBracket,
  kRightBracket,
  kLeftBrace,
  kRightBrace,
  kDot,
  kComma,
  kColon,
  kSemicolon,
  kQuestion,
  kPlus,
  kMinus,
  kStar,
  kSlash,
  kPercent,
  kPlusPlus,
  kMinusMinus,
  kLess,
  kGreater,
  kLessEqual,
  kGreaterEqual,
  kEqualEqual,
  kNotEqual,
  kAndAnd,
  kOrOr,
  kXorXor,
  kBang,
  kTilde,
  kAmp,
  kPipe,
  kCaret,
  kShiftLeft,
  kShiftRight,
  kEqual,
  kPlusEqual,
  kMinusEqual,
  kStarEqual,
  kSlashEqual,
  kPercentEqual,
  kShiftLeftEqual,
  kShiftRightEqual,
  kAmpEqual,
  kPipeEqual,
  kCaretEqual,
  kHashHash,    // '##' (only meaningful inside #define)
  kHashInLine,  // '#' not at the start of a line (stringizing is not GLSL; kept for #define bodies)
};

// Trivia are the bytes between tokens: they are kept so that joining every
// token's leading trivia and text gives back the input byte for byte.
enum class TriviaKind : uint8_t {
  kWhitespace,        // spaces, tabs, form feeds, vertical tabs
  kNewline,           // "\n", "\r\n" or "\r"
  kLineComment,       // "// ..." up to, not including, the newline
  kBlockComment,      // "/* ... */" (an unterminated one runs to end of file)
  kLineContinuation,  // backslash followed by a newline
  kSkipped,           // bytes left unlexed after limits::kMaxTokens was reached
};

struct Trivia {
  TriviaKind kind;
  uint32_t begin;  // byte offsets in the file
  uint32_t end;
};

// A token as lexed from one file: it points into the file's text.
struct Token {
  TokenKind kind = TokenKind::kEndOfFile;
  Punct punct = Punct::kNone;
  uint32_t begin = 0;  // byte range of the token's own text
  uint32_t end = 0;
  uint32_t trivia_begin = 0;   // index into LexedFile::trivia of the first leading trivia
  uint32_t trivia_end = 0;     // one past the last leading trivia
  bool at_line_start = false;  // first token on its (logical) line
  bool leading_space = false;  // whitespace or a comment precedes it on the same line
  std::string_view text;       // the token's bytes (may contain line continuations)
};

}  // namespace shaderport::glsl
