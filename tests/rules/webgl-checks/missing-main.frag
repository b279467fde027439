precision mediump float;
float f() { return 1.0; }
