// The union of two closed surfaces computed on the faces near their overlap
// (paper 3.2.1, the same union merge/MeshUnion asks CGAL for). A face whose
// box misses the other surface's box lies outside that surface, so it is
// kept as it is; only the faces whose boxes meet the other box are
// corefined (CGAL's exact corefinement, which splits them along the
// intersection loops), and each piece they fall into between loops is kept
// or dropped by which side of the other surface it lies on: pieces joined to
// the far faces lie outside, crossing a loop changes the side, and a piece
// out of reach of both is told by a ray cast to the whole other surface.
// On the camel's last merge that is 980 of the 22,230 faces (616 of the
// body's, 364 of the head's) that CGAL's whole union boxes and copies.
//
// The result is the whole union's: the same faces, loop and sources, and
// the same positions but where an edge of one surface crosses an edge of
// the other (two parts sketched in one plane both have edges in it and
// cross so there). CGAL rounds such a point from whichever face pair it
// meets it through first, which differs between the two: such vertices may
// lie a few units in the last place apart (and, on an edge, name the other
// triangle beside it as their source). Either way the same input gives the
// same bytes.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "mesh/TriMesh.h"
#include "part/VertexSource.h"

namespace rigmesh {

// The union as a soup: the inputs' kept vertices and the loops' new ones
// (sources: Vertex for an input vertex, `first` winning where both have one
// at a position; New for a loop vertex of neither), the kept and split faces,
// and the loop edges. Faces and loop index `positions`; every position is
// used by a face.
struct UnionSoup {
    std::vector<Vec3> positions;
    VertexSources sources;
    std::vector<std::array<int, 3>> faces;
    std::vector<std::array<int, 2>> loop;
};

// The union of closed, oriented, manifold `first` and `second`, or nothing
// when this way cannot answer for sure and CGAL's whole union should: an
// input that is not a closed oriented manifold or has two vertices at one
// position, surfaces whose boxes do not
// overlap or that do not cross, a touching that is not a plain crossing (a
// vertex on the other surface, coplanar faces), a piece whose side no test
// settles, or a result that is not a closed oriented manifold whose volume
// lies between the larger input's and their sum. Throws
// Error(MergeSelfIntersecting) where CGAL's corefinement finds crossing faces
// within either input along the loops, as the whole union does.
std::optional<UnionSoup> unionNearOverlap(const TriMesh& first, const TriMesh& second);

}  // namespace rigmesh
