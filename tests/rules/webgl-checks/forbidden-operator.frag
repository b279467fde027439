precision mediump float;
struct S { float t; };
uniform bool b;
void main() {
  S s1 = S(1.0);
  S s2 = S(2.0);
  S s = b ? s1 : s2;
  S t = +s;
  gl_FragColor = vec4(t.t);
}
