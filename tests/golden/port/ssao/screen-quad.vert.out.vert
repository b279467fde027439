#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 3 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// Vertex shader for rendering a 2D plane on the screen. The plane should be sized
/// from -1.0 to 1.0 in the x and y axis. This shader can be shared amongst multiple
/// post-processing fragment shaders.
/// </summary>
/// <summary>
/// Attributes.
/// <summary>
in vec3 Vertex;
in vec2 Uv;
/// <summary>
/// Varying variables.
/// <summary>
out vec2 vUv;
/// <summary>
/// Vertex shader entry.
/// <summary>
void main ()
{
gl_Position = vec4(Vertex, 1.0);
// Flip y-axis
vUv = Uv;
}
