attribute vec4 p;
void main() { gl_Position = p; }
#if 0
$ @ "
#endif
