#version 330 core
// Round, shaded point sprites.
in vec3 vColor;
out vec4 fragColor;
void main() {
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    float shade = 0.55 + 0.45 * sqrt(1.0 - r2);
    vec3 rgb = r2 > 0.72 ? vec3(0.08) : vColor * shade;
    fragColor = vec4(rgb, 1.0);
}
