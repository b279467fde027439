#version 300 es
precision highp float;
out vec4 o;
struct Ray { vec3 origin; float length; };
void main() { Ray r = Ray(vec3(1.0), 2.0); Ray rays[2]; rays[0] = r; o = vec4(r.origin * r.length, rays[0].length + float(rays.length())); }
