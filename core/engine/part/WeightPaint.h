// Painting skin weights, as Blender's weight paint and
// Maya's Paint Skin Weights do: a dab raises (Add), lowers (Subtract), sets
// (Replace) or evens out (Smooth) one bone's weight within a radius, with a
// chosen falloff; the vertex's other unlocked bones take up the difference
// so its weights keep summing to 1 (auto-normalise). Where no other unlocked
// bone weighs the vertex (a region one bone leads), the weight given up goes
// to the parent bone, else the nearest unlocked bone, as Blender's
// auto-normalise does; locked bones never change, and a vertex whose other
// bones are all locked is skipped, never divided by zero. X-mirror works
// vertex by vertex, as Blender's does: each vertex the dab changes passes
// the same change on to its partner across the part's left-right mirror
// plane (rig/MirrorSymmetry, rig/VertexMirror), on the bone's mirror image
// (the left arm's bone for the right arm's), so the two sides stay equal
// even where the surface is not exactly symmetric; a vertex without a
// partner is painted on its own side only, and counted. "Front faces only"
// leaves out vertices whose normal turns away from the viewer, so a brush
// never paints through a limb onto its far side (Blender's option of the
// same name); their partners follow the vertices painted.
#pragma once

#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "part/Part.h"
#include "part/WeightLists.h"
#include "rig/MirrorSymmetry.h"

namespace rigmesh {

enum class BrushMode { Add, Subtract, Replace, Smooth };

// How a dab's strength falls off from its centre (d = distance / radius):
// Smooth (1 - d^2)^2, Linear 1 - d, Sharp (1 - d)^2, Constant 1.
enum class BrushFalloff { Smooth, Linear, Sharp, Constant };

struct WeightDab {
    BoneId bone = 0;
    BrushMode mode = BrushMode::Add;
    BrushFalloff falloff = BrushFalloff::Smooth;
    Vec3 centre = Vec3::Zero();  // in the part's coordinates
    double radius = 0.1;
    double strength = 0.5;  // 0..1, at the centre
    double value = 1.0;     // Replace: the weight painted towards
    bool mirror = false;
    // Front faces only: the direction towards the viewer (any length > 0),
    // in the same coordinates as `centre`; vertices whose rest normal points
    // away from it are not painted. None: paint through.
    std::optional<Vec3> towardsViewer;
    std::set<BoneId> locked;
};

struct DabResult {
    // The vertices whose weights changed, ascending.
    std::vector<int> changed;
    // Vertex visits left as they were because every other bone of the part
    // is locked (nothing can take up the difference).
    int skippedLocked = 0;
    // Vertex visits left as they were because the part has one bone only
    // (its weight is 1 everywhere).
    int skippedOnlyBone = 0;
    // X-mirror: vertices the dab changed that have no partner across the
    // mirror plane (none within vertexMirrorTolerance): painted on their
    // own side only.
    int unpaired = 0;
};

// The brush's strength at distance d (in radii, 0..1) from its centre.
double brushFalloff(BrushFalloff falloff, double d);

// Paints dabs into parts of one mesh, keeping what every dab of a stroke
// needs (the vertex neighbours for Smooth, the rest normals for front faces
// only) so that a dab costs time in proportion to the vertices it touches
// plus one pass over the positions (geometry-central's solver-class idiom).
class WeightPainter {
  public:
    // `mesh` must outlive the painter and be the mesh of every part painted.
    explicit WeightPainter(const TriMesh& mesh);

    // Paints one dab into `part` (its weights only). Throws Error for an
    // unknown or locked bone, a radius or strength out of range, a mirror
    // request on a part without a left-right mirror plane, or a part of
    // another mesh. With X-mirror, of two partners both within the brush
    // the one it reaches more strongly leads (its change is the pair's); a
    // partner on the plane, painted with a bone whose image is another
    // bone, gets the mean of the two bones' weights on both (Blender's
    // compromise there); a locked image bone is not painted.
    DabResult paint(Part& part, const WeightDab& dab);

  private:
    // The vertices within the dab's radius (facing the viewer, if asked)
    // and the brush's strength there, by ascending vertex.
    using Influence = std::vector<std::pair<int, double>>;
    const std::vector<std::vector<int>>& neighbours();
    const std::vector<Vec3>& normals();
    // The part's left-right symmetry and each vertex's partner across it,
    // found at the first mirrored dab.
    const PartSymmetry& symmetry(const Part& part);
    Influence gather(const WeightDab& dab);
    // The dab bone's new weight at each vertex of `influence` whose weight
    // it changes, from the weights as the dab found them.
    std::vector<std::pair<int, double>> targets(const Part& part, const WeightDab& dab,
                                                const Influence& influence);
    void paintBone(Part& part, const WeightDab& dab, const Influence& influence,
                   const LockedBones& locked, DabResult& result);
    void paintMirrored(Part& part, const WeightDab& dab, const Influence& influence,
                       const LockedBones& locked, DabResult& result);

    const TriMesh& mesh_;
    std::vector<std::vector<int>> neighbours_;
    std::vector<Vec3> normals_;
    bool symmetrySearched_ = false;
    std::optional<PartSymmetry> symmetry_;
    std::vector<int> partners_;  // rig/VertexMirror's mirrorVertices
};

// One dab on its own (builds what it needs each call).
DabResult paintWeights(Part& part, const WeightDab& dab);

}  // namespace rigmesh
