#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in float aLayer;  // 0 single, 1 inner, 2 outer; + 4 (k + 1) for body k of a world
uniform mat4 uMVP;
uniform vec3 uBodyHue[8];  // a world's body hues (ui/plot_series.h bodyColor), cycled
uniform float uSize;     // [px]
uniform int uGrabbed;    // index of the grabbed particle, -1: none
out vec3 vColor;
void main() {
    gl_Position = uMVP * vec4(aPos, 1.0);
    bool grabbed = gl_VertexID == uGrabbed;
    gl_PointSize = grabbed ? uSize * 1.9 : uSize;
    int code = int(aLayer + 0.5);
    int body = code / 4 - 1;
    if (grabbed) vColor = vec3(1.0, 0.85, 0.1);
    else if (body >= 0) vColor = uBodyHue[body - 8 * (body / 8)] * ((code - 4 * (code / 4)) == 1 ? 0.55 : 1.0);
    else if (aLayer < 0.5) vColor = vec3(0.2, 0.2, 0.25);
    else if (aLayer < 1.5) vColor = vec3(0.15, 0.35, 0.85);
    else vColor = vec3(0.9, 0.45, 0.1);
}
