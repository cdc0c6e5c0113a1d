// A clean stand-in for a mesh that is not one closed, manifold,
// self-intersection-free piece: CGAL's 3D Alpha Wrapping (Portaneri et al.
// 2022, CGAL::alpha_wrap_3) of all its triangles together. Whatever the
// input (pieces, holes, crossing faces, sheets), the wrap is watertight,
// orientable, 2-manifold and free of self-intersections, a surface the
// curve skeleton and bone heat can take. A ball of radius `alpha` carves the
// space from outside: gaps narrower than about alpha are bridged, and the
// surface lies `offset` outside the input (a sheet gets a volume of twice
// the offset). The wrap's time follows its output size (about
// 1.2 area / alpha^2 vertices), so alpha comes from a vertex budget. A
// wrap with a handle is tried once finer: the handle may be a bridged gap
// (two soles) rather than the shape's. Only ProxyWrap.cpp sees CGAL.
#pragma once

#include "autorig/RigProgress.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct ProxyWrapOptions {
    // The wrap aims at about this many vertices: alpha = sqrt(c * area /
    // target), c measured on the assimp test characters (1.1-1.3 output
    // vertices per area / alpha^2; thin limbs take more).
    int targetVertices = 2400;
    // Alpha stays between these fractions of the bounding-box diagonal: a
    // finer wrap costs time, a coarser one bridges legs and arms.
    double finestAlpha = 1.0 / 90.0;
    double coarsestAlpha = 1.0 / 30.0;
    // The offset as a fraction of alpha. CGAL's default (1/30) follows the
    // input closely, at twice the vertices: on the assimp human 2709
    // vertices at 1/30, 1398 at 1/10, for the same limbs.
    double offsetFraction = 1.0 / 10.0;
    // The wrap is given points sampled on the input's triangles at most
    // alpha times this apart (see surfaceSamples in the .cpp).
    double sampleFraction = 1.0 / 2.0;
    // A wrap with a handle is tried once more at alpha times this (not
    // below the finest), kept when that removes a handle (see wrapIntoProxy).
    double handleRetryFactor = 0.7;
};

struct ProxyWrapResult {
    TriMesh mesh;
    double alpha = 0.0;
    double offset = 0.0;
    int wrappedPoints = 0;  // sampled on the input
    int handles = 0;        // the wrap's genus, summed over its components
    int components = 0;     // its connected pieces
    int wraps = 1;          // 2 when a handle was tried finer
};

// The alpha the options give for `soup` (its area and size).
double chooseWrapAlpha(const TriMesh& soup, const ProxyWrapOptions& options);

// Wraps every triangle of `soup` (any faces with three distinct corners in
// range; others are skipped). Reports progress from 0 to 1 and throws
// Error(AutoRigCancelled) when `progress` says stop, Error(AutoRigTooFewFaces)
// when no triangle is left to wrap.
ProxyWrapResult wrapIntoProxy(const TriMesh& soup, const ProxyWrapOptions& options = {},
                              const RigProgress& progress = {});

}  // namespace rigmesh
