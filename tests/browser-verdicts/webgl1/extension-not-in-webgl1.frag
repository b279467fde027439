#extension GL_OVR_multiview : require
precision mediump float;
void main() { gl_FragColor = vec4(1.0); }
