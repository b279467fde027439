#version 300 es
precision highp float;
// An int expression passed to a macro whose body puts it beside a float: the
// written range is the whole macro use, and wrapping that use in float(...)
// left the int expression inside as it was, so every round wrapped it again.
int twice(int a) { return 2 * a; }
#define SHIFTED(a) (a - 0.5)
out vec4 color;
void main() {
  int i = 3;
  color = vec4(SHIFTED(twice(i)));
}
