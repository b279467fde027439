#include "driver/render_check/varying_feeder.h"

#include <cctype>
#include <vector>

#include "glsl/lex/lexer.h"
#include "source/source_file.h"

namespace shaderport::driver {
namespace {

struct Input {
  std::string type;
  std::string name;
  std::string array;  // "[3]" or ""
  bool flat = false;
};

bool IsPrecision(std::string_view word) {
  return word == "lowp" || word == "mediump" || word == "highp";
}

bool IsInterpolation(std::string_view word) {
  return word == "flat" || word == "smooth" || word == "centroid";
}

// File-scope declarations `[layout(...)] [flat|smooth|centroid] in [precision] T name[N];`.
std::vector<Input> FindInputs(std::string_view text) {
  const SourceFile file(0, "<fragment>", std::string(text));
  const glsl::LexedFile lexed = glsl::Lex(file);
  const auto& tokens = lexed.tokens;
  std::vector<Input> inputs;
  int depth = 0;  // braces and parentheses: `in` parameters are not stage inputs
  for (size_t i = 0; i < tokens.size(); ++i) {
    const glsl::Token& token = tokens[i];
    if (token.punct == glsl::Punct::kLeftBrace || token.punct == glsl::Punct::kLeftParen) ++depth;
    if (token.punct == glsl::Punct::kRightBrace || token.punct == glsl::Punct::kRightParen) {
      --depth;
    }
    if (depth != 0 || token.text != "in") continue;
    if (i + 1 < tokens.size() && tokens[i + 1].punct == glsl::Punct::kLeftParen) continue;
    Input input;
    input.flat = i > 0 && tokens[i - 1].text == "flat";
    size_t j = i + 1;
    while (j < tokens.size() && (IsPrecision(tokens[j].text) || IsInterpolation(tokens[j].text))) {
      ++j;
    }
    if (j + 1 >= tokens.size()) break;
    input.type = std::string(tokens[j].text);
    input.name = std::string(tokens[j + 1].text);
    if (j + 4 < tokens.size() && tokens[j + 2].punct == glsl::Punct::kLeftBracket) {
      input.array = "[" + std::string(tokens[j + 3].text) + "]";
    }
    inputs.push_back(std::move(input));
  }
  return inputs;
}

// A value of `type` that varies smoothly over the screen (p in [0,1]^2): screen
// coordinates for 2D values, a normal facing the viewer for inputs named like
// normals, a point in front of the camera for other positions.
std::string ValueFor(const std::string& type, const std::string& name) {
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (type == "float") return "p.x";
  if (type == "vec2") return "p";
  if (type == "vec3") {
    return lower.find("norm") != std::string::npos ? "normalize(vec3(p * 2.0 - 1.0, 1.0))"
                                                   : "vec3(p * 2.0 - 1.0, -2.0)";
  }
  if (type == "vec4") return "vec4(p * 2.0 - 1.0, -2.0, 1.0)";
  if (type.starts_with("mat")) return type + "(1.0)";
  if (type == "int" || type == "uint") return type + "(0)";
  if (type.starts_with("ivec") || type.starts_with("uvec")) return type + "(0)";
  return type + "(0)";
}

}  // namespace

std::string FeederVertexShader(std::string_view fragment_text) {
  const std::vector<Input> inputs = FindInputs(fragment_text);
  if (inputs.empty()) return "";
  std::string text =
      "#version 300 es\n// Written by shaderport to feed the fragment shader's inputs.\n";
  for (const Input& input : inputs) {
    text += std::string(input.flat ? "flat " : "") + "out highp " + input.type + " " + input.name +
            input.array + ";\n";
  }
  text +=
      "void main() {\n"
      "  // The full-screen triangle (0,0) (2,0) (0,2) in units of the screen.\n"
      "  highp vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
      "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n";
  for (const Input& input : inputs) {
    if (!input.array.empty()) {
      const std::string count = input.array.substr(1, input.array.size() - 2);
      text += "  for (int i = 0; i < " + count + "; ++i) " + input.name +
              "[i] = " + ValueFor(input.type, input.name) + ";\n";
    } else {
      text += "  " + input.name + " = " + ValueFor(input.type, input.name) + ";\n";
    }
  }
  text += "}\n";
  return text;
}

}  // namespace shaderport::driver
