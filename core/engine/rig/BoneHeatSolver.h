// Bone heat skin weights (Baran & Popovic 2007, section 4), the skinning
// RigMesh uses for every shape (paper section 2.4) and re-runs locally after a
// merge (section 3.2.2).
//
// Each bone j radiates heat onto the surface; its weights w_j are the
// equilibrium temperature
//     (-Laplacian + H) w_j = H p_j,
// H_ii = c / d_i^2 with d_i the distance from vertex i to its closest visible
// bone(s), p_j(i) = 1/k if bone j is one of the k closest visible bones of i.
// Pinocchio's Laplacian is the cotangent operator divided by the vertex area
// A_i = sum of the areas of the triangles around i (attachment.cpp: the cotan
// sums over the sum of one-ring cross-product norms). Multiplying through by
// A gives the symmetric positive definite system we factor once:
//     (L + A H) w_j = A H p_j,   L_ik = -(cot a_ik + cot b_ik) / 2,
// L positive semi-definite. Cotangents scale by 1, A by s^2 and H by s^-2, so
// the system is invariant under scaling mesh and bones together.
//
// Area normalisation. Pinocchio's attachment.cpp builds each row
// from the full cotangent sums (cot a + cot b) and adds H / D with
// D = 1 / (1e-10 + sum over the one ring of |e_j x e_j+1|), i.e. twice the
// one-ring area; halving the row gives exactly L + A H above. Baran and
// Popovic's paper (section 4) only names the cotangent formula of Meyer et
// al., whose mixed Voronoi area is about a third of the one ring: heat three
// times weaker, weights wider and more leak. Blender's heat (meshlaplacian.cc)
// amounts to four mixed Voronoi areas, about 4/3 of the one ring: less leak
// but a sharper hand-over at every joint. We keep Pinocchio's one-ring area:
// on the shared sketches Blender's factor made the 99th percentile of the
// per-edge weight jump 8-14% worse, which the taper and the joint-aware
// construction shortcut (SketchToPart) avoid while cutting the leak.
//
// Faces with a repeated corner, a zero-length edge or collinear corners have
// no angles; they are left out (a vertex with only such faces takes the mean
// of its neighbours), so no cotangent pins a vertex with a huge diagonal.
//
// Obtuse triangles keep their negative cotangents, as in Pinocchio: L is the
// P1 finite element stiffness, positive semi-definite for any triangle shape.
// Negative weights or weights above 1 this may produce are clamped afterwards.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/Message.h"
#include "mesh/TriMesh.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

struct BoneHeatOptions {
    // Pinocchio's c (attachment.cpp initialHeatWeight, default 1) with its
    // Laplacian normalisation above.
    double heatConstant = 1.0;
    // Bones are solved in parallel on this many threads (visibility too).
    int threads = 2;
    // Small weights fade to zero before renormalising, as Blender's bone heat
    // does (source/blender/editors/armature/meshlaplacian.cc,
    // heat_limit_weight): a raw weight w below taperEnd is dropped, one in
    // [taperEnd, taperStart) becomes taperStart (w - taperEnd) / (taperStart -
    // taperEnd), continuous at both ends; larger ones are kept. Heat decays
    // exponentially but never reaches zero, so without the taper every bone
    // leaves a small weight far down its neighbours.
    // Blender ramps over 0.025..0.05; with Pinocchio's one-ring area (heat
    // 0.75 times Blender's, see above) that left the limb-leak figure 16-25%
    // above Blender's on every shared sketch with two or more limbs. Over
    // 0.05..0.1 (with the tie tolerance below) it is below Blender's on all
    // of them, the weights stay smoother than Blender's and the dominant bone
    // is unchanged; raising the heat to Blender's 4/3 instead made the
    // weights rougher than Blender's on y_branch
    // (tests/external/heat_vs_blender).
    double taperEnd = 0.05;
    double taperStart = 0.1;
    // Relative tolerance under which equally close visible bones share a
    // vertex. Blender takes 1e-4 (meshlaplacian.cc, DISTANCE_EPSILON); at 1e-2
    // a band of vertices around a kink's bisector split their heat between
    // both bones, and the weights there jumped more than Blender's (kinked:
    // p99 of the largest per-bone jump 0.147 against 0.141). 1e-4 and 1e-3
    // fix kinked but leave banana's tip rougher than Blender's (0.227 against
    // 0.220); 3e-3 keeps every shared sketch smoother than Blender's with
    // the limb leak below it (tests/external/heat_vs_blender).
    double tieTolerance = 3e-3;
};

// Sparse per-vertex skin weights.
struct SkinWeights {
    // (bone index, weight) sorted by bone; weights > 0 summing to 1.
    std::vector<std::vector<std::pair<int, double>>> perVertex;
    // Bones whose solve failed (non-finite bone, failed factorisation or
    // non-finite solution) and which use nearest-bone weights instead.
    std::vector<int> failedBones;
    // Notes for the user when anything fell back; empty otherwise.
    std::vector<Message> warnings;
};

// A vertex's closest visible bone(s) with their distance.
using ClosestBones = std::vector<std::vector<std::pair<int, double>>>;

// Keeps the sparse Cholesky factorisation (CHOLMOD) of L + A H so that bones
// can be solved repeatedly. `closestBones` is empty or has one list per
// vertex; the caller may fill cylinder vertices from construction bookkeeping
// (RigMesh section 2.4), and vertices with an empty list are tested with
// BoneVisibility here.
//
// `mirror`, if given, is each vertex's image in the plane z = 0 (as
// SketchSurface::mirror gives it). When the mesh is exactly its own mirror
// image (mesh/MeshMirror.h) and every vertex has the closest bones its image
// has, the system and every right-hand side are mirror-symmetric, and so is
// every solution: w = R u, with R summing a vertex and its image into one
// unknown. The solver then factors R^T (L + A H) R, of about half the size,
// and solves R^T (L + A H) R u = R^T A H p_j. This is the same system
// restricted to mirror-symmetric weights; the solutions differ from the
// full system's by its rounding only (the full matrix is symmetric up to the
// order in which each vertex's sums are added).
//
// A single bone's heat is 1 at every vertex: every vertex's closest bone is
// that bone (the bone is finite, validateInput, and so is every vertex's
// distance to it), so its right-hand side is A H 1, and L 1 = 0 (each row of the
// cotangent Laplacian, and of the orphans' uniform one, sums to zero), so
// (L + A H) 1 = A H 1. The solver then factors nothing and solves nothing;
// the weights are what the factored system gives up to its rounding, which
// the normalisation removes (a lone weight w becomes w / w = 1).
class BoneHeatSolver {
  public:
    BoneHeatSolver(const TriMesh& mesh, const std::vector<BoneSegment>& bones,
                   const ClosestBones& closestBones = {}, const BoneHeatOptions& options = {},
                   const std::vector<int>& mirror = {});
    ~BoneHeatSolver();
    BoneHeatSolver(BoneHeatSolver&&) noexcept;
    BoneHeatSolver& operator=(BoneHeatSolver&&) noexcept;
    BoneHeatSolver(const BoneHeatSolver&) = delete;
    BoneHeatSolver& operator=(const BoneHeatSolver&) = delete;

    int vertexCount() const;
    int boneCount() const;
    // False if CHOLMOD could not factor the system (every bone falls back).
    // A single bone needs no factorisation: true.
    bool isFactorized() const;
    // True when the mirror-symmetric system of half the size was factored
    // (never for a single bone).
    bool solvesMirrorSymmetric() const;
    // The closest visible bone(s) of every vertex used for the heat.
    const ClosestBones& closestBones() const;
    // How many tested vertices saw no bone from inside and were heated by
    // their closest bone regardless.
    int verticesWithoutVisibleBone() const;
    // The system matrix L + A H (upper triangle stored), for inspection.
    const Eigen::SparseMatrix<double>& systemMatrix() const;
    // The right-hand side A H p_j of a bone.
    Eigen::VectorXd rightHandSide(int bone) const;

    // The raw heat solution w_j (before clamping and normalisation); a bone
    // that cannot be solved gives its nearest-bone weights instead.
    Eigen::VectorXd solveBone(int bone) const;
    // Every bone, solved in parallel, clamped, thresholded and normalised.
    SkinWeights solveAll() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// One-shot convenience: factor, solve every bone and normalise.
SkinWeights computeBoneHeatWeights(const TriMesh& mesh, const std::vector<BoneSegment>& bones,
                                   const ClosestBones& closestBones = {},
                                   const BoneHeatOptions& options = {},
                                   const std::vector<int>& mirror = {});

}  // namespace rigmesh
