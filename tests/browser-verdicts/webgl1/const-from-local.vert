attribute vec4 p;
void main() { float y = 1.0; const float x = y; gl_Position = p * x; }
