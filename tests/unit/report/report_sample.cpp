#include "report_sample.h"

#include <string>
#include <string_view>

namespace shaderport::testing {
namespace {

// The byte range of the first `needle` in `file` (at or after `from`).
SourceRange Find(const SourceFile& file, std::string_view needle, uint32_t from = 0) {
  const size_t at = file.Text().find(needle, from);
  const auto begin = static_cast<uint32_t>(at == std::string_view::npos ? 0 : at);
  return {file.Id(), begin, begin + static_cast<uint32_t>(needle.size())};
}

SourceRange EmptyAt(SourceRange range) { return {range.file, range.end, range.end}; }

}  // namespace

ReportSample::ReportSample() {
  const SourceFile& common = sources.Add(
      "shaders/common.glsl", "float hash(vec2 p) {\n  return fract(p.x * 43758.5);\n}\n");
  const SourceFile& image = sources.Add("./shaders/toy, image.frag",
                                        "// Ünïcödé façade: déjà vu 🎨\n"
                                        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                        "\tvec2 uv = fragCoord / iResolution.xy;  // «naïve» 🎨 uv\n"
                                        "\tfloat h = hash(uv)\n"
                                        "\tgl_FragColor = vec4(uv, h, 1.0);\n"
                                        "}\n");
  const SourceFile& vertex = sources.Add("/work/project/web/quad.vert",
                                         "attribute vec2 position;\n"
                                         "void main() {\n"
                                         "  gl_Position = vec4(position, 0.0, 1.0);\n"
                                         "}\n");
  report.sources = &sources;
  options.tool_version = "0.1.0";
  options.base_directory = "/work/project";
  options.information_uri = "https://example.invalid/shaderport";

  FileReport image_report{&image, "shadertoy", "fragment", {}};
  {
    // Spans the multi-byte characters after a tab.
    Diagnostic d;
    d.severity = Severity::kWarning;
    d.rule_id = "sample/unused-variable";
    d.range = Find(image, "«naïve» 🎨");
    d.message = "comment with «quotes», 100% fun: ok";
    image_report.diagnostics.push_back(d);
  }
  {
    // A missing ';': an insertion fix-it shown on its own line under the caret.
    Diagnostic d;
    d.rule_id = "sample/expected-token";
    d.range = EmptyAt(Find(image, "hash(uv)"));
    d.message = "expected ';' after declaration";
    d.fixes.push_back({d.range, ";", FixSafety::kSafe});
    image_report.diagnostics.push_back(d);
  }
  {
    // A call into the Common file: a note points there.
    Diagnostic d;
    d.severity = Severity::kWarning;
    d.rule_id = "sample/implicit-conversion";
    d.range = Find(image, "hash(uv)");
    d.message = "'hash' returns float\nsecond line";
    d.notes.push_back({Find(common, "hash"), "'hash' is declared here"});
    d.notes.push_back({{}, "a note with no location"});
    image_report.diagnostics.push_back(d);
  }
  {
    // A replacement plus an insertion on another line, applied together.
    Diagnostic d;
    d.rule_id = "sample/undeclared-identifier";
    d.range = Find(image, "gl_FragColor");
    d.message = "'gl_FragColor' does not exist in GLSL ES 3.00";
    d.fixes.push_back({d.range, "fragColor", FixSafety::kSafe});
    d.fixes.push_back({EmptyAt(Find(image, "\n")), "\nout vec4 x;", FixSafety::kSuggestion});
    image_report.diagnostics.push_back(d);
  }
  {
    // A range over two lines: underlined to the end of the first.
    Diagnostic d;
    d.severity = Severity::kNote;
    d.rule_id = "sample/long-function";
    d.range = Find(image, "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n\tvec2");
    d.message = "function starts here";
    image_report.diagnostics.push_back(d);
  }

  FileReport vertex_report{&vertex, "webgl1", "vertex", {}};
  {
    Diagnostic d;
    d.rule_id =
        "input/empty";  // in the catalog: SARIF gets its summary and help (the others are not)
    d.range = {};
    d.message = "a diagnostic about the whole file";
    vertex_report.diagnostics.push_back(d);
  }
  {
    Diagnostic d;
    d.severity = Severity::kWarning;
    d.rule_id = "sample/deprecated-attribute";
    d.range = Find(vertex, "attribute");
    d.message = "'attribute' is 'in' in GLSL ES 3.00";
    d.fixes.push_back({d.range, "in", FixSafety::kSafe});
    vertex_report.diagnostics.push_back(d);
  }

  report.files.push_back(std::move(vertex_report));
  report.files.push_back(std::move(image_report));
  report.files.push_back({&common, "shadertoy", "fragment", {}});
  SortReport(report);
}

}  // namespace shaderport::testing
