// Cutting a rigged part in two by a plane or by the surface a stroke sweeps
// where it was drawn (paper 3.1, Fig. 7): the surface is split, each hole
// filled by a patch at the part's edge length whose interior is either faired
// smooth (tangent-continuous with the surface, Fig. 7 middle) or left flat (a
// crease, Fig. 7 right); bones crossing the cut (their joints in different
// pieces) are split there and each piece keeps its own tree; weights of bones
// a piece no longer has are dropped and the patch's weights are filled by
// minimising their squared Laplacian with the old vertices held (3.1).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "part/Part.h"
#include "part/VertexSource.h"

namespace rigmesh {

enum class CutStyle { Smooth, Sharp };

struct CutRequest {
    // The plane, used when `stroke` is empty.
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitX();
    // Or a stroke swept along `sweep` (the view direction): a curved stroke
    // cuts along the ruled surface it sweeps (CutSurface).
    std::vector<Vec3> stroke;
    Vec3 sweep = Vec3::UnitZ();
    CutStyle style = CutStyle::Smooth;
    double edgeLength = 0.0;  // of the patch; 0 = the part's mean edge
};

struct CutResult {
    // The piece behind the cut (against the normal; for a stroke, against
    // stroke direction x sweep), then the one in front.
    std::array<Part, 2> pieces;
    std::array<double, 2> volumes{};  // of the pieces
    // The larger piece (by volume): the one that stays the part.
    int larger() const { return volumes[1] > volumes[0] ? 1 : 0; }
    std::array<VertexSources, 2> sources;     // into the cut part's mesh (mesh 0)
    std::array<std::vector<int>, 2> patches;  // the patch vertices of each piece
    double milliseconds = 0.0;
};

// Throws Error (a message for the user; nothing changes): a plane that
// misses the part, one that crosses it more than once (more than two
// pieces), a piece left without a bone, an unrigged part.
CutResult cutPart(const Part& part, const CutRequest& request);

}  // namespace rigmesh
