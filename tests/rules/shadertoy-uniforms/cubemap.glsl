// A Cubemap pass gets the site's viewport and corner uniforms too.
void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
    fragColor = vec4(0.5 + 0.5 * rayDir, 1.0);
}
