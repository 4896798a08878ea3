#version 330 core
// Positions only: everything per frame comes from this one buffer.
layout(location = 0) in vec3 aPos;
uniform mat4 uMVP;
out vec3 vWorld;
void main() {
    vWorld = aPos;
    gl_Position = uMVP * vec4(aPos, 1.0);
}
