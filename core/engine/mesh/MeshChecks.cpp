#include "mesh/MeshChecks.h"
#include "mesh/MeshTopologyCheck.h"
#include "mesh/MeshVolume.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "base/DisjointSets.h"
#include "base/Error.h"
#include "mesh/MeshSelfIntersections.h"

namespace rigmesh {

namespace {

constexpr double kDegenerateAreaFactor = 1e-12;  // times the squared bounding-box diagonal

// One face's use of an undirected edge. Sorting by `key` groups the faces of each edge.
struct EdgeUse {
    std::uint64_t key;  // (smaller vertex << 32) | larger vertex
    int face;
    int corner;    // position in the face of the edge's first vertex in face order
    bool forward;  // the face goes from the smaller to the larger vertex
};

// Positions in the face of the edge's smaller and larger vertex.
int loCorner(const EdgeUse& use) {
    return use.forward ? use.corner : (use.corner + 1) % 3;
}
int hiCorner(const EdgeUse& use) {
    return use.forward ? (use.corner + 1) % 3 : use.corner;
}

bool hasRepeatedIndex(const std::array<int, 3>& f) {
    return f[0] == f[1] || f[1] == f[2] || f[2] == f[0];
}

void validate(const TriMesh& mesh) {
    for (const Vec3& v : mesh.vertices)
        if (!v.allFinite())
            throw Error(MessageId::MeshVertexNotFinite);
    for (int i = 0; i < mesh.faceCount(); ++i)
        for (const int index : mesh.faces[i])
            if (index < 0 || index >= mesh.vertexCount())
                throw Error(MessageId::MeshFaceVertexMissing, i, index, mesh.vertexCount());
}

// The edge uses of every face without a repeated vertex, grouped by edge:
// ordered by key, then face. A counting sort on the smaller vertex (the
// key's upper half), then each vertex's few uses sorted by (larger vertex,
// face): the same order as one comparison sort of all uses, in linear time
// (the comparison sort was most of a topology check). Indices are in range
// (validate() runs first).
std::vector<EdgeUse> sortedEdgeUses(const TriMesh& mesh) {
    std::vector<int> start(mesh.vertices.size() + 1, 0);
    for (const auto& face : mesh.faces) {
        if (hasRepeatedIndex(face))
            continue;
        for (int k = 0; k < 3; ++k)
            ++start[std::min(face[k], face[(k + 1) % 3]) + 1];
    }
    for (std::size_t v = 1; v < start.size(); ++v)
        start[v] += start[v - 1];
    std::vector<EdgeUse> uses(static_cast<std::size_t>(start.back()));
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const auto& face = mesh.faces[f];
        if (hasRepeatedIndex(face))
            continue;
        for (int k = 0; k < 3; ++k) {
            const auto from = static_cast<std::uint64_t>(face[k]);
            const auto to = static_cast<std::uint64_t>(face[(k + 1) % 3]);
            const bool forward = from < to;
            const std::uint64_t key = forward ? (from << 32) | to : (to << 32) | from;
            uses[next[std::min(face[k], face[(k + 1) % 3])]++] = {key, f, k, forward};
        }
    }
    // Faces were visited in order, so within a vertex's run the faces of each
    // key already ascend: a stable sort by key alone gives (key, face). The
    // runs are a vertex's few edges: insertion sort (stable, no allocation).
    for (std::size_t v = 0; v + 1 < start.size(); ++v)
        for (int i = start[v] + 1; i < start[v + 1]; ++i) {
            const EdgeUse use = uses[i];
            int j = i;
            for (; j > start[v] && uses[j - 1].key > use.key; --j)
                uses[j] = uses[j - 1];
            uses[j] = use;
        }
    return uses;
}

// Calls visit(first, last) for each run of uses of one edge.
template <class Visit>
void forEachEdge(const std::vector<EdgeUse>& uses, Visit visit) {
    for (std::size_t begin = 0; begin < uses.size();) {
        std::size_t end = begin + 1;
        while (end < uses.size() && uses[end].key == uses[begin].key)
            ++end;
        visit(begin, end);
        begin = end;
    }
}

// Topology from the edge map: boundary, non-manifold and mis-oriented edges,
// fans around vertices, components and the Euler characteristic.
void analyseTopology(const TriMesh& mesh, MeshReport& report) {
    const std::vector<EdgeUse> uses = sortedEdgeUses(mesh);
    // Corners (face * 3 + position) around a vertex join into one fan when
    // their faces share an edge at that vertex.
    DisjointSets fans(mesh.faces.size() * 3);
    int edges = 0;
    forEachEdge(uses, [&](std::size_t begin, std::size_t end) {
        ++edges;
        const std::size_t count = end - begin;
        if (count == 1)
            ++report.boundaryEdges;
        else if (count > 2)
            ++report.nonManifoldEdges;
        else if (uses[begin].forward == uses[begin + 1].forward)
            ++report.inconsistentlyOrientedEdges;
        const EdgeUse& first = uses[begin];
        for (std::size_t i = begin + 1; i < end; ++i) {
            const EdgeUse& other = uses[i];
            // Match the corner of each edge endpoint in both faces.
            const int firstLo = loCorner(first), firstHi = hiCorner(first);
            const int otherLo = loCorner(other), otherHi = hiCorner(other);
            fans.unite(first.face * 3 + firstLo, other.face * 3 + otherLo);
            fans.unite(first.face * 3 + firstHi, other.face * 3 + otherHi);
        }
    });

    // A vertex is non-manifold when its corners fall into more than one fan.
    std::vector<int> fanOfVertex(mesh.vertices.size(), -1);
    std::vector<char> nonManifold(mesh.vertices.size(), 0);
    DisjointSets components(mesh.vertices.size());
    int validFaces = 0;
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const auto& face = mesh.faces[f];
        if (hasRepeatedIndex(face))
            continue;
        ++validFaces;
        components.unite(face[0], face[1]);
        components.unite(face[0], face[2]);
        for (int k = 0; k < 3; ++k) {
            const int fan = fans.find(f * 3 + k);
            int& seen = fanOfVertex[face[k]];
            if (seen < 0)
                seen = fan;
            else if (seen != fan)
                nonManifold[face[k]] = 1;
        }
    }
    int referencedVertices = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (fanOfVertex[v] < 0)
            continue;
        ++referencedVertices;
        report.nonManifoldVertices += nonManifold[v];
        if (components.find(static_cast<int>(v)) == static_cast<int>(v))
            ++report.components;
    }

    report.eulerCharacteristic = referencedVertices - edges + validFaces;
    const int twiceGenus = 2 - report.eulerCharacteristic;
    const bool closedManifold = validFaces > 0 && report.boundaryEdges == 0 &&
                                report.nonManifoldEdges == 0 && report.nonManifoldVertices == 0;
    report.genus =
        closedManifold && report.components == 1 && twiceGenus >= 0 && twiceGenus % 2 == 0
            ? twiceGenus / 2
            : -1;
}

// Degenerate faces, angles, area and signed volume.
// Faces of at most this area count as degenerate.
double degenerateAreaBound(const Eigen::AlignedBox3d& box) {
    return box.isEmpty() ? 0.0 : kDegenerateAreaFactor * box.diagonal().squaredNorm();
}

double faceArea(const TriMesh& mesh, const std::array<int, 3>& face) {
    const Vec3& a = mesh.vertices[face[0]];
    return 0.5 * (mesh.vertices[face[1]] - a).cross(mesh.vertices[face[2]] - a).norm();
}

// Cones to the box centre, not to the world origin: far from the origin
// the cones' volumes would be huge and cancel to noise.
Vec3 volumeApex(const Eigen::AlignedBox3d& box) {
    return box.isEmpty() ? Vec3(Vec3::Zero()) : Vec3(box.center());
}

// Divergence theorem: each face adds the signed volume of its cone to the apex.
double coneVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& apex) {
    return (a - apex).dot((b - apex).cross(c - apex)) / 6;
}

void analyseGeometry(const TriMesh& mesh, MeshReport& report) {
    const Eigen::AlignedBox3d box = boundingBox(mesh);
    const double minArea = degenerateAreaBound(box);
    const Vec3 apex = volumeApex(box);
    double minAngle = 180, maxAngle = 0;
    bool anyAngle = false;
    for (const auto& face : mesh.faces) {
        if (hasRepeatedIndex(face)) {
            ++report.degenerateFaces;
            continue;
        }
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3& b = mesh.vertices[face[1]];
        const Vec3& c = mesh.vertices[face[2]];
        const double area = faceArea(mesh, face);
        report.area += area;
        report.volume += coneVolume(a, b, c, apex);
        if (area <= minArea) {
            ++report.degenerateFaces;
            continue;
        }
        const std::array<Vec3, 3> corners{a, b, c};
        for (int k = 0; k < 3; ++k) {
            const Vec3 u = corners[(k + 1) % 3] - corners[k];
            const Vec3 w = corners[(k + 2) % 3] - corners[k];
            // atan2 stays accurate for angles near 0 and 180 degrees, unlike acos.
            const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / std::numbers::pi;
            minAngle = std::min(minAngle, angle);
            maxAngle = std::max(maxAngle, angle);
            anyAngle = true;
        }
    }
    if (anyAngle) {
        report.minAngleDegrees = minAngle;
        report.maxAngleDegrees = maxAngle;
    }
}

}  // namespace

double surfaceArea(const TriMesh& mesh) {
    double area = 0.0;
    for (const auto& face : mesh.faces)
        area += faceArea(mesh, face);
    return area;
}

Eigen::AlignedBox3d boundingBox(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box;
}

MeshReport analyseMesh(const TriMesh& mesh, bool checkSelfIntersections) {
    validate(mesh);
    MeshReport report;
    report.vertices = mesh.vertexCount();
    report.faces = mesh.faceCount();
    analyseTopology(mesh, report);
    analyseGeometry(mesh, report);
    report.selfIntersectingFacePairs =
        checkSelfIntersections ? countSelfIntersectingFacePairs(mesh) : -1;
    return report;
}

MeshReport analyseMeshTopology(const TriMesh& mesh) {
    validate(mesh);
    MeshReport report;
    report.vertices = mesh.vertexCount();
    report.faces = mesh.faceCount();
    analyseTopology(mesh, report);
    report.selfIntersectingFacePairs = -1;
    return report;
}

double signedVolume(const TriMesh& mesh) {
    validate(mesh);
    const Vec3 apex = volumeApex(boundingBox(mesh));
    double volume = 0;
    for (const auto& face : mesh.faces)
        if (!hasRepeatedIndex(face))
            volume += coneVolume(mesh.vertices[face[0]], mesh.vertices[face[1]],
                                 mesh.vertices[face[2]], apex);
    return volume;
}

int countDegenerateFaces(const TriMesh& mesh) {
    validate(mesh);
    const double minArea = degenerateAreaBound(boundingBox(mesh));
    int count = 0;
    for (const auto& face : mesh.faces)
        count += hasRepeatedIndex(face) || faceArea(mesh, face) <= minArea;
    return count;
}

std::vector<std::array<int, 2>> boundaryEdgeList(const TriMesh& mesh) {
    validate(mesh);
    const std::vector<EdgeUse> uses = sortedEdgeUses(mesh);
    std::vector<std::array<int, 2>> result;
    forEachEdge(uses, [&](std::size_t begin, std::size_t end) {
        if (end - begin != 1)
            return;
        const auto& face = mesh.faces[uses[begin].face];
        const int k = uses[begin].corner;
        result.push_back({face[k], face[(k + 1) % 3]});
    });
    return result;
}

}  // namespace rigmesh
