// The surface a cut follows (paper 3.1): the surface an open stroke sweeps
// in the view direction, only as far as the stroke was drawn (as Blender's
// knife cuts only where it is drawn), or a whole plane. A straight stroke
// sweeps one flat strip, a curved one a ruled surface of one strip per
// stroke segment. Sides, crossings and the 2D frame its hole patches are
// triangulated in.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "base/Types.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

class CutSurface {
  public:
    static CutSurface plane(const Vec3& point, const Vec3& normal);
    // `stroke` (at least two points) is swept along `direction`, between its
    // end points only; a stroke that is straight within 1% of its length
    // sweeps one flat strip between its ends.
    static CutSurface swept(std::vector<Vec3> stroke, const Vec3& direction);

    bool isPlane() const { return stroke_.empty(); }
    const Vec3& planePoint() const { return point_; }
    const Vec3& planeNormal() const { return normal_; }

    // Signed: > 0 on the side the normal (or, swept, the strips' normals
    // stroke direction x sweep direction) points to. Beyond a swept
    // stroke's ends the side is that of its end segments' lines, so it is
    // only meaningful near the drawn stroke.
    double side(const Vec3& p) const;
    // The point where the segment a-b (on opposite sides) crosses.
    Vec3 crossing(const Vec3& a, const Vec3& b) const;
    // 2D coordinates on the surface (arc length along the stroke, depth
    // along the sweep; or plane coordinates) and back.
    Vec2 toPatch(const Vec3& p) const;
    Vec3 fromPatch(const Vec2& q) const;
    // The swept strip as a triangle mesh reaching past `box` in the sweep
    // direction and ending at the stroke's ends (for CGAL's split): only the
    // surface where the stroke was drawn cuts.
    TriMesh strip(const Eigen::AlignedBox3d& box) const;

  private:
    Vec3 point_ = Vec3::Zero();
    Vec3 normal_ = Vec3::UnitX();
    Vec3 u_ = Vec3::UnitY(), v_ = Vec3::UnitZ();  // plane frame
    std::vector<Vec3> stroke_;  // swept: on the plane through it normal to direction_
    std::vector<double> arc_;   // arc length at each stroke point
    Vec3 direction_ = Vec3::UnitZ();

    // The stroke's point nearest to p's projection, its arc length and the
    // segment it lies on.
    struct Nearest {
        Vec3 point;
        double arc;
        int segment;
    };
    Nearest nearest(const Vec3& p) const;
};

}  // namespace rigmesh
