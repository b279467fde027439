// The ShaderToy site's uniforms are written down once, in rules/dialects/shadertoy.toml.
// The site's header (validate), reflection (toolchain), the values a render feeds
// (render) and the project page's table (driver) all enumerate exactly the harness
// model's list, and no other source in src/ or rules/ spells a list of its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "driver/project/html_page.h"
#include "driver/project/page_uniforms.h"
#include "model/shipped_dialects.h"
#include "render/uniform_values.h"
#include "source/source_file.h"
#include "toolchain/emit.h"
#include "validate/shadertoy_contract.h"

namespace shaderport {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> SiteUniforms() {
  std::vector<std::string> names;
  for (const model::ProvidedVariable* v : model::ShaderToySiteUniforms()) names.push_back(v->name);
  return names;
}

std::vector<std::string> Channels() {
  std::vector<std::string> names;
  for (const model::ProvidedVariable& v : model::ShaderToyDialect().provides) {
    if (v.channel >= 0) names.push_back(v.name);
  }
  return names;
}

std::vector<std::string> EntryPointUniforms(std::string_view function) {
  std::vector<std::string> names;
  if (const model::EntryPoint* entry = model::ShaderToyDialect().FindEntryPoint(function)) {
    for (const model::ProvidedVariable& v : entry->provides) names.push_back(v.name);
  }
  return names;
}

template <typename... Lists>
std::vector<std::string> Concat(Lists... lists) {
  std::vector<std::string> all;
  (all.insert(all.end(), lists.begin(), lists.end()), ...);
  return all;
}

TEST(OneUniformList, TheModelHasTheSiteUniforms) {
  // Guards the tests below against passing on an empty list.
  EXPECT_EQ(SiteUniforms().size(), 10u);
  EXPECT_EQ(Channels(),
            (std::vector<std::string>{"iChannel0", "iChannel1", "iChannel2", "iChannel3"}));
  EXPECT_FALSE(EntryPointUniforms("mainCubemap").empty());
  EXPECT_FALSE(EntryPointUniforms("mainSound").empty());
}

// The names the site's header declares, in order.
std::vector<std::string> Declared(const std::string& header) {
  static const std::regex kUniform(R"(^uniform (?:\w+ )?\w+ (\w+)(?:\[\d+\])?;$)");
  std::vector<std::string> names;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (std::regex_match(line, match, kUniform)) names.push_back(match[1]);
  }
  return names;
}

TEST(OneUniformList, ContractDeclaresTheModelsUniforms) {
  const model::ChannelKinds channels{};
  EXPECT_EQ(Declared(validate::ShaderToyHeader(model::PassKind::kImage, channels)),
            Concat(SiteUniforms(), Channels()));
  EXPECT_EQ(Declared(validate::ShaderToyHeader(model::PassKind::kBuffer, channels)),
            Concat(SiteUniforms(), Channels()));
  EXPECT_EQ(Declared(validate::ShaderToyHeader(model::PassKind::kCube, channels)),
            Concat(SiteUniforms(), Channels(), EntryPointUniforms("mainCubemap")));
  EXPECT_EQ(Declared(validate::ShaderToyHeader(model::PassKind::kSound, channels)),
            Concat(SiteUniforms(), Channels(), EntryPointUniforms("mainSound")));
}

TEST(OneUniformList, ReflectReportsTheModelsUniforms) {
  // A pass that uses every uniform and channel the site declares.
  std::string text = validate::ShaderToyHeader(model::PassKind::kImage, {});
  text += "void main() {\n  vec4 sum = vec4(0.0);\n";
  for (const model::ProvidedVariable* v : model::ShaderToySiteUniforms()) {
    const size_t bracket = v->type.find('[');
    const std::string use = v->name + (bracket != std::string::npos ? "[0]" : "") +
                            (v->type.starts_with("vec") ? ".x" : "");
    text += "  sum += vec4(float(" + use + "));\n";
  }
  for (const std::string& channel : Channels()) {
    text += "  sum += texture(" + channel + ", vec2(0.5));\n";
  }
  text += "  shadertoy_out_color = sum;\n}\n";
  const SourceFile file(0, "all-uniforms.frag", text);
  toolchain::EmitOptions options;
  options.kind = toolchain::EmitKind::kReflect;
  options.shadertoy = true;
  const toolchain::EmitResult result = toolchain::Emit(file, model::Stage::kFragment, options);
  ASSERT_FALSE(result.output.empty()) << text;
  const nlohmann::json json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json["shadertoy"]["uniformsUsed"].get<std::vector<std::string>>(), SiteUniforms());
  std::vector<std::string> channels;
  for (const auto& channel : json["shadertoy"]["channels"]) {
    channels.push_back(channel["name"]);
    EXPECT_TRUE(channel["used"].get<bool>()) << channel["name"];
  }
  EXPECT_EQ(channels, Channels());
}

TEST(OneUniformList, RenderFeedsExactlyTheModelsUniforms) {
  // Channels are bound as textures; every other uniform needs a value.
  std::set<std::string> expected;
  for (const std::string& name : SiteUniforms()) expected.insert(name);
  for (const model::EntryPoint& entry : model::ShaderToyDialect().entry_points) {
    for (const model::ProvidedVariable& v : entry.provides) expected.insert(v.name);
  }
  std::set<std::string> fed;
  for (std::string_view name : render::FedShaderToyUniforms()) fed.insert(std::string(name));
  EXPECT_EQ(fed, expected) << "rules/dialects/shadertoy.toml and render's values "
                              "(src/render/uniform_values.cpp) must name the same uniforms";
}

TEST(OneUniformList, PageTableIsTheModels) {
  const std::string script = driver::project::ShaderToyUniformsScript();
  static const std::regex kSite(R"(const spSiteUniforms = (.*);)");
  static const std::regex kEntries(R"(const spEntryPointUniforms = (.*);)");
  std::smatch site;
  std::smatch entries;
  ASSERT_TRUE(std::regex_search(script, site, kSite)) << script;
  ASSERT_TRUE(std::regex_search(script, entries, kEntries)) << script;
  EXPECT_EQ(nlohmann::json::parse(site[1].str()).get<std::vector<std::string>>(), SiteUniforms());
  const nlohmann::json per_entry = nlohmann::json::parse(entries[1].str());
  for (const model::EntryPoint& entry : model::ShaderToyDialect().entry_points) {
    EXPECT_EQ(per_entry.at(entry.function).get<std::vector<std::string>>(),
              EntryPointUniforms(entry.function));
  }
}

std::string_view PageFile(std::string_view name) {
  for (const auto& file : driver::project::page_files::EmbeddedPageFiles()) {
    if (file.name == name) return file.text;
  }
  return {};
}

TEST(OneUniformList, PageFeedsExactlyTheSiteUniforms) {
  // runtime.js's kFeeds: one `name: (...) =>` line a uniform.
  const std::string runtime(PageFile("runtime.js"));
  const size_t begin = runtime.find("const kFeeds = {");
  ASSERT_NE(begin, std::string::npos);
  const size_t end = runtime.find("\n  };", begin);
  ASSERT_NE(end, std::string::npos);
  const std::string table = runtime.substr(begin, end - begin);
  static const std::regex kKey(R"(\n\s+(\w+): \()");
  std::set<std::string> fed;
  for (auto it = std::sregex_iterator(table.begin(), table.end(), kKey);
       it != std::sregex_iterator(); ++it) {
    fed.insert((*it)[1]);
  }
  const std::vector<std::string> site = SiteUniforms();
  EXPECT_EQ(fed, std::set<std::string>(site.begin(), site.end()));
}

// Distinct site uniforms a file names inside string literals.
std::set<std::string> NamedInStrings(const std::string& text,
                                     const std::vector<std::string>& names) {
  static const std::regex kLiteral(R"("(?:[^"\\\n]|\\.)*")");
  std::set<std::string> found;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kLiteral);
       it != std::sregex_iterator(); ++it) {
    const std::string literal = it->str();
    for (const std::string& name : names) {
      if (std::regex_search(literal, std::regex("\\b" + name + "\\b"))) found.insert(name);
    }
  }
  return found;
}

TEST(OneUniformList, NoSecondHandWrittenList) {
  const fs::path root(SHADERPORT_SOURCE_DIR);
  const std::vector<std::string> names = SiteUniforms();
  // Render's values are keyed by name; RenderFeedsExactlyTheModelsUniforms holds them
  // to the TOML.
  const std::set<fs::path> keyed = {root / "src/render/uniform_values.cpp"};
  std::vector<std::string> lists;
  for (const char* dir : {"src", "rules"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
      const fs::path& path = entry.path();
      const std::string ext = path.extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h" && ext != ".js")) continue;
      if (keyed.contains(path)) continue;
      std::ifstream in(path, std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      if (NamedInStrings(text, names).size() >= 3) {
        lists.push_back(fs::relative(path, root).string());
      }
    }
  }
  EXPECT_TRUE(lists.empty()) << "these files list the ShaderToy uniforms by hand; read them from "
                                "model/shipped_dialects.h instead: "
                             << ::testing::PrintToString(lists);
}

}  // namespace
}  // namespace shaderport
