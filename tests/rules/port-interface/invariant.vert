invariant varying highp vec4 v;
attribute vec4 p;
void main() {
  v = p;
  gl_Position = p;
}
