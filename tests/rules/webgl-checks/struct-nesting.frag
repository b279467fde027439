precision mediump float;
struct A { float x; };
struct B { A a; };
struct C { B b; };
struct D { C c; };
struct E { D d; };
void main() { E e; e.d.c.b.a.x = 1.0; gl_FragColor = vec4(e.d.c.b.a.x); }
