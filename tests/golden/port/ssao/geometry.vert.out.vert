#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 2 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// This vertex shader prepares the geometry for rendering to a floating point texture map.
/// </summary>
/// <summary>
/// Attributes.
/// <summary>
in vec3 Vertex;
in vec3 Normal;
/// <summary>
/// Uniform variables.
/// <summary>
uniform mat4 ProjectionMatrix;
uniform mat4 ViewMatrix;
uniform mat4 ModelMatrix;
uniform vec3 ModelScale;
/// <summary>
/// Varying variables.
/// <summary>
out vec4 vPosition;
out vec3 vNormal;
/// <summary>
/// Vertex shader entry.
/// </summary>
void main ()
{
// Position / vertex data
vPosition = ViewMatrix * ModelMatrix * vec4(Vertex * ModelScale, 1.0);
gl_Position = ProjectionMatrix * vPosition;
// Normal data
vNormal = mat3(ViewMatrix * ModelMatrix) * Normal;
}
