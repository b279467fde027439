// A text scan, not a parse: the render layer sits below the GLSL front end. Comments
// are blanked first; a loop's bound is the largest number (or simple #define) on the
// right of a comparison in its condition; nested loops multiply.
#include "render/loop_cap.h"

#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "render/shader_text.h"

namespace shaderport::render {
namespace {

bool IsIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool KeywordAt(const std::string& text, size_t at, std::string_view word) {
  return text.compare(at, word.size(), word) == 0 && (at == 0 || !IsIdent(text[at - 1])) &&
         (at + word.size() >= text.size() || !IsIdent(text[at + word.size()]));
}

std::map<std::string, double> NumericDefines(const std::string& text) {
  std::map<std::string, double> defines;
  size_t at = 0;
  while ((at = text.find("#define", at)) != std::string::npos) {
    at += 7;
    size_t p = at;
    while (p < text.size() && (text[p] == ' ' || text[p] == '\t')) ++p;
    const size_t name_begin = p;
    while (p < text.size() && IsIdent(text[p])) ++p;
    const std::string name = text.substr(name_begin, p - name_begin);
    while (p < text.size() && (text[p] == ' ' || text[p] == '\t')) ++p;
    char* end = nullptr;
    const double value = std::strtod(text.c_str() + p, &end);
    if (!name.empty() && end != text.c_str() + p) defines[name] = value;
  }
  return defines;
}

// Index just past the bracket matching text[open] (one of '(' '{'), or npos.
size_t MatchClose(const std::string& text, size_t open) {
  const char o = text[open];
  const char c = o == '(' ? ')' : '}';
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == o) ++depth;
    if (text[i] == c && --depth == 0) return i + 1;
  }
  return std::string::npos;
}

// The bound in a loop condition: 0 when none is visible (e.g. `;;` or `true`).
double ConditionBound(std::string_view condition, const std::map<std::string, double>& defines,
                      bool& unknown) {
  double bound = 0;
  unknown = false;
  for (size_t i = 0; i < condition.size(); ++i) {
    if (condition[i] != '<' && condition[i] != '>') continue;
    size_t p = i + 1;
    if (p < condition.size() && condition[p] == '=') ++p;
    while (p < condition.size() && std::isspace(static_cast<unsigned char>(condition[p]))) ++p;
    const std::string rest(condition.substr(p));
    char* end = nullptr;
    const double value = std::strtod(rest.c_str(), &end);
    if (end != rest.c_str()) {
      bound = std::max(bound, value);
      continue;
    }
    size_t q = 0;
    while (q < rest.size() && IsIdent(rest[q])) ++q;
    auto it = defines.find(rest.substr(0, q));
    if (it != defines.end()) {
      bound = std::max(bound, it->second);
    } else {
      unknown = true;  // a uniform or variable: cannot tell
    }
  }
  return bound;
}

struct Loop {
  size_t keyword = 0;
  size_t body_end = 0;
  double iterations = 0;  // own bound; 0 when unbounded
  bool unbounded = false;
};

// A loop that may exceed llvmpipe's cap, with the range of its keyword.
struct SuspectLoop {
  SourceRange keyword;
  bool unbounded = false;   // no visible bound
  uint64_t iterations = 0;  // estimated per pixel, nested loops multiplied
};

std::vector<SuspectLoop> SuspectLoops(const SourceFile& file) {
  const std::string text = BlankComments(file.Text());
  const auto defines = NumericDefines(text);
  std::vector<Loop> loops;
  for (size_t i = 0; i < text.size(); ++i) {
    const bool is_for = KeywordAt(text, i, "for");
    const bool is_while = KeywordAt(text, i, "while");
    if (!is_for && !is_while) continue;
    const size_t open = text.find_first_not_of(" \t\r\n", i + (is_for ? 3 : 5));
    if (open == std::string::npos || text[open] != '(') continue;
    const size_t close = MatchClose(text, open);
    if (close == std::string::npos) break;
    std::string_view header(text.data() + open + 1, close - open - 2);
    std::string_view condition = header;
    if (is_for) {
      const size_t first = header.find(';');
      const size_t second = first == std::string_view::npos ? first : header.find(';', first + 1);
      if (second == std::string_view::npos) continue;
      condition = header.substr(first + 1, second - first - 1);
    }
    Loop loop;
    loop.keyword = i;
    bool unknown = false;
    loop.iterations = ConditionBound(condition, defines, unknown);
    const bool empty_condition = condition.find_first_not_of(" \t\r\n") == std::string_view::npos;
    const bool literal_true = condition.find("true") != std::string_view::npos &&
                              condition.find_first_of("<>=!") == std::string_view::npos;
    loop.unbounded = (empty_condition || literal_true) && !unknown;
    const size_t body = text.find_first_not_of(" \t\r\n", close);
    if (body != std::string::npos && text[body] == '{') {
      loop.body_end = MatchClose(text, body);
    } else {
      loop.body_end = text.find(';', close);
    }
    if (loop.body_end == std::string::npos) loop.body_end = text.size();
    loops.push_back(loop);
  }
  std::vector<SuspectLoop> suspects;
  for (size_t k = 0; k < loops.size(); ++k) {
    // Multiply by the bounds of the loops this one is nested in.
    double total = loops[k].iterations;
    for (size_t j = 0; j < k; ++j) {
      if (loops[j].body_end > loops[k].keyword && loops[j].iterations > 0) {
        total *= loops[j].iterations;
      }
    }
    const bool exceeds = total > static_cast<double>(kLlvmpipeLoopCap);
    if (!exceeds && !loops[k].unbounded) continue;
    const auto keyword = static_cast<uint32_t>(loops[k].keyword);
    suspects.push_back({{file.Id(), keyword, keyword + (text[keyword] == 'f' ? 3u : 5u)},
                        loops[k].unbounded,
                        static_cast<uint64_t>(total)});
  }
  return suspects;
}

}  // namespace

DiagnosticList LoopCapNotes(const SourceFile& file) {
  DiagnosticList notes;
  for (const SuspectLoop& loop : SuspectLoops(file)) {
    notes.push_back(MakeDiagnostic(
        Severity::kNote, "render/loop-cap", loop.keyword,
        loop.unbounded ? "this loop has no visible bound; llvmpipe stops every shader invocation "
                         "after 65535 loop iterations, so the smoke render may not show what a "
                         "browser does"
                       : "this loop may run about " + std::to_string(loop.iterations) +
                             " iterations per pixel, more than llvmpipe's silent cap of 65535: "
                             "the smoke render may not show what a browser does"));
  }
  return notes;
}

DiagnosticList LoopCapFindings(const SourceFile& file, const RenderOutcome& outcome,
                               const SourceRange& anchor) {
  if (outcome.max_loop_iterations < 0) return LoopCapNotes(file);
  if (outcome.loop_capped_pixels == 0) return {};
  const std::string message =
      "llvmpipe stopped the loops of " + std::to_string(outcome.loop_capped_pixels) + " of " +
      std::to_string(uint64_t{outcome.width} * outcome.height) +
      " pixels after 65535 iterations, so this picture is not what a browser draws: a browser "
      "runs every iteration, and a loop that never ends hangs the GPU until the page loses its "
      "WebGL context";
  DiagnosticList found;
  for (const SuspectLoop& loop : SuspectLoops(file)) {
    found.push_back(
        MakeDiagnostic(Severity::kWarning, "render/loop-cap", loop.keyword,
                       message + (loop.unbounded ? " (this loop has no visible bound)" : "")));
  }
  if (found.empty()) {
    found.push_back(MakeDiagnostic(Severity::kWarning, "render/loop-cap", anchor, message));
  }
  return found;
}

}  // namespace shaderport::render
