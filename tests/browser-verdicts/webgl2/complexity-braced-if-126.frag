#version 300 es
precision highp float;
out vec4 o;
// complexity braced if 126: ANGLE's tree depth after its folds (webgl/expression-complexity).
uniform float u;
const bool T = true;
void main(){
 float y = 0.0; float a = u;
if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {if (u > 0.5) {y = 1.0;}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}
 o = vec4(y);
}
