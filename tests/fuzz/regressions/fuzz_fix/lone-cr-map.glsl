// origin: seeds/000_832ddd5fa6e5b251.txt, "Step 3: Classic Normal-Direction AO (5 Samples)", placed into the "Complete Code Template" in place of calcAO
// SDF Ambient Occlusion — ShaderToy Template
// Synthesized from classic raymarching implementations

#define AO_STEPS 5
#define AO_MAX_DIST 0.12
#define AO_MIN_DIST 0.01
#define AO_DECAY 0.95
#define AO_STRENGTH 3.0
map(p - e.xyy),
        map(p  0.9, 0.7) * dif * sha;
        col += mate * vec3(0.2, 0.3, 0.5) * sky * ao;
        col += mate * vec3(0.3, 0.2, 0.1fragColor =, -;
uniform MaterialSource Material;sampler2D Sample0; // Rendered scene texture
uniform sampler2D Sample1; // Ambient occlusion map
/// <summary>
/// Varying variables.
/// <summary>
varying; // mistake
    (veciform 12.0 -uv = gl_FragCoord.kernel[3]  vec3 1.0)
/// <summary>
/// Varying variables.
/// <summary>
varying; // mistake
    (vec2 vUv;
/// <summary>
/// Fragment shader entry.
ViewMatrix * vWord2 vUv;
/// <summary>pos.y < 0.01) {
            ;
}
