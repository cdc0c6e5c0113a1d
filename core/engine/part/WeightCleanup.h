// Whole-part weight clean-ups, as Blender's Weights menu has them. Each returns how many vertices
// changed; a vertex already as asked is left bit for bit, and so is every weight of a locked bone
// (the rest of the vertex is rescaled to what the locked bones leave; a vertex with nothing
// unlocked to rescale is left as it is).
#pragma once

#include <set>

#include "part/Part.h"

namespace rigmesh {

// Normalize All: every vertex's weights rescaled to sum to 1 (after paint
// or imports that left them off).
int normalizeAllWeights(Part& part, const std::set<BoneId>& locked = {});
// Clean: unlocked weights below `threshold` dropped, the rest renormalised
// (a vertex never loses its largest unlocked weight).
int cleanWeights(Part& part, double threshold, const std::set<BoneId>& locked = {});
// Limit Total: at most `influences` bones per vertex (the largest kept; a
// vertex with as many locked bones keeps those and its largest unlocked
// one), renormalised; what glTF's four influences need.
int limitWeightInfluences(Part& part, int influences, const std::set<BoneId>& locked = {});

struct SmoothAllOptions {
    double factor = 0.5;  // 0..1: how far a weight moves towards its neighbours' mean per pass
    int iterations = 1;   // passes, 1..100
};
// Smooth All (Blender's Smooth with "All Groups"): every unlocked bone's
// weight moves towards the mean of the vertex's edge neighbours, pass by
// pass (each pass reads the weights the previous one left, Jacobi style),
// then the unlocked weights are rescaled to sum with the locked ones to 1.
int smoothAllWeights(Part& part, const SmoothAllOptions& options,
                     const std::set<BoneId>& locked = {});

// Bone heat over the whole part again (paper 2.4, every vertex tested for
// visibility; Blender's "Assign Automatic from Bones"), keeping locked
// bones: each vertex takes the new weights of its unlocked bones, scaled
// into what its locked ones leave; a vertex whose new weights fall on locked
// bones only keeps its list. Returns how many vertices changed. Throws Error for a part without a
// skeleton.
int recomputeWeights(Part& part, const std::set<BoneId>& locked);

}  // namespace rigmesh
