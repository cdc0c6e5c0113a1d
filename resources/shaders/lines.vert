#version 330 core
// Coloured lines and points: grid, skeleton overlay, the stroke being drawn.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inColour;

uniform mat4 viewProjection;
uniform float pointSize;

out vec3 colour;

void main() {
    colour = inColour;
    gl_PointSize = pointSize;
    gl_Position = viewProjection * vec4(inPosition, 1.0);
}
