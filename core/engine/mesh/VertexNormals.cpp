#include "mesh/VertexNormals.h"

#include <Eigen/Geometry>

namespace rigmesh {

std::vector<Vec3> vertexNormals(const TriMesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
    for (const auto& [a, b, c] : mesh.faces) {
        // The cross product's length is twice the area: area weighting.
        const Vec3 n =
            (mesh.vertices[b] - mesh.vertices[a]).cross(mesh.vertices[c] - mesh.vertices[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (Vec3& n : normals) {
        const double length = n.norm();
        n = length > 0 ? Vec3(n / length) : Vec3::Zero();
    }
    return normals;
}

}  // namespace rigmesh
