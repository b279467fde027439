// Sweeps the real ShaderToy passes of ../shared/corpus-shadertoy/permissive.jsonl
// through the site's own compile (validate/shadertoy_contract.h), `fix` and
// `port`, and compares the result with the committed report
// tests/reports/shadertoy-port.md (SHADERPORT_UPDATE_REPORTS=1 rewrites it).
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "driver/parallel_for.h"
#include "driver/port/port_file.h"
#include "source/source_manager.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Pass {
  size_t shader = 0;  // index into the shader list
  std::string type;   // "image", "buffer", "cube", "sound"
  std::string name;   // the tab's name on the site
  std::string code;
  const std::string* common = nullptr;  // the shader's Common tab, if any
  model::ChannelKinds channels{};
};

struct Shader {
  std::string id, name, author, license;
};

struct Corpus {
  std::vector<Shader> shaders;
  std::vector<Pass> passes;
  std::vector<std::unique_ptr<std::string>> commons;  // stable addresses
};

struct PassOutcome {
  bool site_ok = false;
  bool fix_repaired = false;
  std::string site_error;  // first error as the site compiles it
  bool port_ok = false;    // port output validates as plain ESSL 3.00
  std::string port_error;
  std::vector<std::string> port_rules;  // rule id of each fixed finding
  std::vector<std::string> fix_rules;
};

// Keeps a report cell on one line and out of the table syntax.
std::string Cell(std::string_view text, size_t limit = 120) {
  std::string out;
  for (char c : text) {
    if (out.size() >= limit) {
      out += "…";
      break;
    }
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

Corpus LoadCorpus(const fs::path& path) {
  Corpus corpus;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const json shader = json::parse(line);
    corpus.shaders.push_back({shader.value("id", ""), shader.value("name", ""),
                              shader.value("author", ""), shader.value("license", "")});
    const std::string* common = nullptr;
    for (const json& pass : shader["passes"]) {
      if (pass.value("type", "") == "common") {
        corpus.commons.push_back(std::make_unique<std::string>(pass.value("code", "")));
        common = corpus.commons.back().get();
      }
    }
    for (const json& pass : shader["passes"]) {
      Pass p;
      p.shader = corpus.shaders.size() - 1;
      p.type = pass.value("type", "");
      const std::optional<model::PassKind> kind = model::ParsePassKind(p.type);
      if (!kind || *kind == model::PassKind::kCommon) continue;
      p.name = pass.value("name", "");
      p.code = pass.value("code", "");
      p.common = common;
      for (const json& input : pass.value("inputs", json::array())) {
        const int channel = input.value("channel", -1);
        if (channel >= 0 && channel < 4) {
          p.channels[static_cast<size_t>(channel)] =
              model::ChannelKindFromCtype(input.value("ctype", ""));
        }
      }
      corpus.passes.push_back(std::move(p));
    }
  }
  return corpus;
}

std::string FirstError(const validate::ValidationResult& result) {
  if (result.crashed) return "glslang crashed";
  for (const Diagnostic& d : result.diagnostics) {
    if (d.severity == Severity::kError) return d.rule_id + ": " + d.message;
  }
  return result.compiled ? "does not link" : "does not compile";
}

// Compiles `pass` (and `common`) exactly as the site does.
validate::ValidationResult CompileOnSite(SourceManager& sources, const Pass& pass,
                                         const SourceFile* common, const SourceFile& code) {
  return validate::ValidateWithGlslang(validate::ComposeShaderToyRequest(
      sources, *model::ParsePassKind(pass.type), pass.channels, common, code));
}

PortOptions OptionsFor(const Pass& pass, rule::PortMode mode) {
  PortOptions options;
  options.mode = mode;
  options.dialect = Dialect::kShaderToy;
  options.stage = model::Stage::kFragment;
  for (size_t i = 0; i < 4; ++i) options.channels[i] = pass.channels[i];
  return options;
}

// The first error when `text` is not GLSL ES 3.00 that compiles and links on its own.
std::string ValidateOutput(const std::string& text, SourceManager& sources) {
  const SourceFile& output = sources.Add("ported.frag", text);
  validate::ValidationRequest request;
  request.parts.push_back({output.Name(), output.Text(), output.Id()});
  request.stage = model::Stage::kFragment;
  request.default_version = 100;
  request.link = true;
  const validate::ValidationResult result = validate::ValidateWithGlslang(request);
  if (!result.Accepted(true)) return FirstError(result);
  if (text.rfind("#version 300 es", 0) != 0) return "no #version 300 es on the first line";
  return "";
}

PassOutcome Sweep(const Pass& pass) {
  PassOutcome outcome;
  SourceManager sources;
  // Common is a file of its own (named so that it reads as the Common tab).
  const SourceFile* common =
      pass.common != nullptr ? &sources.Add("common.glsl", *pass.common) : nullptr;
  const SourceFile& code = sources.Add(pass.type + ".glsl", pass.code);

  const validate::ValidationResult site = CompileOnSite(sources, pass, common, code);
  outcome.site_ok = site.Accepted(/*link_requested=*/true);
  if (!outcome.site_ok) {
    outcome.site_error = FirstError(site);
    const PortResult fixed =
        PortSource(code, common, OptionsFor(pass, rule::PortMode::kFix), sources);
    for (const Diagnostic& d : fixed.fixed) outcome.fix_rules.push_back(d.rule_id);
    const SourceFile& fixed_code = sources.Add(pass.type + ".fixed.glsl", fixed.text);
    outcome.fix_repaired = CompileOnSite(sources, pass, common, fixed_code).Accepted(true);
  }

  // `port` gets the pass with its Common prepended, as the site compiles it, so
  // that the output stands alone.
  const std::string whole = pass.common != nullptr ? *pass.common + "\n" + pass.code : pass.code;
  const SourceFile& whole_file = sources.Add(pass.type + ".whole.glsl", whole);
  // Validating the output here first is cheaper than port's own glslang runs;
  // a port that validates is exactly what port with validation makes (it only
  // narrows fixes that add errors), and a failing one is re-run for real.
  PortOptions port_options = OptionsFor(pass, rule::PortMode::kPort);
  port_options.validate = false;
  PortResult ported = PortSource(whole_file, nullptr, port_options, sources);
  std::string error = ValidateOutput(ported.text, sources);
  if (!error.empty()) {
    port_options.validate = true;
    ported = PortSource(whole_file, nullptr, port_options, sources);
    error = ValidateOutput(ported.text, sources);
  }
  for (const Diagnostic& d : ported.fixed) outcome.port_rules.push_back(d.rule_id);
  if (outcome.site_ok) {
    outcome.port_ok = error.empty();
    outcome.port_error = error;
  }
  return outcome;
}

struct RuleCount {
  size_t findings = 0;
  size_t passes = 0;
};

std::map<std::string, RuleCount> CountRules(const std::vector<PassOutcome>& outcomes,
                                            std::vector<std::string> PassOutcome::*rules) {
  std::map<std::string, RuleCount> counts;
  for (const PassOutcome& o : outcomes) {
    std::map<std::string, size_t> mine;
    for (const std::string& id : o.*rules) ++mine[id];
    for (const auto& [id, n] : mine) {
      counts[id].findings += n;
      ++counts[id].passes;
    }
  }
  return counts;
}

void WriteRuleTable(std::ostringstream& out, const std::map<std::string, RuleCount>& counts) {
  out << "| rule | fixed findings | passes |\n|---|---:|---:|\n";
  for (const auto& [id, c] : counts) {
    out << "| `" << id << "` | " << c.findings << " | " << c.passes << " |\n";
  }
  if (counts.empty()) out << "| (none) | 0 | 0 |\n";
}

std::string PassRow(const Corpus& corpus, const Pass& pass, const std::string& error) {
  const Shader& s = corpus.shaders[pass.shader];
  std::string row = "| [" + s.id + "](https://www.shadertoy.com/view/" + s.id + ") | " +
                    Cell(pass.name, 40) + " | " + Cell(s.name, 60) + " | " + Cell(s.author, 40) +
                    " | " + Cell(s.license, 40) + " |";
  if (!error.empty()) row += " " + Cell(error) + " |";
  return row + "\n";
}

std::string MakeReport(const Corpus& corpus, const std::vector<PassOutcome>& outcomes) {
  std::map<std::string, size_t> by_type;
  size_t site_fail = 0, repaired = 0, site_ok = 0, port_fail = 0;
  for (size_t i = 0; i < outcomes.size(); ++i) {
    ++by_type[corpus.passes[i].type];
    if (outcomes[i].site_ok) {
      ++site_ok;
      if (!outcomes[i].port_ok) ++port_fail;
    } else {
      ++site_fail;
      if (outcomes[i].fix_repaired) ++repaired;
    }
  }
  std::ostringstream out;
  out << "# ShaderToy corpus: the site's compile, `fix` and `port`\n\n"
      << "Generated by `tests/unit/driver/port_shadertoy_report_test.cpp` from "
      << "`../shared/corpus-shadertoy/permissive.jsonl` (every image, buffer, cube and sound "
      << "pass, with the shader's Common tab compiled in as the site does). Do not edit: run "
      << "`SHADERPORT_UPDATE_REPORTS=1 driver_tests --gtest_filter='ShaderToyPortReport.*'`.\n\n"
      << "- **site**: glslang on the pass as shadertoy.com compiles it "
      << "(`validate/shadertoy_contract.h`: generated header, Common, pass, generated `main`; "
      << "channel types from the pass's inputs).\n"
      << "- **fix**: `shaderport fix` (the pass stays a ShaderToy pass), compiled again as the "
      << "site does.\n"
      << "- **port**: `shaderport port` of Common + pass; the output must compile and link in "
      << "glslang as plain GLSL ES 3.00 on its own.\n\n";
  out << "## Totals\n\n| | passes |\n|---|---:|\n";
  out << "| passes swept | " << outcomes.size() << " |\n";
  for (const auto& [type, n] : by_type) out << "| — " << type << " | " << n << " |\n";
  out << "| fail as the site compiles them | " << site_fail << " |\n";
  out << "| — repaired by `fix` | " << repaired << " |\n";
  out << "| — still failing after `fix` | " << site_fail - repaired << " |\n";
  out << "| compile on the site | " << site_ok << " |\n";
  out << "| — `port` output validates as ESSL 3.00 | " << site_ok - port_fail << " |\n";
  out << "| — `port` output fails | " << port_fail << " |\n\n";

  out << "## Rules fired by `port` (all passes)\n\n";
  WriteRuleTable(out, CountRules(outcomes, &PassOutcome::port_rules));
  out << "\n## Rules fired by `fix` (passes that fail on the site)\n\n";
  WriteRuleTable(out, CountRules(outcomes, &PassOutcome::fix_rules));

  const std::string header = "| shader | pass | name | author | license |";
  out << "\n## Fail on the site, still failing after `fix`\n\n"
      << header << " first site error |\n|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!outcomes[i].site_ok && !outcomes[i].fix_repaired) {
      out << PassRow(corpus, corpus.passes[i], outcomes[i].site_error);
    }
  }
  out << "\n## Fail on the site, repaired by `fix`\n\n"
      << header << " first site error |\n|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!outcomes[i].site_ok && outcomes[i].fix_repaired) {
      out << PassRow(corpus, corpus.passes[i], outcomes[i].site_error);
    }
  }
  out << "\n## Compile on the site, `port` output fails\n\n"
      << header << " first error in the output |\n|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (outcomes[i].site_ok && !outcomes[i].port_ok) {
      out << PassRow(corpus, corpus.passes[i], outcomes[i].port_error);
    }
  }
  return out.str();
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(ShaderToyPortReport, MatchesCommittedReport) {
  const fs::path corpus_path =
      fs::path(SHADERPORT_SHARED_DIR) / "corpus-shadertoy" / "permissive.jsonl";
  if (!fs::exists(corpus_path)) GTEST_SKIP() << corpus_path << " is missing";
  const Corpus corpus = LoadCorpus(corpus_path);
  ASSERT_GT(corpus.passes.size(), 1000u);

  std::vector<PassOutcome> outcomes(corpus.passes.size());
  ParallelFor(corpus.passes.size(), 2, [&](size_t i) { outcomes[i] = Sweep(corpus.passes[i]); });

  size_t site_ok = 0, port_ok = 0, site_fail = 0, repaired = 0;
  for (const PassOutcome& o : outcomes) {
    site_ok += o.site_ok;
    port_ok += o.site_ok && o.port_ok;
    site_fail += !o.site_ok;
    repaired += !o.site_ok && o.fix_repaired;
  }
  // Most of the corpus runs on the site; nearly all of it must come out of port valid.
  EXPECT_GT(site_ok, corpus.passes.size() * 8 / 10);
  EXPECT_GE(port_ok * 100, site_ok * 95) << port_ok << " of " << site_ok;
  EXPECT_GT(repaired, 0u) << site_fail << " fail on the site";

  const std::string report = MakeReport(corpus, outcomes);
  const fs::path committed = fs::path(SHADERPORT_SOURCE_DIR) / "tests/reports/shadertoy-port.md";
  const char* update = std::getenv("SHADERPORT_UPDATE_REPORTS");
  if (update != nullptr && std::string(update) == "1") {
    fs::create_directories(committed.parent_path());
    std::ofstream(committed, std::ios::binary) << report;
  }
  EXPECT_TRUE(ReadFile(committed) == report)
      << committed << " is stale; regenerate it with SHADERPORT_UPDATE_REPORTS=1 and review it";
}

}  // namespace
}  // namespace shaderport::driver
