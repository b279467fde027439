#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 5 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// This fragment shader outputs vertex data to a floating point texture map
/// </summary>
#ifdef GL_ES
precision highp float;
#endif
/// <summary>
/// Stores the (Far - Near) clip value used for calculating linear depth.
/// <summary>
uniform float LinearDepth;
/// <summary>
/// Varying variables.
/// <summary>
in vec4 vPosition;
/// <summary>
/// Fragment shader entry.
/// </summary>
out highp vec4 fragColor;
void main ()
{
// Calculate and include linear depth
float linearDepth = length(vPosition) / LinearDepth;
fragColor = vec4(vPosition.x, vPosition.y, vPosition.z, linearDepth);
}
