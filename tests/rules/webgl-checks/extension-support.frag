#extension GL_NV_shader_noperspective_interpolation : require
precision mediump float;
void main() { gl_FragColor = vec4(1.0); }
