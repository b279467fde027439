#version 300 es
// An integer literal past 32 bits in a group the preprocessor skips: browsers never
// read it; glslang's scanner rejects it even there ("numeric literal too big").
precision highp float;
out vec4 color;
#define AA 2
void main() {
  color = vec4(1.0);
#if (AA == 3)
  color /= 4294967296;
#elif 0
  color /= 0x100000000;
#endif
}
