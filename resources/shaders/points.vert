#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in float aLayer;  // 0 single, 1 inner, 2 outer
uniform mat4 uMVP;
uniform float uSize;     // [px]
uniform int uGrabbed;    // index of the grabbed particle, -1: none
out vec3 vColor;
void main() {
    gl_Position = uMVP * vec4(aPos, 1.0);
    bool grabbed = gl_VertexID == uGrabbed;
    gl_PointSize = grabbed ? uSize * 1.9 : uSize;
    if (grabbed) vColor = vec3(1.0, 0.85, 0.1);
    else if (aLayer < 0.5) vColor = vec3(0.2, 0.2, 0.25);
    else if (aLayer < 1.5) vColor = vec3(0.15, 0.35, 0.85);
    else vColor = vec3(0.9, 0.45, 0.1);
}
