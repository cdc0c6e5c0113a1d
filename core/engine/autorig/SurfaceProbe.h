// Questions the auto-rig asks a closed, outward rig surface about a point:
// inside or not (generalized winding number, autorig/JointsInside), how
// far from the surface, and where the middle of the shape's cross-section
// is (the medial position a joint of a limb takes, as a sketched part's
// joints sit on its chordal axis, paper 2.1). Only SurfaceProbe.cpp sees
// CGAL (an AABB tree of the triangles for rays and distances).
//
// A mesh as a file gives it (open, in pieces that overlap: an eye inside a
// head) may be asked by ray-cast parity instead, the test Blender's users
// and tests/external/check_tails_inside_in_blender.py apply: a point is
// inside when a ray from it crosses the surface an odd number of times,
// walls closer together than 1e-5 of the size counting once. So a point
// inside an eye inside a head is outside (two walls), as Blender sees it.
// Inside here means all but one of seven fixed rays say so, so that any
// three of them vote inside by majority.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

enum class InsideBy { WindingNumber, RayParity };

class SurfaceProbe {
  public:
    explicit SurfaceProbe(const TriMesh& surface, InsideBy rule = InsideBy::WindingNumber);
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
    // Every wall the ray from `from` along `direction` crosses, nearest
    // first, as distances along the (normalized) direction; walls closer
    // together than 1e-5 of the size count once (a ray through an edge or
    // a seam meets two faces there).
    std::vector<double> walls(const Vec3& from, const Vec3& direction) const;
    // The bounding box diagonal of the surface.
    double size() const;

  private:
    struct Tree;
    const TriMesh& mesh_;
    InsideBy rule_;
    std::unique_ptr<Tree> tree_;
};

}  // namespace rigmesh
