// Questions the auto-rig asks a closed, outward rig surface about a point:
// inside or not (generalized winding number, autorig/JointsInside), how
// far from the surface, and where the middle of the shape's cross-section
// is (the medial position a joint of a limb takes, as a sketched part's
// joints sit on its chordal axis, paper 2.1). Only SurfaceProbe.cpp sees
// CGAL (an AABB tree of the triangles for rays and distances).
#pragma once

#include <memory>
#include <optional>

#include "mesh/TriMesh.h"

namespace rigmesh {

class SurfaceProbe {
  public:
    explicit SurfaceProbe(const TriMesh& surface);
    ~SurfaceProbe();
    SurfaceProbe(const SurfaceProbe&) = delete;
    SurfaceProbe& operator=(const SurfaceProbe&) = delete;

    bool inside(const Vec3& p) const;
    double distance(const Vec3& p) const;
    // The middle of the cross-section of the shape through `p` in the plane
    // perpendicular to `direction`. From a point inside: rays both ways
    // along two crossing directions in the plane, each time halfway between
    // the walls. From a point outside: the nearest wall any ray in the plane
    // meets, halfway from there to the wall behind it, then centred across.
    // None when no wall is met or the middle is not inside.
    std::optional<Vec3> middleOfCrossSection(const Vec3& p, const Vec3& direction) const;
    // Where the segment from a point outside to a point inside enters.
    Vec3 entry(const Vec3& outsidePoint, const Vec3& insidePoint) const;

  private:
    struct Tree;
    const TriMesh& mesh_;
    std::unique_ptr<Tree> tree_;
};

}  // namespace rigmesh
