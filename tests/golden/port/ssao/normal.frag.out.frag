#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 6 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// This fragment shader outputs normals to a floating point texture map
/// </summary>
#ifdef GL_ES
precision highp float;
#endif
/// <summary>
/// Varying variables.
/// <summary>
in vec3 vNormal;
/// <summary>
/// Fragment shader entry.
/// </summary>
out highp vec4 fragColor;
void main ()
{
vec3 normal = normalize(vNormal);
fragColor = vec4(normal.x, normal.y, normal.z, 0.0);
}
