// a comment that ends in a backslash \
continues here

// ...and a syntax error of the shader itself, lines below it:
const uint x = 4u;
void main() { gl_Position = vec4(1.0); }
