#include "driver/config/glob.h"

#include <vector>

namespace shaderport::driver {
namespace {

enum class Op { kLiteral, kAnyChar, kStar, kGlobStar, kAnyDirectories };

struct Piece {
  Op op;
  char c = 0;
};

std::vector<Piece> Compile(std::string_view pattern) {
  if (!pattern.empty() && pattern.front() == '/') pattern.remove_prefix(1);
  std::vector<Piece> pieces;
  for (size_t i = 0; i < pattern.size(); ++i) {
    const char c = pattern[i];
    if (c == '?') {
      pieces.push_back({Op::kAnyChar});
    } else if (c == '*' && i + 1 < pattern.size() && pattern[i + 1] == '*') {
      const bool segment_start = i == 0 || pattern[i - 1] == '/';
      if (segment_start && i + 2 < pattern.size() && pattern[i + 2] == '/') {
        pieces.push_back({Op::kAnyDirectories});  // "**/": zero or more whole directories
        i += 2;
      } else {
        pieces.push_back({Op::kGlobStar});
        ++i;
      }
    } else if (c == '*') {
      pieces.push_back({Op::kStar});
    } else {
      pieces.push_back({Op::kLiteral, c});
    }
  }
  return pieces;
}

}  // namespace

std::string GlobError(std::string_view pattern) {
  if (pattern.empty()) return "an empty glob matches nothing";
  if (pattern.find("***") != std::string_view::npos) return "'***' is not a glob; use '**'";
  if (pattern.find('\\') != std::string_view::npos) return "use '/' to separate directories";
  for (size_t start = 0; start <= pattern.size();) {
    size_t end = pattern.find('/', start);
    if (end == std::string_view::npos) end = pattern.size();
    if (pattern.substr(start, end - start) == "..") {
      return "'..' cannot be used: globs match files under the config file's directory";
    }
    start = end + 1;
  }
  return "";
}

bool GlobMatches(std::string_view pattern, std::string_view path) {
  const std::vector<Piece> pieces = Compile(pattern);
  // matched[j]: the pieces so far match path[0, j).
  std::vector<char> matched(path.size() + 1, 0);
  std::vector<char> next(path.size() + 1, 0);
  matched[0] = 1;
  for (const Piece& piece : pieces) {
    std::fill(next.begin(), next.end(), 0);
    bool reachable = false;  // for kAnyDirectories: some earlier j matched
    for (size_t j = 0; j <= path.size(); ++j) {
      switch (piece.op) {
        case Op::kLiteral:
          if (j > 0 && matched[j - 1] && path[j - 1] == piece.c) next[j] = 1;
          break;
        case Op::kAnyChar:
          if (j > 0 && matched[j - 1] && path[j - 1] != '/') next[j] = 1;
          break;
        case Op::kStar:
          next[j] = matched[j] || (j > 0 && next[j - 1] && path[j - 1] != '/');
          break;
        case Op::kGlobStar:
          next[j] = matched[j] || (j > 0 && next[j - 1]);
          break;
        case Op::kAnyDirectories:
          next[j] = matched[j] || (reachable && path[j - 1] == '/');
          break;
      }
      reachable = reachable || matched[j];
    }
    matched.swap(next);
  }
  return matched[path.size()] != 0;
}

}  // namespace shaderport::driver
