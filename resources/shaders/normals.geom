#version 330 core
// One outward normal per triangle, from its centroid, uLength long, drawn as a thin quad.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 vWorld[];
uniform mat4 uMVP;
uniform vec2 uViewport;
uniform float uWidth;
uniform float uLength;  // [m]
uniform vec4 uColor;
out vec4 gColor;

void main() {
    vec3 c = (vWorld[0] + vWorld[1] + vWorld[2]) / 3.0;
    vec3 n = cross(vWorld[1] - vWorld[0], vWorld[2] - vWorld[0]);
    float l = length(n);
    if (l < 1e-12) return;
    vec4 p0 = uMVP * vec4(c, 1.0);
    vec4 p1 = uMVP * vec4(c + n / l * uLength, 1.0);
    if (p0.w <= 0.0 || p1.w <= 0.0) return;
    vec2 s0 = p0.xy / p0.w * uViewport * 0.5;
    vec2 s1 = p1.xy / p1.w * uViewport * 0.5;
    vec2 d = s1 - s0;
    float len = length(d);
    d = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 o = vec2(-d.y, d.x) * (0.5 * uWidth) / (uViewport * 0.5);
    gColor = uColor; gl_Position = vec4(p0.xy + o * p0.w, p0.zw); EmitVertex();
    gColor = uColor; gl_Position = vec4(p0.xy - o * p0.w, p0.zw); EmitVertex();
    gColor = uColor; gl_Position = vec4(p1.xy + o * p1.w, p1.zw); EmitVertex();
    gColor = uColor; gl_Position = vec4(p1.xy - o * p1.w, p1.zw); EmitVertex();
    EndPrimitive();
}
