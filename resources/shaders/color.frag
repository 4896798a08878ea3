#version 330 core
in vec4 gColor;
out vec4 fragColor;
void main() { fragColor = gColor; }
