// Common code shared by every pass of this shader.
#define SCALE 2.0

float wave(float x) {
    return sin(x * SCALE) * 0.5 + 0.5;
}

float broken(float x) {
    return x * 2; // int where a float is required
}
