#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <map>
#include <stdexcept>
#include <string>

#include "base/Error.h"
#include "part/PartDetail.h"

namespace rigmesh {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace SMS = CGAL::Surface_mesh_simplification;

// Half-edge collapse: the edge goes to whichever end the quadric-based
// Lindstrom-Turk cost prefers, so no new position (and no new vertex) is
// made and every surviving vertex keeps its own skin weights exactly.
struct EndpointPlacement {
    template <class Profile>
    boost::optional<typename Profile::Point> operator()(const Profile& profile) const {
        const SMS::LindstromTurk_cost<Mesh> cost;
        const auto at0 = cost(profile, boost::optional<Point>(profile.p0()));
        const auto at1 = cost(profile, boost::optional<Point>(profile.p1()));
        if (!at0 && !at1)
            return boost::none;
        if (!at1 || (at0 && *at0 <= *at1))
            return profile.p0();
        return profile.p1();
    }
};

Mesh toCgal(const TriMesh& mesh) {
    Mesh out;
    std::vector<Mesh::Vertex_index> vertices;
    vertices.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices)
        vertices.push_back(out.add_vertex(Point(v.x(), v.y(), v.z())));
    for (const auto& f : mesh.faces)
        if (out.add_face(vertices[static_cast<std::size_t>(f[0])],
                         vertices[static_cast<std::size_t>(f[1])],
                         vertices[static_cast<std::size_t>(f[2])]) == Mesh::null_face())
            throw Error(MessageId::DecimationNotManifold);
    return out;
}

}  // namespace

Part decimatedPart(const Part& part, int faces) {
    if (faces < 4)
        throw Error(MessageId::DecimationTooFewFaces, faces);
    if (part.mesh.faceCount() <= faces)
        return part;
    Mesh mesh = toCgal(part.mesh);
    // A closed triangle mesh has 3/2 edges per face.
    const SMS::Count_stop_predicate<Mesh> stop(static_cast<std::size_t>(faces) * 3 / 2);
    SMS::edge_collapse(mesh, stop,
                       CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
                           .get_placement(EndpointPlacement()));
    mesh.collect_garbage();

    // Every vertex left sits exactly on an original vertex: its source.
    std::map<std::array<double, 3>, int> original;
    for (int v = 0; v < part.mesh.vertexCount(); ++v) {
        const Vec3& p = part.mesh.vertices[static_cast<std::size_t>(v)];
        original.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, v);
    }
    Part out = part;
    out.mesh = TriMesh();
    out.weights.perVertex.clear();
    std::map<Mesh::Vertex_index, int> index;
    for (const Mesh::Vertex_index v : mesh.vertices()) {
        const Point& p = mesh.point(v);
        const auto source = original.find({p.x(), p.y(), p.z()});
        if (source == original.end())
            throw std::logic_error("decimating '" + part.name + "' made a vertex of its own");
        index[v] = out.mesh.vertexCount();
        out.mesh.vertices.push_back(part.mesh.vertices[static_cast<std::size_t>(source->second)]);
        if (!part.weights.perVertex.empty())
            out.weights.perVertex.push_back(
                part.weights.perVertex[static_cast<std::size_t>(source->second)]);
    }
    for (const Mesh::Face_index f : mesh.faces()) {
        std::array<int, 3> face{};
        int k = 0;
        for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            face[static_cast<std::size_t>(k++)] = index.at(v);
        out.mesh.faces.push_back(face);
    }
    out.origins.clear();
    out.mirror.clear();
    out.knownClosestBones.clear();
    if (const auto problems = out.validate(); !problems.empty())
        throw Error(MessageId::DecimationInvalidResult, part.name, problems.front());
    return out;
}

}  // namespace rigmesh
