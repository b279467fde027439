// ShaderToy passes come after the site's header: an #extension line is always too late.
#extension GL_OES_standard_derivatives : enable
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(dFdx(fragCoord.x)); }
