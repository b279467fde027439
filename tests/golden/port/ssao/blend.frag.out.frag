#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 8 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// This fragment shader blends an ambient occlusion map with the rendered scene.
/// </summary>
#ifdef GL_ES
precision highp float;
#endif
/// <summary>
/// Texture samples used by this shader.
/// <summary>
uniform sampler2D Sample0; // Rendered scene texture
uniform sampler2D Sample1; // Ambient occlusion map
/// <summary>
/// Varying variables.
/// <summary>
in vec2 vUv;
/// <summary>
/// Fragment shader entry.
/// <summary>
out highp vec4 fragColor;
void main ()
{
// Get scene colour and ambient occlusion values
vec3 colour = texture(Sample0, vUv).xyz;
float ao = texture(Sample1, vUv).x;
// Blend the two
colour = clamp(colour - ao, 0.0, 1.0);
// Apply gamma correction
fragColor.xyz = pow(colour, vec3(1.0 / 2.2));
fragColor.w = 1.0;
}
