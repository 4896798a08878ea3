#version 330 core
// Springs and other segments as screen-space quads uWidth pixels wide (core profile has no
// wide lines). In strain mode a spring's colour comes from its strain (L - L0) / L0, with
// L0 read from a buffer texture by primitive index: only positions are uploaded per frame.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 vWorld[];
uniform vec2 uViewport;      // pixels
uniform float uWidth;        // pixels
uniform vec4 uColor;
uniform int uStrainMode;     // 1: colour by strain
uniform samplerBuffer uRest; // rest length per spring of the family being drawn [m]
uniform float uStrainRange;  // strain drawn at full colour
out vec4 gColor;

// Diverging map: blue (compressed) - white (rest) - red (stretched).
vec3 strainColor(float s) {
    vec3 white = vec3(0.95, 0.95, 0.95);
    vec3 blue = vec3(0.15, 0.35, 0.95);
    vec3 red = vec3(0.9, 0.12, 0.1);
    return s < 0.0 ? mix(white, blue, -s) : mix(white, red, s);
}

void main() {
    vec4 c = uColor;
    if (uStrainMode == 1) {
        float L = length(vWorld[1] - vWorld[0]);
        float L0 = texelFetch(uRest, gl_PrimitiveIDIn).r;
        float s = (L - L0) / max(L0, 1e-9);
        c = vec4(strainColor(clamp(s / uStrainRange, -1.0, 1.0)), uColor.a);
    }
    vec4 p0 = gl_in[0].gl_Position;
    vec4 p1 = gl_in[1].gl_Position;
    if (p0.w <= 0.0 || p1.w <= 0.0) return;
    vec2 s0 = p0.xy / p0.w * uViewport * 0.5;
    vec2 s1 = p1.xy / p1.w * uViewport * 0.5;
    vec2 d = s1 - s0;
    float len = length(d);
    d = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 n = vec2(-d.y, d.x) * (0.5 * uWidth) / (uViewport * 0.5);
    gColor = c; gl_Position = vec4(p0.xy + n * p0.w, p0.zw); EmitVertex();
    gColor = c; gl_Position = vec4(p0.xy - n * p0.w, p0.zw); EmitVertex();
    gColor = c; gl_Position = vec4(p1.xy + n * p1.w, p1.zw); EmitVertex();
    gColor = c; gl_Position = vec4(p1.xy - n * p1.w, p1.zw); EmitVertex();
    EndPrimitive();
}
