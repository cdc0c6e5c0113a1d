#version 330 core
// Soft shading with a headlight: the light sits at the eye.
in vec3 viewPosition;
in vec3 viewNormal;
in vec3 weightColour;

uniform vec3 baseColour;
uniform float highlight;  // 0 = normal, 1 = selected
uniform int flatColour;   // 1: baseColour as is (the selection outline)
uniform int weightView;   // > 0: the vertex's weight colour replaces baseColour
uniform float opacity;    // below 1: a translucent onion-skin ghost

out vec4 fragColour;

void main() {
    if (flatColour == 1) {
        fragColour = vec4(baseColour, 1.0);
        return;
    }
    vec3 n = normalize(viewNormal);
    vec3 toEye = normalize(-viewPosition);
    if (!gl_FrontFacing) n = -n;
    float diffuse = max(dot(n, toEye), 0.0);
    float specular = pow(max(dot(reflect(-toEye, n), toEye), 0.0), 32.0);
    vec3 base = weightView > 0 ? weightColour : baseColour;
    // Weight colours are lit more evenly, so the ramp reads on dark sides too.
    float light = weightView > 0 ? 0.45 + 0.55 * diffuse : 0.25 + 0.75 * diffuse;
    vec3 colour = base * light + vec3(0.12) * specular;
    if (weightView == 0) colour = mix(colour, vec3(1.0, 0.62, 0.2), 0.25 * highlight);
    fragColour = vec4(colour, opacity);
}
