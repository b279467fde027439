// Keeps corpus/MANIFEST true: every file it lists exists, and glslang gives each file the
// verdict the `expect` column states (see docs/corpus.md for the columns).
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace shaderport {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpusDir = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";

struct ManifestRow {
  std::string path, origin, dialect, stage, expect;
};

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, '\t')) fields.push_back(field);
  return fields;
}

std::vector<ManifestRow> ReadManifest() {
  std::vector<ManifestRow> rows;
  std::istringstream in(ReadText(kCorpusDir / "MANIFEST"));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitTabs(line);
    if (f.size() != 5) {
      ADD_FAILURE() << "MANIFEST row without 5 fields: " << line;
      continue;
    }
    rows.push_back({f[0], f[1], f[2], f[3], f[4]});
  }
  return rows;
}

// shadertoy.com's WebGL2 page header (peers-and-users.md §1c), reduced to what these files
// use. `#line 1 0` makes glslang report the corpus file's own line numbers.
constexpr const char* kShaderToyHeader =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
    "#define HW_PERFORMANCE 1\n"
    "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iChannelTime[4];\n"
    "uniform vec4 iMouse;\nuniform vec4 iDate;\nuniform float iSampleRate;\n"
    "uniform vec3 iChannelResolution[4];\nuniform int iFrame;\nuniform float iTimeDelta;\n"
    "uniform float iFrameRate;\nuniform sampler2D iChannel0;\nuniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\nuniform sampler2D iChannel3;\n"
    "void mainImage(out vec4 c, in vec2 f);\n#line 1 0\n";
constexpr const char* kShaderToyFooter =
    "\nout vec4 shadertoy_out_color;\n"
    "void main() {\n  vec4 color = vec4(1e20);\n  mainImage(color, gl_FragCoord.xy);\n"
    "  shadertoy_out_color = vec4(color.xyz, 1.0);\n}\n";
// The raymarching blog's page supplies `uv` and `time` and reads `color`.
constexpr const char* kHarnessHeader =
    "#version 300 es\nprecision highp float;\nin vec2 uv;\nuniform float time;\n"
    "out vec4 color;\n#line 1 0\n";

std::string CompilableText(const ManifestRow& row, const std::string& text) {
  if (row.dialect == "shadertoy") return kShaderToyHeader + text + kShaderToyFooter;
  if (row.dialect == "raymarch-harness") return kHarnessHeader + text;
  return text;  // webgl1 / webgl2 files are whole shaders
}

struct Verdict {
  bool ok = false;
  std::string log;
};

Verdict Compile(const std::string& text, EShLanguage stage) {
  glslang::InitializeProcess();
  glslang::TShader shader(stage);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  Verdict verdict;
  verdict.ok = shader.parse(GetDefaultResources(), 100, false, EShMsgCascadingErrors);
  verdict.log = shader.getInfoLog();
  if (verdict.ok) {
    glslang::TProgram program;
    program.addShader(&shader);
    verdict.ok = program.link(EShMsgDefault);
    verdict.log += program.getInfoLog();
  }
  return verdict;
}

// Line numbers of glslang's "ERROR: 0:<line>:" messages, in order.
std::vector<int> ErrorLines(const std::string& log) {
  static const std::regex kError(R"(ERROR: 0:(\d+):)");
  std::vector<int> lines;
  for (std::sregex_iterator it(log.begin(), log.end(), kError), end; it != end; ++it) {
    lines.push_back(std::stoi((*it)[1]));
  }
  return lines;
}

// "error: line 5: ..." or "seed-error: line 30: ..." -> 5 / 30; 0 if no line is given.
int ExpectedLine(const std::string& expect) {
  static const std::regex kLine(R"(^(?:seed-)?error: line (\d+):)");
  std::smatch match;
  return std::regex_search(expect, match, kLine) ? std::stoi(match[1]) : 0;
}

TEST(CorpusManifest, ListsEveryCorpusFileExactlyOnce) {
  std::set<std::string> on_disk;
  for (const auto& entry : fs::recursive_directory_iterator(kCorpusDir)) {
    if (!entry.is_regular_file()) continue;
    const std::string rel = fs::relative(entry.path(), kCorpusDir).generic_string();
    if (rel != "MANIFEST") on_disk.insert(rel);
  }
  std::set<std::string> listed;
  for (const ManifestRow& row : ReadManifest()) {
    EXPECT_TRUE(listed.insert(row.path).second) << "listed twice: " << row.path;
  }
  EXPECT_EQ(listed, on_disk);
  EXPECT_GE(listed.size(), 40u);
}

TEST(CorpusManifest, ColumnsUseTheDocumentedValues) {
  const std::set<std::string> dialects = {"shadertoy", "webgl1", "webgl2", "raymarch-harness"};
  for (const ManifestRow& row : ReadManifest()) {
    SCOPED_TRACE(row.path);
    EXPECT_TRUE(dialects.count(row.dialect)) << row.dialect;
    EXPECT_TRUE(row.stage == "fragment" || row.stage == "vertex") << row.stage;
    EXPECT_FALSE(row.origin.empty());
    const std::string ext = fs::path(row.path).extension().string();
    if (ext == ".vert") {
      EXPECT_EQ(row.stage, "vertex");
    } else if (ext == ".frag") {
      EXPECT_EQ(row.stage, "fragment");
    } else {
      EXPECT_EQ(ext, ".glsl");
      EXPECT_TRUE(row.dialect == "shadertoy" || row.dialect == "raymarch-harness");
    }
    const bool known = row.expect == "compiles" || row.expect.rfind("error: ", 0) == 0 ||
                       row.expect.rfind("seed-error: ", 0) == 0;
    EXPECT_TRUE(known) << row.expect;
  }
}

TEST(CorpusManifest, EveryFileNamesItsOriginInALeadingComment) {
  for (const ManifestRow& row : ReadManifest()) {
    std::istringstream in(ReadText(kCorpusDir / row.path));
    std::string line;
    std::getline(in, line);
    if (line.rfind("#version", 0) == 0) std::getline(in, line);  // #version must stay first
    EXPECT_EQ(line.rfind("//", 0), 0u) << row.path << ": " << line;
  }
}

// Files cut from a seed keep its text byte for byte, apart from the added origin comment. Files
// assembled from several snippets (AO variants, the Steps 1-5 assembly) may only add the changed
// call of the variant; every other line must be a line of the seed.
TEST(CorpusManifest, SeedFilesKeepTheSeedText) {
  const fs::path seeds = fs::path(SHADERPORT_SHARED_DIR) / "seeds";
  if (!fs::exists(seeds)) GTEST_SKIP() << "no seeds at " << seeds;
  int checked = 0;
  for (const ManifestRow& row : ReadManifest()) {
    if (row.origin.rfind("seeds/", 0) != 0) continue;
    SCOPED_TRACE(row.path);
    const std::string seed_name = row.origin.substr(0, row.origin.find(' '));
    const std::string seed = ReadText(seeds / fs::path(seed_name).filename());
    ASSERT_FALSE(seed.empty()) << seed_name;
    std::string body = ReadText(kCorpusDir / row.path);
    if (body.rfind("// origin: ", 0) == 0) body.erase(0, body.find('\n') + 1);
    while (!body.empty() && body.back() == '\n') body.pop_back();
    ++checked;
    const bool assembled = row.path.rfind("ao/variant-", 0) == 0 || row.path == "ao/steps-1-5.glsl";
    if (!assembled) {
      EXPECT_NE(seed.find(body), std::string::npos) << "text differs from " << seed_name;
      continue;
    }
    std::set<std::string> seed_lines;
    std::istringstream seed_in(seed);
    for (std::string line; std::getline(seed_in, line);) seed_lines.insert(line);
    std::istringstream body_in(body);
    for (std::string line; std::getline(body_in, line);) {
      if (line.empty() || line.find("float ao = calcAO") != std::string::npos) continue;
      EXPECT_TRUE(seed_lines.count(line)) << "line not in " << seed_name << ": " << line;
    }
  }
  EXPECT_GE(checked, 20);
}

TEST(CorpusManifest, GlslangVerdictMatchesExpectColumn) {
  int compiled = 0;
  int failed = 0;
  for (const ManifestRow& row : ReadManifest()) {
    SCOPED_TRACE(row.path + " [" + row.expect + "]");
    const std::string text = ReadText(kCorpusDir / row.path);
    EXPECT_FALSE(text.empty());
    const Verdict verdict =
        Compile(CompilableText(row, text), row.stage == "vertex" ? EShLangVertex : EShLangFragment);
    if (row.expect == "compiles") {
      EXPECT_TRUE(verdict.ok) << verdict.log;
      compiled += verdict.ok;
      continue;
    }
    EXPECT_FALSE(verdict.ok);
    failed += !verdict.ok;
    const std::vector<int> lines = ErrorLines(verdict.log);
    const int expected_line = ExpectedLine(row.expect);
    EXPECT_FALSE(lines.empty()) << verdict.log;
    if (lines.empty() || expected_line == 0) continue;
    EXPECT_EQ(lines.front(), expected_line) << verdict.log;
    // A strict-typing case holds exactly one mistake: every error sits on its line.
    if (row.expect.rfind("error: ", 0) == 0) {
      for (int line : lines) EXPECT_EQ(line, expected_line) << verdict.log;
    }
  }
  EXPECT_GT(compiled, 0);
  EXPECT_GT(failed, 0);
}

}  // namespace
}  // namespace shaderport
