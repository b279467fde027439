// 1025 bone matrices take 4100 uniform vectors, more than Chromium's 4096 here.
attribute vec4 position;
attribute float boneIndex;
uniform mat4 uBones[1025];
void main() { gl_Position = uBones[int(boneIndex)] * position; }
