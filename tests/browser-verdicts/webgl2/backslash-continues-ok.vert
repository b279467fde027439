#version 300 es
in vec4 vPosition;
void main()
{
    gl_Position = vPosition;
}
float sp_y = 1.0; \
