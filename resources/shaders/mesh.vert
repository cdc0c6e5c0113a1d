#version 330 core
// Skinned part mesh: dual quaternion skinning (Kavan et al. 2008, with the
// antipodal fix) or linear blend skinning, on the GPU, from up to four
// influences per vertex.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inBones;
layout(location = 3) in vec4 inWeights;
layout(location = 4) in float inInfluences;  // how many bones weigh the vertex
layout(location = 5) in float inDifference;  // L1 distance to global weights (view 4)

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform int boneCount;               // 0 = rest pose, no skinning
uniform int dualQuaternionSkinning;  // 1 = DQS, 0 = LBS
uniform vec4 boneReal[128];          // rotation part (x, y, z, w)
uniform vec4 boneDual[128];          // translation part
uniform vec4 boneRows[384];          // 3 rows of each bone's affine matrix
uniform float outlinePixels;         // > 0: the selection outline pass (see below)
uniform vec2 viewportPixels;
uniform int weightView;  // 0 off, 1 selected bone, 2 dominant bone, 3 influences, 4 difference
uniform int weightBone;  // the selected bone's index, -1 none

out vec3 viewPosition;
out vec3 viewNormal;
out vec3 weightColour;

// Blender's weight ramp: blue (0), cyan, green (0.5), yellow, red (1).
vec3 weightRamp(float w) {
    vec3 stops[5] = vec3[5](vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 1.0), vec3(0.0, 1.0, 0.0),
                            vec3(1.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0));
    float x = clamp(w, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

// A distinct colour per bone index (golden-angle hues).
vec3 boneColour(int bone) {
    float h = fract(float(bone) * 0.618034);
    vec3 k = clamp(abs(fract(h + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
    return mix(vec3(0.35), k, 0.75);
}

vec3 weightViewColour() {
    if (weightView == 1) {
        float w = 0.0;
        for (int k = 0; k < 4; ++k)
            if (int(inBones[k]) == weightBone) w += inWeights[k];
        // Zero weight has its own colour, as in Blender's "Show Zero Weights".
        return w <= 0.0 ? vec3(0.05, 0.05, 0.25) : weightRamp(w);
    }
    if (weightView == 2) return boneColour(int(inBones.x));
    // Blue: as the global computation; red: 0.25 or more apart (of 2 at most).
    if (weightView == 4) return weightRamp(inDifference / 0.25);
    // 1 blue, 2 green, 3 yellow, 4 orange; more than 4 (cut for glTF): magenta.
    if (inInfluences > 4.5) return vec3(1.0, 0.0, 1.0);
    return weightRamp((clamp(inInfluences, 1.0, 4.0) - 1.0) / 3.0 * 0.85);
}

vec3 rotate(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }

void main() {
    vec3 p = inPosition;
    vec3 n = inNormal;
    if (boneCount > 0) {
        if (dualQuaternionSkinning == 1) {
            vec4 pivot = boneReal[int(inBones.x)];
            vec4 real = vec4(0.0);
            vec4 dual = vec4(0.0);
            for (int k = 0; k < 4; ++k) {
                int b = int(inBones[k]);
                vec4 r = boneReal[b];
                vec4 d = boneDual[b];
                // Antipodal fix: blend in the hemisphere of the dominant bone.
                if (dot(r, pivot) < 0.0) { r = -r; d = -d; }
                real += inWeights[k] * r;
                dual += inWeights[k] * d;
            }
            float len = length(real);
            real /= len;
            dual /= len;
            vec3 t = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
            p = rotate(real, inPosition) + t;
            n = rotate(real, inNormal);
        } else {
            vec3 sp = vec3(0.0);
            vec3 sn = vec3(0.0);
            for (int k = 0; k < 4; ++k) {
                int b = int(inBones[k]);
                mat4 m = transpose(mat4(boneRows[3 * b], boneRows[3 * b + 1], boneRows[3 * b + 2],
                                        vec4(0.0, 0.0, 0.0, 1.0)));
                sp += inWeights[k] * (m * vec4(inPosition, 1.0)).xyz;
                sn += inWeights[k] * (mat3(m) * inNormal);
            }
            p = sp;
            n = sn;
        }
    }
    weightColour = weightView > 0 ? weightViewColour() : vec3(0.0);
    vec4 world = model * vec4(p, 1.0);
    vec4 eye = view * world;
    viewPosition = eye.xyz;
    viewNormal = mat3(view) * mat3(model) * n;
    gl_Position = projection * eye;
    // Selection outline (an inverted hull): the back faces, drawn first,
    // pushed outwards on screen by a fixed number of pixels along the
    // projected normal, so a band of them shows around the silhouette.
    if (outlinePixels > 0.0) {
        vec2 screenNormal = (projection * vec4(viewNormal, 0.0)).xy;
        if (length(screenNormal) > 1e-6)
            gl_Position.xy += normalize(screenNormal) * outlinePixels * 2.0 / viewportPixels *
                              gl_Position.w;
    }
}
