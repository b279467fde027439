precision mediump float;
void entry() { gl_FragColor = vec4(1.0); }
