#version 300 es
// origin: seeds/004_44ca9435b1f2b4ba.txt, shader listing 9 of 9 (WebGL1 deferred SSAO demo)
/// <summary>
/// Fragment shader to modify brightness, contrast, and gamma of an image.
/// </summary>
#ifdef GL_ES
precision highp float;
#endif
/// <summary>
/// Uniform variables.
/// <summary>
uniform float Brightness; // 0 is the centre. < 0 = darken, > 1 = brighten
uniform float Contrast; // 1 is the centre. < 1 = lower contrast, > 1 is raise contrast
uniform float InvGamma; // Inverse gamma correction applied to the pixel
uniform sampler2D Sample0; // Colour texture to modify
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
// Get the sample
vec4 colour = texture(Sample0, vUv);
// Adjust the brightness
colour.xyz = colour.xyz + Brightness;
// Adjust the contrast
colour.xyz = (colour.xyz - vec3(0.5)) * Contrast + vec3(0.5);
// Clamp result
colour.xyz = clamp(colour.xyz, 0.0, 1.0);
// Apply gamma correction, except for the alpha channel
colour.xyz = pow(colour.xyz, vec3(InvGamma));
// Set fragment
fragColor = colour;
}
