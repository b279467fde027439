// A Sound pass: mainSound returns the stereo sample at a time.
vec2 mainSound(int samp, float time) {
    return vec2(sin(6.2831 * 440.0 * time) * exp(-3.0 * time));
}
