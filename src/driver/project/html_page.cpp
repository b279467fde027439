#include "driver/project/html_page.h"

#include <nlohmann/json.hpp>

namespace shaderport::driver::project {
namespace {

std::string_view KindName(ShaderToyPass kind) {
  switch (kind) {
    case ShaderToyPass::kImage:
      return "image";
    case ShaderToyPass::kBuffer:
      return "buffer";
    case ShaderToyPass::kCubemap:
      return "cube";
    case ShaderToyPass::kSound:
      return "sound";
    case ShaderToyPass::kCommon:
      return "common";
  }
  return "image";
}

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

std::string EscapeHtml(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
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

}  // namespace

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
    nlohmann::json lines = nlohmann::json::array();
    for (const PageLineRun& run : pass.lines)
      lines.push_back({run.ported_first, run.count, run.origin, run.user_first});
    passes.push_back({{"name", pass.tab_name},
                      {"kind", KindName(pass.kind)},
                      {"output", pass.output_buffer},
                      {"inputs", std::move(inputs)},
                      {"code", pass.fragment_shader},
                      {"lines", std::move(lines)},
                      {"portErrors", pass.port_errors}});
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
      EscapeHtml(ValidText(project.name.empty() ? "ShaderToy project" : project.name));
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
