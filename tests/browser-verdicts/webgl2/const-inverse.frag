#version 300 es
precision highp float;
// ANGLE folds inverse, transpose and determinant of constants.
out vec4 o;
const mat3 B = mat3(2.0);
const mat3 I = inverse(B);
const mat2 T = transpose(mat2(1.0, 2.0, 3.0, 4.0));
const float D = determinant(mat2(2.0));
void main() { o = vec4(I[0] + vec3(T[0], D), 1.0); }
