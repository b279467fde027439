// The shaders render draws with when the user gives none for a stage; generated
// pages (driver/project) draw with the same texts so that their pictures compare.
#pragma once

namespace shaderport::render {

// A full-screen triangle from gl_VertexID: no attributes.
inline constexpr const char* kFullScreenVertexShader =
    "#version 300 es\n"
    "void main() {\n"
    "  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - "
    "1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

// Shades by depth, so that a vertex shader's geometry is visible.
inline constexpr const char* kFlatFragmentShader =
    "#version 300 es\n"
    "precision highp float;\n"
    "out vec4 shaderport_color;\n"
    "void main() {\n"
    "  shaderport_color = vec4(vec3(0.9 - 0.8 * gl_FragCoord.z), 1.0);\n"
    "}\n";

}  // namespace shaderport::render
