#version 330 core
// Faces: flat-lit from the screen-space derivatives of the world position, so the face
// normal needs no per-frame normal buffer. Unlit (uLit = 0) for 2D fills and the floor.
in vec3 vWorld;
uniform vec4 uColor;
uniform int uLit;
uniform vec3 uEye;
out vec4 fragColor;
void main() {
    if (uLit == 0) { fragColor = uColor; return; }
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    vec3 v = normalize(uEye - vWorld);
    if (dot(n, v) < 0.0) n = -n;
    vec3 l = normalize(vec3(0.35, 1.0, 0.55));
    float diffuse = max(dot(n, l), 0.0);
    float fill = 0.25 * max(dot(n, v), 0.0);
    vec3 h = normalize(l + v);
    float specular = 0.35 * pow(max(dot(n, h), 0.0), 48.0);
    vec3 rgb = uColor.rgb * (0.28 + 0.6 * diffuse + fill) + vec3(specular);
    fragColor = vec4(rgb, uColor.a);
}
