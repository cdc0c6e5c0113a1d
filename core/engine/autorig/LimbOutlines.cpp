#include "autorig/LimbOutlines.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <unordered_map>

#include "base/DisjointSets.h"
#include "mesh/PositionHash.h"

namespace rigmesh {

namespace {

// Two outlines are two limbs when the shorter is at least this share of
// the longer (a strap or a strand of hair beside a leg is not a limb), and
// no third outline is as long.
constexpr double kComparable = 0.35;

std::uint64_t edgeKey(int u, int v) {
    if (u > v)
        std::swap(u, v);
    return (static_cast<std::uint64_t>(u) << 32) | static_cast<std::uint32_t>(v);
}

// Where the plane through `p` perpendicular to `d` cuts the triangles.
std::vector<Segment> slice(const std::vector<Vec3>& points,
                           const std::vector<std::array<int, 3>>& faces, const Vec3& p,
                           const Vec3& d) {
    std::vector<Segment> segments;
    for (const auto& f : faces) {
        const std::array<double, 3> side{(points[f[0]] - p).dot(d), (points[f[1]] - p).dot(d),
                                         (points[f[2]] - p).dot(d)};
        std::array<Vec3, 2> ends;
        std::array<std::uint64_t, 2> keys{};
        int found = 0;
        for (int i = 0; i < 3 && found < 2; ++i) {
            const int j = (i + 1) % 3;
            if ((side[i] >= 0.0) == (side[j] >= 0.0))
                continue;
            const double t = side[i] / (side[i] - side[j]);
            ends[found] = points[f[i]] + t * (points[f[j]] - points[f[i]]);
            keys[found] = edgeKey(f[i], f[j]);
            ++found;
        }
        if (found == 2)
            segments.push_back({ends[0], ends[1], keys[0], keys[1]});
    }
    return segments;
}

// The segments' connected outlines (through shared mesh edges).
std::vector<std::vector<int>> outlinesOf(const std::vector<Segment>& segments,
                                         const std::vector<int>& chosen) {
    std::unordered_map<std::uint64_t, int> keyIndex;
    const auto indexOf = [&](std::uint64_t key) {
        return keyIndex.emplace(key, static_cast<int>(keyIndex.size())).first->second;
    };
    std::vector<std::array<int, 2>> ends;
    for (int s : chosen)
        ends.push_back({indexOf(segments[s].keyA), indexOf(segments[s].keyB)});
    DisjointSets sets(keyIndex.size());
    for (const auto& [a, b] : ends)
        sets.unite(a, b);
    std::unordered_map<std::size_t, int> outlineOf;
    std::vector<std::vector<int>> outlines;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        const auto [at, added] =
            outlineOf.emplace(sets.find(ends[i][0]), static_cast<int>(outlines.size()));
        if (added)
            outlines.emplace_back();
        outlines[at->second].push_back(chosen[i]);
    }
    return outlines;
}

// Whether `q` lies inside the closed outline (crossing number in the plane
// spanned by u and v).
bool encloses(const std::vector<Segment>& segments, const std::vector<int>& outline, const Vec3& q,
              const Vec3& u, const Vec3& v) {
    bool inside = false;
    for (int s : outline) {
        const Vec3 a = segments[s].a - q, b = segments[s].b - q;
        const double ya = a.dot(v), yb = b.dot(v);
        if ((ya > 0.0) == (yb > 0.0))
            continue;
        const double xa = a.dot(u), xb = b.dot(u);
        if (xa + (0.0 - ya) * (xb - xa) / (yb - ya) > 0.0)
            inside = !inside;
    }
    return inside;
}

Outline outlineFrom(const std::vector<Segment>& segments, const std::vector<int>& members) {
    Outline outline;
    outline.members = members;
    for (int s : members) {
        const double l = (segments[s].b - segments[s].a).norm();
        outline.centroid += l * 0.5 * (segments[s].a + segments[s].b);
        outline.length += l;
    }
    if (outline.length > 0.0)
        outline.centroid /= outline.length;
    else if (!members.empty())
        outline.centroid = segments[members.front()].a;
    return outline;
}

void merge(Outline& into, const Outline& from) {
    const double total = into.length + from.length;
    if (total > 0.0)
        into.centroid = (into.length * into.centroid + from.length * from.centroid) / total;
    into.length = total;
    into.members.insert(into.members.end(), from.members.begin(), from.members.end());
}

double nearestTo(const std::vector<Segment>& segments, const Outline& outline, const Vec3& p) {
    double nearest = INFINITY;
    for (int s : outline.members)
        nearest = std::min({nearest, (segments[s].a - p).norm(), (segments[s].b - p).norm()});
    return nearest;
}

}  // namespace

Welded weld(const TriMesh& mesh) {
    Welded welded;
    std::unordered_map<Vec3, int, PositionHash> index;
    std::vector<int>& of = welded.of;
    of.resize(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto [at, added] =
            index.emplace(mesh.vertices[v], static_cast<int>(welded.points.size()));
        if (added)
            welded.points.push_back(mesh.vertices[v]);
        of[v] = at->second;
    }
    const int n = mesh.vertexCount();
    for (const auto& f : mesh.faces) {
        if (f[0] < 0 || f[1] < 0 || f[2] < 0 || f[0] >= n || f[1] >= n || f[2] >= n)
            continue;
        const std::array<int, 3> w{of[f[0]], of[f[1]], of[f[2]]};
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2])
            welded.faces.push_back(w);
    }
    return welded;
}

bool ProxyCut::holds(const Vec3& q) const {
    bool odd = false;
    for (const Outline& outline : outlines)
        odd ^= encloses(segments, outline.members, q, u, v);
    return odd && std::any_of(around.begin(), around.end(), [&](int o) {
               return encloses(segments, outlines[o].members, q, u, v);
           });
}

double ProxyCut::reach(const Vec3& p) const {
    double farthest = 0.0;
    for (int o : around)
        for (int s : outlines[o].members)
            farthest = std::max({farthest, (segments[s].a - p).norm(), (segments[s].b - p).norm()});
    return farthest;
}

ProxyCut proxyCutAt(const Welded& proxy, const Vec3& p, const Vec3& d) {
    ProxyCut cut;
    cut.u = d.unitOrthogonal();
    cut.v = d.cross(cut.u);
    cut.segments = slice(proxy.points, proxy.faces, p, d);
    std::vector<int> all(cut.segments.size());
    std::iota(all.begin(), all.end(), 0);
    for (const std::vector<int>& members : outlinesOf(cut.segments, all))
        cut.outlines.push_back(outlineFrom(cut.segments, members));
    const int count = static_cast<int>(cut.outlines.size());
    int enclosing = 0;
    for (const Outline& outline : cut.outlines)
        enclosing += encloses(cut.segments, outline.members, p, cut.u, cut.v) ? 1 : 0;
    if (enclosing % 2 == 1) {
        for (int o = 0; o < count; ++o)
            if (encloses(cut.segments, cut.outlines[o].members, p, cut.u, cut.v) &&
                (cut.around.empty() || cut.outlines[o].length < cut.outlines[cut.around[0]].length))
                cut.around = {o};
    } else {
        double nearest = INFINITY;
        for (const Outline& outline : cut.outlines)
            nearest = std::min(nearest, nearestTo(cut.segments, outline, p));
        for (int o = 0; o < count; ++o)
            if (nearestTo(cut.segments, cut.outlines[o], p) <= 2.0 * nearest)
                cut.around.push_back(o);
    }
    return cut;
}

std::vector<Outline> limbsAt(const Welded& mesh, const std::vector<std::array<int, 3>>& faces,
                             const ProxyCut& proxyCut, const Vec3& p, const Vec3& d) {
    const Vec3& u = proxyCut.u;
    const Vec3& v = proxyCut.v;
    if (proxyCut.around.empty())
        return {};
    const std::vector<Segment> meshCut = slice(mesh.points, faces, p, d);
    std::vector<int> inside;
    for (int s = 0; s < static_cast<int>(meshCut.size()); ++s)
        if (proxyCut.holds(0.5 * (meshCut[s].a + meshCut[s].b)))
            inside.push_back(s);
    std::vector<Outline> outlines;
    for (const std::vector<int>& members : outlinesOf(meshCut, inside))
        outlines.push_back(outlineFrom(meshCut, members));
    // Open outlines whose free ends pair with each other's close one loop
    // (the front and back of a limb made of two sheets, a seam not joined).
    const auto freeEnds = [&](const Outline& outline) {
        std::unordered_map<std::uint64_t, std::pair<int, Vec3>> seen;
        for (int s : outline.members) {
            auto& a = seen.emplace(meshCut[s].keyA, std::pair{0, meshCut[s].a}).first->second;
            ++a.first;
            auto& b = seen.emplace(meshCut[s].keyB, std::pair{0, meshCut[s].b}).first->second;
            ++b.first;
        }
        std::vector<Vec3> ends;
        for (const auto& [key, use] : seen)
            if (use.first == 1)
                ends.push_back(use.second);
        return ends;
    };
    for (bool merged = true; merged;) {
        merged = false;
        std::vector<std::vector<Vec3>> ends;
        for (const Outline& outline : outlines)
            ends.push_back(freeEnds(outline));
        // The outline whose free end is nearest each of this one's two.
        const auto partner = [&](std::size_t i, const Vec3& end) {
            std::size_t best = i;
            double nearest = INFINITY;
            for (std::size_t j = 0; j < outlines.size(); ++j)
                for (const Vec3& other : j == i ? std::vector<Vec3>{} : ends[j])
                    if ((other - end).norm() < nearest) {
                        nearest = (other - end).norm();
                        best = j;
                    }
            return best;
        };
        const auto pairedWith = [&](std::size_t i) {
            if (ends[i].size() != 2)
                return i;
            const std::size_t j = partner(i, ends[i][0]);
            return partner(i, ends[i][1]) == j ? j : i;
        };
        for (std::size_t i = 0; i < outlines.size() && !merged; ++i) {
            const std::size_t j = pairedWith(i);
            if (j != i && pairedWith(j) == i) {
                merge(outlines[std::min(i, j)], outlines[std::max(i, j)]);
                outlines.erase(outlines.begin() + static_cast<long>(std::max(i, j)));
                merged = true;
            }
        }
    }
    // An outline inside another (a sleeve around an arm, a boot around a
    // foot) is the same limb.
    const auto nested = [&](const Outline& a, const Outline& b) {
        return encloses(meshCut, a.members, b.centroid, u, v) ||
               encloses(meshCut, b.members, a.centroid, u, v);
    };
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < outlines.size() && !merged; ++i)
            for (std::size_t j = i + 1; j < outlines.size() && !merged; ++j)
                if (nested(outlines[i], outlines[j])) {
                    merge(outlines[i], outlines[j]);
                    outlines.erase(outlines.begin() + static_cast<long>(j));
                    merged = true;
                }
    }
    std::sort(outlines.begin(), outlines.end(),
              [](const Outline& a, const Outline& b) { return a.length > b.length; });
    // Those comparable with the longest (not a strap or a strand of hair).
    std::erase_if(outlines, [&](const Outline& outline) {
        return outline.length < kComparable * outlines.front().length;
    });
    return outlines;
}

}  // namespace rigmesh
