// Bone heat skin weights (Pinocchio, as used by RigMesh section 2.4).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "BoneHeatTestMeshes.h"
#include "SketchToSurfaceTestSupport.h"
#include "base/Error.h"
#include "pipeline/SketchToPart.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh {
namespace {

using test::boneWeights;
using test::expectPartitionOfUnity;
using test::makeCappedTube;
using test::makeUvSphere;

// A tube of length 4 and radius 0.5 along x with a joint in the middle.
struct TwoBoneTube {
    TriMesh mesh = makeCappedTube(41, 24, 0.5, 4.0);
    std::vector<BoneSegment> bones = {{Vec3(0.25, 0, 0), Vec3(2, 0, 0)},
                                      {Vec3(2, 0, 0), Vec3(3.75, 0, 0)}};
};

TEST(BoneHeatSolver, TestMeshesAreClosedAndOutward) {
    EXPECT_GT(test::signedVolume(makeCappedTube(5, 8, 0.5, 4.0)), 0.0);
    EXPECT_GT(test::signedVolume(makeUvSphere(8, 12, 1.0)), 0.0);
}

TEST(BoneHeatSolver, WeightsArePositiveAndSumToOneOnEveryTubeVertex) {
    const TwoBoneTube tube;
    const SkinWeights weights = computeBoneHeatWeights(tube.mesh, tube.bones);
    expectPartitionOfUnity(weights, tube.mesh.vertexCount(), 2);
    EXPECT_TRUE(weights.failedBones.empty());
    EXPECT_TRUE(weights.warnings.empty()) << englishText(weights.warnings);
}

TEST(BoneHeatSolver, WeightsArePositiveAndSumToOneOnEverySphereVertex) {
    const TriMesh sphere = makeUvSphere(16, 24, 1.0);
    const std::vector<BoneSegment> bones = {{Vec3(0, 0, -0.6), Vec3(0, 0, 0)},
                                            {Vec3(0, 0, 0), Vec3(0, 0, 0.6)},
                                            {Vec3(0, 0, 0), Vec3(0.6, 0, 0)}};
    const SkinWeights weights = computeBoneHeatWeights(sphere, bones);
    expectPartitionOfUnity(weights, sphere.vertexCount(), 3);
    EXPECT_TRUE(weights.failedBones.empty());
}

// One bone: the solver factors nothing and gives heat 1 everywhere, which
// solves the system it would have factored (each Laplacian row, the
// degenerate faces' uniform ones included, sums to zero); every vertex then
// weighs 1 on that bone.
TEST(BoneHeatSolver, ASingleBonesHeatIsOneEverywhereAndSolvesItsSystem) {
    const TwoBoneTube tube;
    TriMesh mesh = tube.mesh;
    const int onRing = 18 * 24 + 3;
    mesh.faces.push_back({onRing, onRing, onRing + 24});  // a repeated corner
    const int middle = mesh.vertexCount();                // a vertex on collinear faces only
    mesh.vertices.push_back(0.5 * (mesh.vertices[onRing] + mesh.vertices[onRing + 1]));
    mesh.faces.push_back({onRing, middle, onRing + 1});
    mesh.vertices.push_back(Vec3(2.0, 0.1, 0.0));  // in no face
    const std::vector<BoneSegment> bone = {{Vec3(0.25, 0, 0), Vec3(3.75, 0, 0)}};

    const BoneHeatSolver solver(mesh, bone);
    EXPECT_TRUE(solver.isFactorized());
    EXPECT_FALSE(solver.solvesMirrorSymmetric());
    const Eigen::VectorXd heat = solver.solveBone(0);
    EXPECT_EQ(heat, Eigen::VectorXd::Ones(mesh.vertexCount()));
    // The assembled system (its upper triangle stored) times the heat.
    const Eigen::SparseMatrix<double> system =
        solver.systemMatrix().selfadjointView<Eigen::Upper>();
    ASSERT_EQ(system.rows(), mesh.vertexCount());
    const Eigen::VectorXd rhs = solver.rightHandSide(0);
    EXPECT_GT(rhs.minCoeff(), 0.0);
    EXPECT_LT((system * heat - rhs).lpNorm<Eigen::Infinity>(),
              1e-12 * rhs.lpNorm<Eigen::Infinity>());
    // Asked again: the same system.
    const Eigen::SparseMatrix<double> again = solver.systemMatrix();
    EXPECT_EQ((again - solver.systemMatrix()).norm(), 0.0);
    EXPECT_EQ(2 * again.nonZeros(), system.nonZeros() + mesh.vertexCount());  // upper triangle
    // The factored system gives the same heat up to its rounding: a second,
    // non-finite bone makes the solver factor it (the bone is left out of
    // every vertex's closest bones, so the system and bone 0's right-hand
    // side are the same).
    const std::vector<BoneSegment> withUnusable = {
        bone.front(), {Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0), Vec3(1, 0, 0)}};
    const BoneHeatSolver factored(mesh, withUnusable);
    ASSERT_TRUE(factored.isFactorized());
    EXPECT_LT((factored.solveBone(0) - heat).lpNorm<Eigen::Infinity>(), 1e-9);
    const SkinWeights factoredWeights = factored.solveAll();

    const SkinWeights weights = solver.solveAll();
    ASSERT_EQ(weights.perVertex.size(), static_cast<std::size_t>(mesh.vertexCount()));
    for (std::size_t v = 0; v < weights.perVertex.size(); ++v) {
        const auto& list = weights.perVertex[v];
        ASSERT_EQ(list.size(), 1u);
        EXPECT_EQ(list.front(), std::make_pair(0, 1.0));
        EXPECT_EQ(factoredWeights.perVertex[v], list);
    }
    EXPECT_TRUE(weights.failedBones.empty());
    // The vertex on collinear faces only and the one in no face have no
    // normal to look along; the factored solver says the same (after its
    // note on the unusable bone).
    ASSERT_EQ(weights.warnings.size(), 1u) << englishText(weights.warnings);
    EXPECT_EQ(weights.warnings.front(), (Message{MessageId::WeightsVerticesSeeNoBone, {"2"}}));
    EXPECT_EQ(factoredWeights.warnings.back(), weights.warnings.front());
}

TEST(BoneHeatSolver, TubeEndsFollowTheirOwnBone) {
    const TwoBoneTube tube;
    const SkinWeights weights = computeBoneHeatWeights(tube.mesh, tube.bones);
    const std::vector<double> first = boneWeights(weights, 0);
    const std::vector<double> second = boneWeights(weights, 1);
    int checked = 0;
    for (int v = 0; v < tube.mesh.vertexCount(); ++v) {
        const double x = tube.mesh.vertices[v].x();
        if (x < 0.5) {
            EXPECT_GE(first[v], 0.95) << "x = " << x;
            ++checked;
        } else if (x > 3.5) {
            EXPECT_GE(second[v], 0.95) << "x = " << x;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
}

TEST(BoneHeatSolver, WeightsVarySmoothlyBetweenMeshNeighbours) {
    const TwoBoneTube tube;
    const SkinWeights weights = computeBoneHeatWeights(tube.mesh, tube.bones);
    const std::vector<double> first = boneWeights(weights, 0);
    double largestJump = 0.0;
    for (const auto& face : tube.mesh.faces) {
        for (int c = 0; c < 3; ++c) {
            largestJump =
                std::max(largestJump, std::abs(first[face[c]] - first[face[(c + 1) % 3]]));
        }
    }
    // Pinocchio's system behaves like -Laplace + 3c/d^2 (one-ring area, see
    // BoneHeatSolver.h): across the joint w decays over d/sqrt(3) = 0.29, a
    // slope of at most sqrt(3)/(2 * 0.5) = 1.73 per unit length. Rings are 0.1
    // apart, so neighbours differ by at most ~0.17.
    EXPECT_LT(largestJump, 0.2);
    // ...and the weight of the first bone falls monotonically along the tube.
    for (int r = 0; r + 1 < 41; ++r) {
        EXPECT_GE(first[r * 24] + 1e-12, first[(r + 1) * 24]) << "ring " << r;
    }
}

TEST(BoneHeatSolver, ScalingMeshAndBonesLeavesWeightsUnchanged) {
    const TwoBoneTube tube;
    const SkinWeights reference = computeBoneHeatWeights(tube.mesh, tube.bones);
    for (double factor : {1e-3, 1e3}) {
        const SkinWeights scaledWeights = computeBoneHeatWeights(test::scaled(tube.mesh, factor),
                                                                 test::scaled(tube.bones, factor));
        for (int bone = 0; bone < 2; ++bone) {
            const std::vector<double> a = boneWeights(reference, bone);
            const std::vector<double> b = boneWeights(scaledWeights, bone);
            for (std::size_t v = 0; v < a.size(); ++v) {
                EXPECT_NEAR(a[v], b[v], 1e-9) << "scale " << factor << " vertex " << v;
            }
        }
    }
}

// The documented system, assembled densely and independently of the solver:
// (L + A H) w = A H p with L the cot/2 stiffness, A the one-ring area and
// H = c / d^2.
TEST(BoneHeatSolver, SmallSystemMatchesDenseLdltSolve) {
    const TriMesh mesh = makeCappedTube(7, 10, 0.5, 3.0);
    ASSERT_LT(mesh.vertexCount(), 200);
    const std::vector<BoneSegment> bones = {{Vec3(0.3, 0, 0), Vec3(1.4, 0, 0)},
                                            {Vec3(1.4, 0, 0), Vec3(2.7, 0, 0)}};
    const int n = mesh.vertexCount();
    ClosestBones closest(n);
    for (int v = 0; v < n; ++v) {
        const double d0 = pointSegmentDistance(mesh.vertices[v], bones[0]);
        const double d1 = pointSegmentDistance(mesh.vertices[v], bones[1]);
        closest[v].emplace_back(d0 <= d1 ? 0 : 1, std::min(d0, d1));
    }
    BoneHeatOptions options;
    options.heatConstant = 0.7;
    const BoneHeatSolver solver(mesh, bones, closest, options);

    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd area = Eigen::VectorXd::Zero(n);
    for (const auto& f : mesh.faces) {
        for (int c = 0; c < 3; ++c) {
            const int i = f[c], j = f[(c + 1) % 3], k = f[(c + 2) % 3];
            const Vec3 a = mesh.vertices[j] - mesh.vertices[i];
            const Vec3 b = mesh.vertices[k] - mesh.vertices[i];
            const double halfCot = 0.5 * a.dot(b) / a.cross(b).norm();
            system(j, k) -= halfCot;
            system(k, j) -= halfCot;
            system(j, j) += halfCot;
            system(k, k) += halfCot;
            area[i] += 0.5 * a.cross(b).norm();
        }
    }
    Eigen::VectorXd heat(n);
    for (int v = 0; v < n; ++v) {
        heat[v] = options.heatConstant * area[v] / std::pow(closest[v][0].second, 2);
        system(v, v) += heat[v];
    }
    const Eigen::LDLT<Eigen::MatrixXd> dense(system);
    for (int bone = 0; bone < 2; ++bone) {
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
        for (int v = 0; v < n; ++v) {
            if (closest[v][0].first == bone) {
                rhs[v] = heat[v];
            }
        }
        const Eigen::VectorXd expected = dense.solve(rhs);
        const Eigen::VectorXd actual = solver.solveBone(bone);
        EXPECT_LT((expected - actual).lpNorm<Eigen::Infinity>(), 1e-8) << "bone " << bone;
        EXPECT_LT((solver.rightHandSide(bone) - rhs).lpNorm<Eigen::Infinity>(), 1e-12);
    }
}

TEST(BoneHeatSolver, RawSolutionsOfAllBonesSumToOneBeforeClamping) {
    const TwoBoneTube tube;
    const BoneHeatSolver solver(tube.mesh, tube.bones);
    const Eigen::VectorXd sum = solver.solveBone(0) + solver.solveBone(1);
    EXPECT_LT((sum - Eigen::VectorXd::Ones(sum.size())).lpNorm<Eigen::Infinity>(), 1e-9);
}

TEST(BoneHeatSolver, BoneWithNanEndpointIsReportedAndVerticesStayWeighted) {
    const TwoBoneTube tube;
    std::vector<BoneSegment> bones = tube.bones;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bones.push_back({Vec3(1, 0, 0), Vec3(nan, 0, 0)});
    const SkinWeights weights = computeBoneHeatWeights(tube.mesh, bones);
    EXPECT_EQ(weights.failedBones, std::vector<int>{2});
    ASSERT_EQ(weights.warnings.size(), 1u) << englishText(weights.warnings);
    EXPECT_EQ(weights.warnings[0].id, MessageId::WeightsBoneUnsolved);
    EXPECT_EQ(weights.warnings[0].args, std::vector<std::string>{"2"});
    EXPECT_NE(englishText(weights.warnings).find("bone 2"), std::string::npos);
    expectPartitionOfUnity(weights, tube.mesh.vertexCount(), 3);
    for (const auto& list : weights.perVertex) {
        for (const auto& [bone, w] : list) {
            EXPECT_NE(bone, 2);
        }
    }
}

TEST(BoneHeatSolver, ResolvingWithTheSameSolverGivesIdenticalWeights) {
    const TwoBoneTube tube;
    const BoneHeatSolver solver(tube.mesh, tube.bones);
    const SkinWeights first = solver.solveAll();
    const SkinWeights second = solver.solveAll();
    EXPECT_EQ(first.perVertex, second.perVertex);
    EXPECT_EQ(solver.solveBone(1), solver.solveBone(1));
    const SkinWeights oneShot = computeBoneHeatWeights(tube.mesh, tube.bones);
    EXPECT_EQ(first.perVertex, oneShot.perVertex);
}

TEST(BoneHeatSolver, OneThreadAndTwoThreadsGiveIdenticalWeights) {
    const TwoBoneTube tube;
    BoneHeatOptions serial;
    serial.threads = 1;
    EXPECT_EQ(computeBoneHeatWeights(tube.mesh, tube.bones, {}, serial).perVertex,
              computeBoneHeatWeights(tube.mesh, tube.bones).perVertex);
}

TEST(BoneHeatSolver, CallerGivenClosestBonesAreUsedWithoutVisibilityTests) {
    const TwoBoneTube tube;
    const int n = tube.mesh.vertexCount();
    // Claim every vertex is closest to bone 1 (a deliberately odd choice).
    ClosestBones closest(n, {{1, 0.5}});
    const BoneHeatSolver solver(tube.mesh, tube.bones, closest);
    EXPECT_EQ(solver.closestBones(), closest);
    const SkinWeights weights = solver.solveAll();
    for (const auto& list : weights.perVertex) {
        ASSERT_EQ(list.size(), 1u);
        EXPECT_EQ(list[0].first, 1);
    }
}

TEST(BoneHeatSolver, VerticesWithEmptyClosestListAreTestedForVisibility) {
    const TwoBoneTube tube;
    ClosestBones closest(tube.mesh.vertexCount());
    closest[0] = {{1, 0.5}};
    const BoneHeatSolver solver(tube.mesh, tube.bones, closest);
    EXPECT_EQ(solver.closestBones()[0], closest[0]);
    // Ring 20 sits on the joint: both bones tie there.
    const auto& joint = solver.closestBones()[20 * 24];
    EXPECT_EQ(joint.size(), 2u);
    EXPECT_EQ(solver.closestBones()[tube.mesh.vertexCount() - 2].at(0).first, 0);
}

// Blender's taper (meshlaplacian.cc heat_limit_weight): raw weights below the
// end are dropped, those between end and start fade linearly from 0 to start.
TEST(BoneHeatSolver, SmallWeightsFadeToZeroBetweenTaperEndAndStart) {
    const TwoBoneTube tube;
    BoneHeatOptions options;
    options.taperEnd = 0.1;
    options.taperStart = 0.2;
    const BoneHeatSolver solver(tube.mesh, tube.bones, {}, options);
    const SkinWeights weights = solver.solveAll();
    expectPartitionOfUnity(weights, tube.mesh.vertexCount(), 2);
    const Eigen::VectorXd raw0 = solver.solveBone(0);
    const Eigen::VectorXd raw1 = solver.solveBone(1);
    int dropped = 0;
    int faded = 0;
    for (int v = 0; v < tube.mesh.vertexCount(); ++v) {
        const double r0 = raw0[v];
        const double r1 = raw1[v];
        auto tapered = [](double w) { return w < 0.1 ? 0.0 : w < 0.2 ? 0.2 * (w - 0.1) / 0.1 : w; };
        const double t0 = tapered(r0);
        const double t1 = tapered(r1);
        dropped += (r0 > 0.0 && r0 < 0.1) || (r1 > 0.0 && r1 < 0.1) ? 1 : 0;
        faded += (r0 >= 0.1 && r0 < 0.2) || (r1 >= 0.1 && r1 < 0.2) ? 1 : 0;
        EXPECT_NEAR(boneWeights(weights, 0)[v], t0 / (t0 + t1), 1e-12) << "vertex " << v;
        EXPECT_NEAR(boneWeights(weights, 1)[v], t1 / (t0 + t1), 1e-12) << "vertex " << v;
    }
    EXPECT_GT(dropped, 0);
    EXPECT_GT(faded, 0);
}

// A junction patch can emit triangles with a repeated corner or three
// collinear corners. Their cotangents (~1e8) once pinned a vertex at 0 in
// every solve, so it fell back to one bone among neighbours at 0.2-0.4.
// The solver leaves such faces out: the other vertices get
// the weights of the clean mesh, and a vertex with only degenerate
// faces takes the mean of its neighbours.
TEST(BoneHeatSolver, DegenerateFacesLeaveNoSpike) {
    const TwoBoneTube tube;
    const int segments = 24;
    TriMesh mesh = tube.mesh;
    // Ring 18 is just before the joint (ring 20), where both bones matter.
    const int onRing = 18 * segments + 3;
    const int nextOnRing = onRing + 1;
    const int nextRing = onRing + segments;
    mesh.faces.push_back({onRing, onRing, nextRing});  // repeated corner
    mesh.faces.push_back({onRing, nextRing, nextRing});
    // A vertex in the middle of an edge, used only by a collinear face.
    const int middle = mesh.vertexCount();
    mesh.vertices.push_back(0.5 * (mesh.vertices[onRing] + mesh.vertices[nextOnRing]));
    mesh.faces.push_back({onRing, middle, nextOnRing});

    const BoneHeatSolver solver(mesh, tube.bones);
    const BoneHeatSolver clean(tube.mesh, tube.bones);
    // No pinning: every diagonal entry stays of the order of its neighbours'.
    const Eigen::VectorXd diagonal = solver.systemMatrix().diagonal();
    EXPECT_LT(diagonal.maxCoeff(), 100.0 * clean.systemMatrix().diagonal().maxCoeff());

    for (int bone = 0; bone < 2; ++bone) {
        const Eigen::VectorXd raw = solver.solveBone(bone);
        const Eigen::VectorXd reference = clean.solveBone(bone);
        // Up to the pull of the added vertex's tiny heat (1e-6 per edge).
        EXPECT_LT((raw.head(tube.mesh.vertexCount()) - reference).lpNorm<Eigen::Infinity>(), 1e-6)
            << "bone " << bone;
        EXPECT_NEAR(raw[middle], 0.5 * (raw[onRing] + raw[nextOnRing]), 1e-4) << "bone " << bone;
    }
    const SkinWeights weights = solver.solveAll();
    expectPartitionOfUnity(weights, mesh.vertexCount(), 2);
    const std::vector<double> first = boneWeights(weights, 0);
    for (int v : {onRing, middle}) {
        for (int neighbour : {nextOnRing, nextRing, onRing - segments}) {
            EXPECT_LT(std::abs(first[v] - first[neighbour]), 0.2)
                << "vertex " << v << " against " << neighbour;
        }
    }
}

TEST(BoneHeatSolver, InvalidInputIsRejectedWithAnError) {
    const TwoBoneTube tube;
    EXPECT_THROW(computeBoneHeatWeights(tube.mesh, {}), Error);
    TriMesh broken = tube.mesh;
    broken.faces.push_back({0, 1, broken.vertexCount()});
    EXPECT_THROW(computeBoneHeatWeights(broken, tube.bones), Error);
    EXPECT_THROW(computeBoneHeatWeights(tube.mesh, tube.bones, ClosestBones(3)), std::logic_error);
    BoneHeatOptions reversedTaper;
    reversedTaper.taperEnd = 0.1;
    reversedTaper.taperStart = 0.05;
    EXPECT_THROW(computeBoneHeatWeights(tube.mesh, tube.bones, {}, reversedTaper),
                 std::logic_error);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(computeBoneHeatWeights(tube.mesh, {{Vec3(nan, 0, 0), Vec3(1, 0, 0)}}), Error);
}

// A sketched part is its own mirror image in the sketch plane with its bones
// in that plane: given the mirror, the solver factors the mirror-symmetric
// system of half the size. Every bone's heat is then exactly symmetric and
// within rounding of the full system's; a mesh whose image is off by a
// little is solved in full.
TEST(BoneHeatSolver, MirroredPartIsSolvedOnHalfTheUnknownsWithTheFullSystemsHeat) {
    const SketchToPartResult built =
        sketchToPart(testsupport::sharedSketchPoints("biped"), "biped");
    const TriMesh& mesh = built.part.mesh;
    const std::vector<int>& mirror = built.part.mirror;
    const auto bones = built.part.boneSegments();
    const ClosestBones closest = closestBonesFromConstruction(
        built.surface.surface, built.surface.cylinders, built.skeleton);
    const BoneHeatSolver full(mesh, bones, closest);
    const BoneHeatSolver half(mesh, bones, closest, {}, mirror);
    EXPECT_FALSE(full.solvesMirrorSymmetric());
    ASSERT_TRUE(half.solvesMirrorSymmetric());
    for (int bone = 0; bone < full.boneCount(); ++bone) {
        const Eigen::VectorXd a = full.solveBone(bone);
        const Eigen::VectorXd b = half.solveBone(bone);
        EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-12) << "bone " << bone;
        for (int v = 0; v < mesh.vertexCount(); ++v)
            ASSERT_EQ(b[v], b[mirror[v]]) << "bone " << bone << ", vertex " << v;
    }

    TriMesh uneven = mesh;
    int off = 0;
    while (mirror[off] == off)
        ++off;
    uneven.vertices[off].z() += 1e-9;
    EXPECT_FALSE(BoneHeatSolver(uneven, bones, closest, {}, mirror).solvesMirrorSymmetric());
}

}  // namespace
}  // namespace rigmesh
