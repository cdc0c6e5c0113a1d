// Painting skin weights (issue 14 item 3), as Blender's weight paint and
// Maya's Paint Skin Weights do: a dab raises (Add), lowers (Subtract), sets
// (Replace) or evens out (Smooth) one bone's weight within a radius, with a
// smooth falloff; the vertex's other unlocked bones take up the difference
// so its weights keep summing to 1 (auto-normalise); locked bones never
// change, and a vertex whose other bones are all locked is skipped, never
// divided by zero. X-mirror paints the reflection through the sketch plane
// too (Part::mirror).
#pragma once

#include <set>
#include <vector>

#include "part/Part.h"

namespace rigmesh {

enum class BrushMode { Add, Subtract, Replace, Smooth };

struct WeightDab {
    BoneId bone = 0;
    BrushMode mode = BrushMode::Add;
    Vec3 centre = Vec3::Zero();  // in the part's coordinates
    double radius = 0.1;
    double strength = 0.5;  // 0..1, at the centre
    double value = 1.0;     // Replace: the weight painted towards
    bool mirror = false;
    std::set<BoneId> locked;
};

struct DabResult {
    // The vertices whose weights changed, with their weights before and after.
    std::vector<int> changed;
    WeightsById before, after;
    // Vertices left as they were: every other bone locked, or no other bone
    // to hand the difference to (subtracting from a vertex with one bone).
    int skippedLocked = 0;
};

// Paints one dab into `part` (its weights only). Throws Error for an unknown
// or locked bone, a radius or strength out of range, or a mirror request on
// a part without a mirror map.
DabResult paintWeights(Part& part, const WeightDab& dab);

// Whole-part clean-ups, as Blender's Weights menu has them (issue 14 item
// 3). Each returns how many vertices changed; a vertex already as asked is
// left bit for bit.
// Normalize All: every vertex's weights rescaled to sum to 1 (after paint
// or imports that left them off).
int normalizeAllWeights(Part& part);
// Clean: weights below `threshold` dropped, the rest renormalised (a vertex
// never loses its largest weight).
int cleanWeights(Part& part, double threshold);
// Limit Total: at most `influences` bones per vertex (the largest kept),
// renormalised; what glTF's four influences need.
int limitWeightInfluences(Part& part, int influences);

}  // namespace rigmesh
