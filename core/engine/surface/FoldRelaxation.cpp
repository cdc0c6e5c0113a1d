#include "surface/FoldRelaxation.h"

#include "surface/CrossSections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include <Eigen/Geometry>

namespace rigmesh {
namespace {

Vec3 mirrored(const Vec3& v) {
    return {v.x(), v.y(), -v.z()};
}

// The upper half of the mirrored surface (faces above the sketch plane),
// with each face's neighbour across each edge: another upper face, or -1
// across the outline, where the neighbour is the face's own mirror image.
class UpperHalf {
  public:
    explicit UpperHalf(SketchSurface& surface) : p_(surface.mesh.vertices) {
        for (const auto& f : surface.mesh.faces)
            if (p_[f[0]].z() + p_[f[1]].z() + p_[f[2]].z() > 0)
                faces_.push_back(f);
        // Faces around each vertex, packed (no map: the neighbour across an
        // edge is found among the faces around one of its ends).
        const int faceTotal = static_cast<int>(faces_.size());
        firstFaceOf_.assign(p_.size() + 1, 0);
        for (const auto& f : faces_)
            for (int v : f)
                ++firstFaceOf_[v + 1];
        for (std::size_t v = 0; v < p_.size(); ++v)
            firstFaceOf_[v + 1] += firstFaceOf_[v];
        aroundVertex_.resize(3 * faces_.size());
        std::vector<int> fill(firstFaceOf_.begin(), firstFaceOf_.end() - 1);
        for (int i = 0; i < faceTotal; ++i)
            for (int v : faces_[i])
                aroundVertex_[fill[v]++] = i;
        across_.assign(faces_.size(), {-1, -1, -1});
        for (int i = 0; i < faceTotal; ++i)
            for (int k = 0; k < 3; ++k)
                for (int j : facesOf(faces_[i][(k + 1) % 3]))
                    if (j != i && contains(j, faces_[i][(k + 2) % 3])) {
                        across_[i][k] = j;
                        break;
                    }
        normal_.resize(faces_.size());
        area_.resize(faces_.size());
        for (int i = 0; i < faceTotal; ++i)
            updateNormal(i);
    }

    // The largest angle between neighbouring faces' normals, as its cosine.
    double smallestCos() const {
        double smallest = 1.0;
        for (int i = 0; i < faceCount(); ++i)
            for (int k = 0; k < 3; ++k)
                smallest = std::min(smallest, cosAcross(i, k));
        return smallest;
    }

    int faceCount() const { return static_cast<int>(faces_.size()); }
    const std::array<int, 3>& face(int i) const { return faces_[i]; }
    std::span<const int> facesOf(int v) const {
        return {aroundVertex_.data() + firstFaceOf_[v],
                static_cast<std::size_t>(firstFaceOf_[v + 1] - firstFaceOf_[v])};
    }
    int across(int i, int k) const { return across_[i][k]; }

    // The outline's edges: those with no upper face across them.
    std::vector<std::array<int, 2>> rimEdges() const {
        std::vector<std::array<int, 2>> edges;
        for (int i = 0; i < faceCount(); ++i)
            for (int k = 0; k < 3; ++k)
                if (across_[i][k] < 0)
                    edges.push_back({faces_[i][(k + 1) % 3], faces_[i][(k + 2) % 3]});
        return edges;
    }

    // The cosine of the angle between the normals across edge k of face i.
    double cosAcross(int i, int k) const {
        const int j = across_[i][k];
        return normal_[i].dot(j >= 0 ? normal_[j] : mirrored(normal_[i]));
    }

    void updateNormal(int i) {
        const auto& f = faces_[i];
        const Vec3 n = (p_[f[1]] - p_[f[0]]).cross(p_[f[2]] - p_[f[0]]);
        area_[i] = n.norm();
        normal_[i] = area_[i] > 0 ? Vec3(n / area_[i]) : Vec3::Zero();
    }

    // (1 - cos)^3 over the edges of the faces around v, each edge once.
    double energyAround(int v) const {
        double e = 0;
        for (int i : facesOf(v))
            for (int k = 0; k < 3; ++k) {
                const int j = across_[i][k];
                const bool shared = j >= 0 && contains(j, v);
                const double c = 1.0 - cosAcross(i, k);
                e += (shared ? 0.5 : 1.0) * c * c * c;
            }
        return e;
    }

    // The gradient of energyAround(v) with respect to v's position (its
    // mirror image moving with it): a face's unit normal n = N / |N| turns by
    // (I - n n^T) (delta x e) / |N| when a corner moves by delta, e running
    // between the face's two other corners.
    Vec3 gradientAt(int v) const {
        Vec3 g = Vec3::Zero();
        for (int i : facesOf(v)) {
            if (!(area_[i] > 0))
                continue;
            const auto& f = faces_[i];
            const int a = f[0] == v ? 0 : f[1] == v ? 1 : 2;
            const Vec3 e = p_[f[(a + 1) % 3]] - p_[f[(a + 2) % 3]];
            const Vec3& n = normal_[i];
            for (int k = 0; k < 3; ++k) {
                const int j = across_[i][k];
                // d cos / d n_i = the other normal; across the outline the
                // other normal is n_i's mirror image, which turns with it.
                const Vec3 other = j >= 0 ? normal_[j] : Vec3(2.0 * mirrored(n));
                const Vec3 perpendicular = other - other.dot(n) * n;
                const double c = 1.0 - cosAcross(i, k);
                g += -3.0 * c * c * e.cross(perpendicular) / area_[i];
            }
        }
        return g;
    }

  private:
    bool contains(int i, int v) const {
        return faces_[i][0] == v || faces_[i][1] == v || faces_[i][2] == v;
    }

    std::vector<Vec3>& p_;
    std::vector<std::array<int, 3>> faces_;
    std::vector<std::array<int, 3>> across_;
    std::vector<int> firstFaceOf_;  // per vertex, into aroundVertex_; one past the end last
    std::vector<int> aroundVertex_;
    std::vector<Vec3> normal_;
    std::vector<double> area_;
};

// The vertices of every edge whose faces meet at more than `degrees`, then
// `rings` edges around them, in the order found.
std::vector<int> verticesAroundFolds(const UpperHalf& half, double degrees, int rings,
                                     std::vector<char>& inRegion) {
    const double foldCos = std::cos(degrees * std::numbers::pi / 180.0);
    std::vector<int> region;
    for (int i = 0; i < half.faceCount(); ++i)
        for (int k = 0; k < 3; ++k)
            if (half.cosAcross(i, k) < foldCos)
                for (int c : {(k + 1) % 3, (k + 2) % 3}) {
                    const int v = half.face(i)[c];
                    if (!inRegion[v]) {
                        inRegion[v] = 1;
                        region.push_back(v);
                    }
                }
    for (int ring = 0; ring < rings && !region.empty(); ++ring) {
        const std::size_t size = region.size();
        for (std::size_t r = 0; r < size; ++r)
            for (int i : half.facesOf(region[r]))
                for (int v : half.face(i))
                    if (!inRegion[v]) {
                        inRegion[v] = 1;
                        region.push_back(v);
                    }
    }
    return region;
}

// One relaxation round: the vertices within `options.rings` edges of every
// fold descend on the energy, each with its mirror image; with
// `moveOutline`, the outline vertices within one edge of a fold above the
// limit too, in the sketch plane and at most `options.outlineShift` from
// where they were built. Returns how many vertices moved; `moved` marks
// them.
int relaxAroundFolds(SketchSurface& surface, UpperHalf& half, const FoldRelaxationOptions& options,
                     bool moveOutline, std::vector<char>& moved) {
    auto& p = surface.mesh.vertices;
    const int n = static_cast<int>(p.size());
    std::vector<char> inRegion(n, 0), nearLimit(n, 0);
    const std::vector<int> region =
        verticesAroundFolds(half, options.foldDegrees, options.rings, inRegion);
    if (region.empty())
        return 0;
    if (moveOutline)
        verticesAroundFolds(half, options.limitDegrees, 1, nearLimit);
    // Off the outline a vertex moves with its mirror image; on it, only
    // when asked, and then within the sketch plane (its own mirror image).
    std::vector<int> moving;
    for (int v : region) {
        const bool outline = surface.origins[v].onOutline || surface.mirror[v] == v;
        if (!outline || (moveOutline && nearLimit[v]))
            moving.push_back(v);
    }
    std::sort(moving.begin(), moving.end());
    std::vector<Vec3> built(moving.size());
    for (std::size_t m = 0; m < moving.size(); ++m)
        built[m] = p[moving[m]];
    int movedCount = 0;
    for (int pass = 0; pass < options.passes; ++pass) {
        bool any = false;
        for (std::size_t m = 0; m < moving.size(); ++m) {
            const int v = moving[m];
            const bool outline = surface.mirror[v] == v;
            Vec3 g = half.gradientAt(v);
            if (outline)
                g.z() = 0.0;
            if (!(g.norm() > 0) || !g.allFinite())
                continue;
            // Steps of at most a tenth of the longest edge around v, halved
            // until the energy drops; never through the sketch plane, and
            // an outline vertex never farther than outlineShift from where
            // it was built.
            double reach = 0;
            for (int i : half.facesOf(v))
                for (int w : half.face(i))
                    reach = std::max(reach, (p[w] - p[v]).norm());
            const double before = half.energyAround(v);
            const Vec3 start = p[v];
            double step = 0.1 * reach / g.norm();
            bool accepted = false;
            for (int attempt = 0; attempt < 6 && !accepted; ++attempt, step *= 0.5) {
                const Vec3 next = start - step * g;
                if (outline ? (next - built[m]).norm() > options.outlineShift
                            : !(next.z() > 0.25 * start.z()))
                    continue;
                p[v] = next;
                for (int i : half.facesOf(v))
                    half.updateNormal(i);
                accepted = half.energyAround(v) < before;
            }
            if (!accepted) {
                p[v] = start;
                for (int i : half.facesOf(v))
                    half.updateNormal(i);
                continue;
            }
            p[surface.mirror[v]] = mirrored(p[v]);
            any = true;
            if (!moved[v]) {
                moved[v] = 1;
                ++movedCount;
            }
        }
        if (!any)
            break;
    }
    return movedCount;
}

// Whether an outline edge with a moved end crosses another outline edge in
// the sketch plane.
bool outlineCrossesItself(const std::vector<Vec3>& p, const std::vector<std::array<int, 2>>& rim,
                          const std::vector<char>& moved) {
    for (const auto& a : rim) {
        if (!moved[a[0]] && !moved[a[1]])
            continue;
        for (const auto& b : rim) {
            if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1])
                continue;
            if (segmentsIntersect(p[a[0]].head<2>(), p[a[1]].head<2>(), p[b[0]].head<2>(),
                                  p[b[1]].head<2>()))
                return true;
        }
    }
    return false;
}

}  // namespace

int relaxFolds(SketchSurface& surface, const FoldRelaxationOptions& options) {
    UpperHalf half(surface);
    const double limitCos = std::cos(options.limitDegrees * std::numbers::pi / 180.0);
    // A surface with no fold above the limit is left as it is.
    if (!(half.smallestCos() < limitCos))
        return 0;
    std::vector<char> moved(surface.mesh.vertices.size(), 0);
    int count = relaxAroundFolds(surface, half, options, false, moved);
    // A fold the first round leaves has an outline vertex at one end: where
    // the outline turns too sharply for the faces meeting at that vertex (a
    // slot's apex turning 150 degrees within a spacing, a hair-thin tip
    // whose last ring ends beside the tip), which held, no interior vertex
    // can spread. Moving the outline vertices there a little along the
    // sketch plane rounds that corner just enough: a fillet where needed.
    // A surface the first round brings within the limit keeps its outline.
    if (options.outlineShift > 0 && half.smallestCos() < limitCos) {
        const std::vector<Vec3> before = surface.mesh.vertices;
        std::vector<char> movedHere(moved.size(), 0);
        relaxAroundFolds(surface, half, options, true, movedHere);
        if (outlineCrossesItself(surface.mesh.vertices, half.rimEdges(), movedHere)) {
            // Across a narrow slot the outline would cross itself: as before.
            surface.mesh.vertices = before;
        } else {
            for (std::size_t v = 0; v < moved.size(); ++v)
                count += movedHere[v] && !moved[v] ? 1 : 0;
        }
    }
    return count;
}

}  // namespace rigmesh
