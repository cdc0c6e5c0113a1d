#version 330 core
in vec3 colour;
uniform int roundPoints;  // 1 = discard outside a disc (joints)
out vec4 fragColour;

void main() {
    if (roundPoints == 1 && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
    fragColour = vec4(colour, 1.0);
}
