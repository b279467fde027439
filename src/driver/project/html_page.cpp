#include "driver/project/html_page.h"

#include <nlohmann/json.hpp>

#include "driver/html_report/html_report.h"
#include "driver/project/page_uniforms.h"
#include "driver/project/port_project.h"

namespace shaderport::driver::project {
namespace {

std::string_view InputKindName(PageInputKind kind) {
  switch (kind) {
    case PageInputKind::kNone:
      return "none";
    case PageInputKind::kBuffer:
      return "buffer";
    case PageInputKind::kCubeBuffer:
      return "cubebuffer";
    case PageInputKind::kTexture:
      return "texture";
    case PageInputKind::kCubemap:
      return "cubemap";
    case PageInputKind::kVolume:
      return "volume";
    case PageInputKind::kKeyboard:
      return "keyboard";
    case PageInputKind::kVideo:
      return "video";
    case PageInputKind::kAudio:
      return "audio";
  }
  return "none";
}

// JSON that is also safe as the text of a <script> element and inside HTML: the
// characters that could open markup or end the element, and the two line
// separators old JavaScript parsers reject, become \u escapes (only ever inside
// strings, where JSON.parse turns them back).
std::string ScriptSafeJson(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size() + text.size() / 16);
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else if (c == '\xe2' && i + 2 < text.size() && text[i + 1] == '\x80' &&
               (text[i + 2] == '\xa8' || text[i + 2] == '\xa9')) {
      out += text[i + 2] == '\xa8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

std::string_view PageFile(std::string_view name) {
  for (const page_files::EmbeddedTextFile& file : page_files::EmbeddedPageFiles()) {
    if (file.name == name) return file.text;
  }
  return {};
}

// The title text, UTF-8 made valid (the JSON dump replaces bad bytes the same way).
std::string ValidText(const std::string& text) {
  const std::string quoted =
      nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted).get<std::string>();
}

nlohmann::json RunsJson(const std::vector<PageLineRun>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const PageLineRun& run : runs)
    out.push_back({run.ported_first, run.count, run.origin, run.user_first});
  return out;
}

PageInputKind InputKindOf(ChannelSource source) {
  switch (source) {
    case ChannelSource::kNone:
      return PageInputKind::kNone;
    case ChannelSource::kBuffer:
      return PageInputKind::kBuffer;
    case ChannelSource::kCubeBuffer:
      return PageInputKind::kCubeBuffer;
    case ChannelSource::kTexture:
      return PageInputKind::kTexture;
    case ChannelSource::kCubemap:
      return PageInputKind::kCubemap;
    case ChannelSource::kVolume:
      return PageInputKind::kVolume;
    case ChannelSource::kKeyboard:
      return PageInputKind::kKeyboard;
    case ChannelSource::kVideo:
      return PageInputKind::kVideo;
    case ChannelSource::kAudio:
      return PageInputKind::kAudio;
  }
  return PageInputKind::kNone;
}

// The tab a user line came from, by its source file.
std::string TabOf(const PortedProject& ported, const SourceFile* file) {
  if (file == nullptr) return {};
  for (const PassSource& source : ported.sources.passes) {
    if (source.file == file && source.pass != nullptr) return source.pass->name;
  }
  return file->Name();
}

// "Buffer A:3: message" for each error the port left on a pass without text.
std::string PortErrors(const PortedProject& ported, const PortedPass& pass) {
  std::string out;
  for (const Diagnostic& d : pass.result.diagnostics) {
    if (d.severity != Severity::kError) continue;
    std::string where = pass.pass != nullptr ? pass.pass->name : std::string("pass");
    for (const PassSource& source : ported.sources.passes) {
      if (source.file == nullptr || source.file->Id() != d.range.file) continue;
      where = (source.pass != nullptr ? source.pass->name : source.file->Name()) + ":" +
              std::to_string(source.file->LocationOf(d.range.begin).line);
    }
    out += where + ": " + d.message + " [" + d.rule_id + "]\n";
  }
  return out.empty() ? "the port produced no shader text" : out;
}

}  // namespace

PageProject PageFromPorted(const PortedProject& ported) {
  PageProject page;
  if (ported.project != nullptr) {
    page.name = ported.project->name;
    page.id = ported.project->id;
    page.author = ported.project->author;
  }
  for (const PortedPass& pass : ported.passes) {
    if (pass.pass == nullptr || pass.pass->kind == model::PassKind::kCommon) continue;
    PagePass out;
    out.tab_name = pass.pass->name;
    out.kind = pass.pass->kind;
    out.output_buffer = pass.pass->output_buffer;
    for (const ChannelBinding& binding : pass.pass->inputs) {
      out.inputs.push_back({binding.channel, InputKindOf(binding.source), binding.buffer,
                            binding.sampler.filter, binding.sampler.wrap, binding.sampler.vflip});
    }
    if (!pass.result.read_failed) out.fragment_shader = pass.result.text;
    if (out.fragment_shader.empty()) out.port_errors = PortErrors(ported, pass);
    std::vector<LineOrigin> origins;
    origins.reserve(pass.line_origins.size());
    for (const UserLine& line : pass.line_origins)
      origins.push_back({TabOf(ported, line.file), line.line});
    out.lines = LineRunsFromOrigins(origins);
    page.passes.push_back(std::move(out));
  }
  return page;
}

std::vector<PageLineRun> LineRunsFromOrigins(const std::vector<LineOrigin>& lines) {
  std::vector<PageLineRun> runs;
  for (size_t i = 0; i < lines.size(); ++i) {
    const LineOrigin& line = lines[i];
    if (line.origin.empty() || line.line == 0) continue;
    const auto ported = static_cast<uint32_t>(i + 1);
    if (!runs.empty()) {
      PageLineRun& last = runs.back();
      if (last.origin == line.origin && last.ported_first + last.count == ported &&
          last.user_first + last.count == line.line) {
        ++last.count;
        continue;
      }
    }
    runs.push_back({ported, 1, line.origin, line.line});
  }
  return runs;
}

std::string PageProjectJson(const PageProject& project, const PageOptions& options) {
  nlohmann::json passes = nlohmann::json::array();
  for (const PagePass& pass : project.passes) {
    nlohmann::json inputs = nlohmann::json::array();
    for (const PageInput& input : pass.inputs) {
      inputs.push_back({{"channel", input.channel},
                        {"kind", InputKindName(input.kind)},
                        {"buffer", input.buffer},
                        {"filter", input.filter},
                        {"wrap", input.wrap},
                        {"vflip", input.vflip}});
    }
    nlohmann::json lines = RunsJson(pass.lines);
    passes.push_back({{"name", pass.tab_name},
                      {"kind", model::PassKindName(pass.kind)},
                      {"output", pass.output_buffer},
                      {"inputs", std::move(inputs)},
                      {"code", pass.fragment_shader},
                      {"lines", std::move(lines)},
                      {"portErrors", pass.port_errors},
                      {"vertex", pass.vertex_shader},
                      {"vertexLines", RunsJson(pass.vertex_lines)},
                      {"mesh", pass.mesh}});
  }
  const nlohmann::json page = {{"name", project.name},
                               {"id", project.id},
                               {"author", project.author},
                               {"cubeSize", options.cube_size},
                               {"passes", std::move(passes)}};
  return ScriptSafeJson(page);
}

std::string BuildProjectPage(const PageProject& project, const PageOptions& options) {
  const std::string title =
      HtmlEscape(ValidText(project.name.empty() ? "ShaderToy project" : project.name));
  std::string page;
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  // Nothing may be fetched: the page is one file, offline.
  page +=
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
      "script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:\">\n";
  page += "<title>" + title + "</title>\n<style>\n";
  page += PageFile("page.css");
  page += "</style>\n</head>\n<body>\n";
  page += "<header><h1 id=\"sp-title\">" + title + "</h1>";
  page += "<span id=\"sp-status\"></span></header>\n";
  page += "<div id=\"sp-stage\"><canvas id=\"sp-canvas\" tabindex=\"0\"></canvas>";
  page +=
      "<p id=\"sp-fallback\" hidden>This page needs WebGL2, which this browser does not "
      "offer.</p></div>\n";
  page +=
      "<nav id=\"sp-controls\"><button id=\"sp-pause\" type=\"button\">Pause</button> "
      "<button id=\"sp-restart\" type=\"button\">Restart</button> "
      "<span id=\"sp-clock\"></span></nav>\n";
  page += "<section id=\"sp-errors\" hidden><h2>Compile errors</h2></section>\n";
  page += "<section id=\"sp-channels\"></section>\n";
  // Test hooks (docs/html-pages.md): state, log and the last frame's pixels.
  page += "<div id=\"sp-state\" data-state=\"loading\" hidden></div>\n";
  page += "<pre id=\"sp-log\" hidden></pre>\n<pre id=\"sp-pixels\" hidden></pre>\n";
  page += "<script type=\"application/json\" id=\"sp-project\">";
  page += PageProjectJson(project, options);
  page += "</script>\n<script>\n";
  page += PageFile("textures.js");    // spResources(), used by the runtime
  page += PageFile("sound.js");       // spSound()
  page += ShaderToyUniformsScript();  // spSiteUniforms, spEntryPointUniforms
  page += PageFile("runtime.js");
  page += "</script>\n</body>\n</html>\n";
  return page;
}

std::vector<PageLineRun> ComposedLineRuns(uint32_t header_lines, uint32_t common_lines,
                                          uint32_t pass_lines, const std::string& pass_tab) {
  std::vector<PageLineRun> runs;
  uint32_t next = header_lines + 1;
  if (common_lines > 0) {
    runs.push_back({next, common_lines, "Common", 1});
    next += common_lines;
  }
  if (pass_lines > 0) runs.push_back({next, pass_lines, pass_tab, 1});
  return runs;
}

}  // namespace shaderport::driver::project
