// The split of a closed surface by a cut surface with CGAL given only the
// band of faces the split can touch (cut/SurfaceSplit's Band method). Include
// only from .cpp files: it brings in CGAL (mesh/CgalSurfaceMesh.h).
//
// CGAL's PMP::split(tm, splitter) corefines tm with the splitter and cuts
// along the intersection (splitAlong below); PMP::split_connected_components copies each piece
// out. Over the whole part most of that is spent on faces far from the cut
// (the box intersection sorts every face and edge; every face and edge is
// copied). Here the band is a copy of the whole surface (same element
// indices) with the faces far from the cut marked removed and garbage not
// recycled, so CGAL adds the same new elements at the same indices as on the
// whole surface; the pieces are then read off the band's new connectivity
// and the whole surface's old one, in the order split_connected_components
// and copy_face_graph give (by face index; vertices by the index of their
// halfedge; border loops by halfedge index).
//
// The band must hold everything CGAL's result depends on: every edge whose
// box meets a splitter triangle's box and does not lie on one side of its
// plane (the keys of its edge-to-faces map, whose iteration order depends on
// the whole key set), every face whose box meets a splitter edge's box and
// whose plane that edge does not lie on one side of (the face sets of the
// splitter's edges, likewise), and two rings of faces around them so that
// nothing CGAL changes reaches the band's border; the border is checked to
// be unchanged after the split. CGAL's box intersection reports the pairs
// among a subset of boxes in the order it reports them among all (one
// splitter side has fewer boxes than the cutoff, so it scans boxes sorted by
// their lower x and address, which the copy keeps in index order).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

// One connected piece of the split surface as split_connected_components
// copies it out: points, faces (corners from the source of the face's
// halfedge) and border loops (each from its first halfedge by index).
struct SplitComponent {
    std::vector<Vec3> points;
    // Per point its vertex index on the whole surface (at or past the
    // whole's vertex count: made by the split); empty when not known.
    std::vector<int> wholeVertex;
    std::vector<std::array<int, 3>> faces;
    std::vector<std::vector<int>> holes;
};

struct BandOutcome {
    std::optional<std::vector<SplitComponent>> components;  // nullopt: the band did not hold
    int bandFaces = 0;
    // Per face of the whole surface: whether it is in the band (every face
    // the split changed is).
    std::vector<char> inBand;
    std::string whyNot;
};

// CGAL's PMP::split(tm, splitter) with the splitter left as it is
// (do_not_modify, CGAL 5.5 Polygon_mesh_processing/clip.h): corefine() then
// neither splits the splitter's edges nor triangulates its faces around the
// intersection points (a splitter triangle spans the part and holds hundreds
// of them): perf on bench_merge's curved camel cut, the split fell from 29%
// to 18% of cutPart's samples on the benchmark thread. tm is split along the
// same edges into the same elements at the same indices. CGAL writes a new
// vertex's position as its lazily exact intersection point rounded from its
// interval unless an exact predicate has refined it; the splitter's
// triangulation refined some, so a few of the new positions differ in their
// last bits (on the shared sketches' 825 test cuts: 12.6% of the new
// vertices, by at most 1.3e-14, the same links; docs/ARCHITECTURE.md section
// 10).
void splitAlong(cgal::SurfaceMesh& tm, cgal::SurfaceMesh& splitter);

// `whole`: the closed input (as mesh/CgalSurfaceMesh's toSurfaceMesh builds
// it); `splitter`: what PMP::split would corefine it with (left as it is,
// splitAlong).
BandOutcome splitInBand(const cgal::SurfaceMesh& whole, cgal::SurfaceMesh& splitter);

}  // namespace rigmesh
