// Golfed style: the out parameter is accumulated without ever being set.
void mainImage(out vec4 O, vec2 U) {
    U /= iResolution.xy;
    O += vec4(U, 0.3, 1.0);
    O -= 0.1 * vec4(U.yx, 0.0, 0.0);
}
