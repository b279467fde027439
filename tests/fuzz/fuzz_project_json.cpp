// libFuzzer target for the ShaderToy project reader (check, fix, port and report of
// .json/.jsonl documents: driver/project/json_project_reader.h) and the in-place
// rewrite of code strings that `fix -i` does. Properties:
//  - every problem offset lies in the document;
//  - each pass's code maps byte for byte into the document: a byte that is not from
//    an escape is the document byte at its offset;
//  - rewriting every code string with its own text (an identity map) gives the
//    document back unchanged, byte for byte;
//  - rewriting with new text reads back as that text, and the rest of the document
//    reads back the same.
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include "driver/project/json_code_rewrite.h"
#include "driver/project/json_project_reader.h"
#include "fuzz_check.h"
#include "json_custom_mutator.h"

namespace {

using namespace shaderport;
using namespace shaderport::driver::project;

void Require(bool ok, const char* what) { fuzz::Check(ok, "fuzz_project_json", what); }

void CheckDocument(const std::string& text, const ProjectDocument& read) {
  for (const ProjectProblem& problem : read.problems)
    Require(problem.offset <= text.size(), "problem offset in the document");
  std::vector<CodeReplacement> identity;
  std::vector<SourceMap> maps;
  size_t pass_count = 0;
  for (const ShaderToyProject& project : read.projects) pass_count += project.passes.size();
  maps.reserve(pass_count);
  for (const ShaderToyProject& project : read.projects) {
    for (const ProjectPass& pass : project.passes) {
      const auto& offsets = pass.origin.document_offsets;
      Require(offsets.size() == pass.code.size() + 1, "one offset per code byte, and the end");
      for (size_t i = 0; i < pass.code.size(); ++i) {
        Require(offsets[i] < text.size(), "offset in the document");
        if (text[offsets[i]] != '\\') Require(text[offsets[i]] == pass.code[i], "byte maps");
      }
      Require(pass.origin.literal_begin < pass.origin.literal_end &&
                  pass.origin.literal_end <= text.size(),
              "literal in the document");
      maps.push_back(SourceMap::Identity(static_cast<uint32_t>(pass.code.size())));
      identity.push_back({&pass, pass.code, &maps.back()});
    }
  }
  if (identity.empty()) return;
  Require(RewriteCodeStrings(text, identity) == text, "identity rewrite keeps every byte");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const ProjectDocument read = ReadShaderToyJson(text);
  CheckDocument(text, read);
  CheckDocument(text, ReadShaderToyJsonLines(text));
  // New code for the first pass: it reads back, the other passes stay as they were.
  if (read.problems.empty() && !read.projects.empty() && !read.projects[0].passes.empty()) {
    const ProjectPass& first = read.projects[0].passes[0];
    const std::string code = "vec3 v = vec3(\"\\\n\t\x01é\");" + first.code;
    SourceMap map;
    map.Append(
        {0, static_cast<uint32_t>(code.size()), 0, static_cast<uint32_t>(first.code.size()), true});
    map.SetSizes(static_cast<uint32_t>(first.code.size()), static_cast<uint32_t>(code.size()));
    const std::string rewritten = RewriteCodeStrings(text, {{&first, code, &map}});
    const ProjectDocument again = ReadShaderToyJson(rewritten);
    Require(again.problems.empty(), "a rewritten document reads without problems");
    Require(again.projects.size() == read.projects.size(), "same projects");
    Require(!again.projects.empty() && !again.projects[0].passes.empty() &&
                again.projects[0].passes[0].code == code,
            "the new code reads back");
    for (size_t p = 0; p < read.projects.size() && p < again.projects.size(); ++p) {
      const auto& before = read.projects[p].passes;
      const auto& after = again.projects[p].passes;
      Require(before.size() == after.size(), "same passes");
      for (size_t i = (p == 0 ? 1 : 0); i < before.size() && i < after.size(); ++i)
        Require(before[i].code == after[i].code, "other passes unchanged");
    }
  }
  return 0;
}
