#include "driver/port/output_files.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "base/file_io/same_file.h"

namespace shaderport::driver {
namespace {

std::vector<std::string_view> SplitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start < text.size()) {
    const size_t newline = text.find('\n', start);
    const size_t end = newline == std::string_view::npos ? text.size() : newline + 1;
    lines.push_back(text.substr(start, end - start));
    start = end;
  }
  return lines;
}

enum class Op : char { kEqual = ' ', kDelete = '-', kInsert = '+' };
struct Step {
  Op op;
  size_t a;  // line index in before (for kEqual/kDelete)
  size_t b;  // line index in after (for kEqual/kInsert)
};

// Line edit script: common prefix and suffix, then an LCS table on the middle
// when it is small enough, else the middle as one replacement.
std::vector<Step> Script(const std::vector<std::string_view>& a,
                         const std::vector<std::string_view>& b) {
  size_t prefix = 0;
  while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix]) ++prefix;
  size_t suffix = 0;
  while (suffix < a.size() - prefix && suffix < b.size() - prefix &&
         a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix]) {
    ++suffix;
  }
  std::vector<Step> steps;
  for (size_t i = 0; i < prefix; ++i) steps.push_back({Op::kEqual, i, i});
  const size_t n = a.size() - prefix - suffix;
  const size_t m = b.size() - prefix - suffix;
  if (n * m <= 4'000'000) {
    std::vector<std::vector<uint32_t>> lcs(n + 1, std::vector<uint32_t>(m + 1, 0));
    for (size_t i = n; i-- > 0;) {
      for (size_t j = m; j-- > 0;) {
        lcs[i][j] = a[prefix + i] == b[prefix + j] ? lcs[i + 1][j + 1] + 1
                                                   : std::max(lcs[i + 1][j], lcs[i][j + 1]);
      }
    }
    size_t i = 0, j = 0;
    while (i < n || j < m) {
      if (i < n && j < m && a[prefix + i] == b[prefix + j]) {
        steps.push_back({Op::kEqual, prefix + i++, prefix + j++});
      } else if (j < m && (i == n || lcs[i][j + 1] >= lcs[i + 1][j])) {
        steps.push_back({Op::kInsert, 0, prefix + j++});
      } else {
        steps.push_back({Op::kDelete, prefix + i++, 0});
      }
    }
  } else {
    for (size_t i = 0; i < n; ++i) steps.push_back({Op::kDelete, prefix + i, 0});
    for (size_t j = 0; j < m; ++j) steps.push_back({Op::kInsert, 0, prefix + j});
  }
  for (size_t k = 0; k < suffix; ++k) {
    steps.push_back({Op::kEqual, a.size() - suffix + k, b.size() - suffix + k});
  }
  return steps;
}

void AppendLine(std::string& out, char prefix, std::string_view line) {
  out.push_back(prefix);
  out.append(line);
  if (line.empty() || line.back() != '\n') out.append("\n\\ No newline at end of file\n");
}

}  // namespace

std::filesystem::path OutDirPath(const std::filesystem::path& out_dir,
                                 const std::filesystem::path& relative,
                                 std::string_view extension) {
  std::filesystem::path inside = relative.lexically_normal();
  if (inside.is_absolute()) inside = inside.filename();
  while (!inside.empty() && *inside.begin() == "..") {
    inside = inside.lexically_relative(*inside.begin());
  }
  inside.replace_extension(extension);
  return out_dir / inside;
}

namespace {

namespace fs = std::filesystem;

// The argument an input came from, absolute: a named file's directory, or the
// directory that was walked (the path without its `relative` tail).
fs::path ArgumentDirectory(const InputFile& input) {
  std::error_code error;
  fs::path directory = fs::absolute(input.path, error).lexically_normal();
  if (input.named) return directory.parent_path();
  for (auto part = input.relative.begin(); part != input.relative.end(); ++part) {
    directory = directory.parent_path();
  }
  return directory;
}

fs::path CommonAncestor(const fs::path& a, const fs::path& b) {
  fs::path common;
  for (auto x = a.begin(), y = b.begin(); x != a.end() && y != b.end() && *x == *y; ++x, ++y) {
    common /= *x;
  }
  return common;
}

}  // namespace

void RelativeToCommonRoot(std::vector<InputFile>& inputs) {
  if (inputs.empty()) return;
  fs::path root = ArgumentDirectory(inputs.front());
  for (const InputFile& input : inputs) root = CommonAncestor(root, ArgumentDirectory(input));
  for (InputFile& input : inputs) {
    std::error_code error;
    const fs::path absolute = fs::absolute(input.path, error).lexically_normal();
    input.relative = absolute.lexically_relative(root);
  }
}

namespace {

// The same file however it is named (without throwing on unreadable paths).
std::filesystem::path SameFileKey(const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::path key = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path, error).lexically_normal() : key;
}

}  // namespace

std::string OutputClash(const std::vector<std::filesystem::path>& inputs,
                        const std::vector<std::filesystem::path>& targets) {
  std::map<std::filesystem::path, size_t> written;
  for (size_t i = 0; i < targets.size(); ++i) {
    if (targets[i].empty()) continue;
    const std::filesystem::path key = SameFileKey(targets[i]);
    const auto [it, fresh] = written.emplace(key, i);
    if (!fresh) {
      return inputs[it->second].string() + " and " + inputs[i].string() +
             " would both be written to " + targets[i].string();
    }
  }
  for (const std::filesystem::path& input : inputs) {
    const auto it = written.find(SameFileKey(input));
    if (it != written.end()) {
      return "the result of " + inputs[it->second].string() + " (" + targets[it->second].string() +
             ") would replace the input " + input.string();
    }
  }
  // A hard link has another path: the device and inode of a target that exists tell.
  for (size_t i = 0; i < targets.size(); ++i) {
    if (targets[i].empty()) continue;
    if (const auto input = file_io::InputReplacedBy(targets[i], inputs)) {
      return "the result of " + inputs[i].string() + " (" + targets[i].string() +
             ") would replace the input " + input->string();
    }
  }
  return {};
}

std::string UnifiedDiff(std::string_view before, std::string_view after, const std::string& name) {
  if (before == after) return {};
  const auto a = SplitLines(before);
  const auto b = SplitLines(after);
  std::vector<Step> steps = Script(a, b);
  // diff(1) and git print a change's removed lines before the lines that replace them.
  for (size_t i = 0; i < steps.size();) {
    size_t j = i;
    while (j < steps.size() && steps[j].op != Op::kEqual) ++j;
    std::stable_partition(steps.begin() + static_cast<std::ptrdiff_t>(i),
                          steps.begin() + static_cast<std::ptrdiff_t>(j),
                          [](const Step& step) { return step.op == Op::kDelete; });
    i = j == i ? i + 1 : j;
  }
  constexpr size_t kContext = 3;
  std::string out = "--- a/" + name + "\n+++ b/" + name + "\n";
  size_t k = 0;
  while (k < steps.size()) {
    while (k < steps.size() && steps[k].op == Op::kEqual) ++k;
    if (k == steps.size()) break;
    const size_t start = k >= kContext ? k - kContext : 0;
    // Extend the hunk while changes are closer than 2 * context lines apart.
    size_t end = k;
    size_t equal_run = 0;
    while (end < steps.size() && equal_run <= 2 * kContext) {
      equal_run = steps[end].op == Op::kEqual ? equal_run + 1 : 0;
      ++end;
    }
    end -= std::min(equal_run, end);
    const size_t stop = std::min(steps.size(), end + kContext);
    size_t a_start = 0, b_start = 0, a_count = 0, b_count = 0;
    bool a_set = false, b_set = false;
    std::string body;
    for (size_t s = start; s < stop; ++s) {
      const Step& step = steps[s];
      if (step.op != Op::kInsert) {
        if (!a_set) a_start = step.a, a_set = true;
        ++a_count;
      }
      if (step.op != Op::kDelete) {
        if (!b_set) b_start = step.b, b_set = true;
        ++b_count;
      }
      AppendLine(body, static_cast<char>(step.op), step.op == Op::kInsert ? b[step.b] : a[step.a]);
    }
    // An empty side is numbered by the line before it, as diff(1) does.
    auto position = [](bool set, size_t first, size_t count, size_t fallback) {
      return std::to_string(set ? first + 1 : fallback) + "," + std::to_string(count);
    };
    size_t a_fallback = 0, b_fallback = 0;
    for (size_t s = 0; s < start; ++s) {
      if (steps[s].op != Op::kInsert) a_fallback = steps[s].a + 1;
      if (steps[s].op != Op::kDelete) b_fallback = steps[s].b + 1;
    }
    out += "@@ -" + position(a_set, a_start, a_count, a_fallback) + " +" +
           position(b_set, b_start, b_count, b_fallback) + " @@\n" + body;
    k = stop;
  }
  return out;
}

std::string OutputReplacesInput(std::string_view option, const std::filesystem::path& output,
                                std::span<const std::filesystem::path> inputs) {
  const std::optional<std::filesystem::path> input = file_io::InputReplacedBy(output, inputs);
  if (!input) return "";
  return std::string(option) + " " + output.string() + " is the input " + input->string() +
         ": writing would replace it; nothing was written";
}

std::string WriteOutput(const std::filesystem::path& target, std::string_view text) {
  std::error_code error;  // a directory that cannot be made fails the write, which says why
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), error);
  return file_io::WriteFileAtomically(target, text);
}

}  // namespace shaderport::driver
