// Quality checks for a triangle mesh: topology (boundary, manifoldness,
// orientation, components, genus), geometry (degenerate faces, angles, area,
// volume) and self-intersections. Works on any soup of triangles, including
// non-manifold and degenerate ones, so it can diagnose broken output.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/TriMesh.h"

namespace rigmesh {

struct MeshReport {
    int vertices = 0, faces = 0;
    int boundaryEdges = 0;                // edges with one incident face
    int nonManifoldEdges = 0;             // edges with > 2 incident faces
    int nonManifoldVertices = 0;          // vertices whose incident faces do not form one fan
    int inconsistentlyOrientedEdges = 0;  // two-face edges traversed the same way by both faces
    int components = 0;                   // connected components of faces (by shared vertices)
    int eulerCharacteristic = 0;          // V - E + F over referenced vertices and valid faces
    int genus = -1;           // for a closed, connected, manifold mesh: (2 - chi)/2; -1 otherwise
    int degenerateFaces = 0;  // repeated vertex index or area < 1e-12 * bbox diagonal^2
    // Pairs of distinct faces that intersect other than in a shared vertex or
    // edge, as CGAL::Polygon_mesh_processing::self_intersections counts them;
    // -1 when the check was not requested.
    int selfIntersectingFacePairs = 0;
    double minAngleDegrees = 0, maxAngleDegrees = 0;  // over all non-degenerate faces
    double volume = 0;                                // signed; > 0 for outward orientation
    double area = 0;

    bool isClosed() const { return faces > 0 && boundaryEdges == 0; }
    bool isManifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
    bool isOutwardOriented() const { return volume > 0 && inconsistentlyOrientedEdges == 0; }
    // What the CLI summary reports as the mesh checks: closed, manifold,
    // outward, no degenerate face and (when checked) no self-intersection.
    bool passesChecks() const {
        return isClosed() && isManifold() && isOutwardOriented() && degenerateFaces == 0 &&
               selfIntersectingFacePairs <= 0;
    }
    // Closed, manifold, consistently oriented, one component, genus 0.
    bool isWatertightGenus0() const {
        return isClosed() && isManifold() && inconsistentlyOrientedEdges == 0 && components == 1 &&
               genus == 0;
    }
};

// Analyses `mesh`. Faces with a repeated vertex index count as degenerate and
// are left out of the topology (edges, fans, components, Euler characteristic).
// Throws Error if a face index is out of range or a coordinate is not finite.
MeshReport analyseMesh(const TriMesh& mesh, bool checkSelfIntersections = true);

// MeshReport::degenerateFaces alone, without the rest of the analysis.
// Throws as analyseMesh does.
int countDegenerateFaces(const TriMesh& mesh);

// The sum of the faces' areas (MeshReport::area without the analysis).
double surfaceArea(const TriMesh& mesh);

// The axis-aligned box around the vertices (empty for no vertices).
Eigen::AlignedBox3d boundingBox(const TriMesh& mesh);

// The edges with exactly one incident face, as (from, to) in that face's order.
std::vector<std::array<int, 2>> boundaryEdgeList(const TriMesh& mesh);

}  // namespace rigmesh
