// X-mirror weight painting vertex by vertex (part/WeightPaint, rig/VertexMirror),
// as Blender's X-mirror does it: every vertex a dab changes passes the same
// change to its partner across the part's mirror plane, on the bone's image.
// On a surface that is not exactly symmetric (a symmetric outline's surface
// with its vertices jittered by a tenth of an edge) every painted pair ends
// with equal weights, bone by image bone, to 1e-9, whatever the brush, its
// falloff, locks, front faces only, or a dab across the plane.
#include <gtest/gtest.h>

#include <random>

#include "PartWeightOf.h"
#include "SharedSketchPart.h"
#include "SymmetricOutline.h"
#include "mesh/MeshAdjacency.h"
#include "part/WeightPaint.h"
#include "pipeline/SketchToPart.h"
#include "rig/VertexMirror.h"

namespace rigmesh {
namespace {

using testsupport::weightOf;

// The biped sketched from its outline made exactly symmetric, its vertices
// then moved at random by up to a tenth of the mean edge (seeded): no vertex
// lies exactly at another's reflection.
Part jitteredBiped() {
    Part part =
        sketchToPart(testsupport::symmetricOutline(testsupport::sharedSketchPart("biped").outline),
                     "biped")
            .part;
    const double step = 0.1 * meanEdgeLength(part.mesh);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> offset(-step, step);
    for (Vec3& v : part.mesh.vertices)
        v += Vec3(offset(random), offset(random), offset(random)) / std::sqrt(3.0);
    return part;
}

struct Mirrored {
    Part part;
    PartSymmetry symmetry;
    std::vector<int> partner;
};

// The jittered biped with its weights made left-right equal first: each
// pair's second vertex gets its first's weights on the image bones, a vertex
// on the plane the mean of each bone and its image.
Mirrored mirroredBiped() {
    Mirrored m{jitteredBiped(), {}, {}};
    const std::optional<PartSymmetry> symmetry = findPartSymmetry(m.part);
    EXPECT_TRUE(symmetry.has_value());
    m.symmetry = *symmetry;
    m.partner = mirrorVertices(m.part.mesh, m.symmetry.plane, vertexMirrorTolerance(m.part.mesh));
    auto& weights = m.part.weights.perVertex;
    for (int v = 0; v < m.part.mesh.vertexCount(); ++v) {
        const int p = m.partner[v];
        if (p == v) {
            WeightList even;
            for (const Bone& bone : m.part.skeleton.bones()) {
                const double w = 0.5 * (weightOf(m.part, v, bone.id) +
                                        weightOf(m.part, v, m.symmetry.imageOf(bone.id)));
                if (w > 0.0)
                    even.emplace_back(bone.id, w);
            }
            weights[v] = even;
        } else if (p > v) {
            WeightList image;
            for (const auto& [bone, w] : weights[v])
                image.emplace_back(m.symmetry.imageOf(bone), w);
            std::sort(image.begin(), image.end());
            weights[p] = image;
        }
    }
    EXPECT_TRUE(m.part.validate().empty());
    return m;
}

// The largest difference, over the pairs the dab changed, between a bone's
// weight at one vertex and its image's at the partner (every bone); the
// number of pairs compared in `compared`.
double largestMirrorDifference(const Mirrored& m, const Part& before, int& compared) {
    double largest = 0.0;
    compared = 0;
    for (int v = 0; v < m.part.mesh.vertexCount(); ++v) {
        const int p = m.partner[v];
        if (p == kNoMirrorVertex || m.part.weights.perVertex[v] == before.weights.perVertex[v])
            continue;
        ++compared;
        for (const Bone& bone : m.part.skeleton.bones())
            largest = std::max(largest, std::abs(weightOf(m.part, v, bone.id) -
                                                 weightOf(m.part, p, m.symmetry.imageOf(bone.id))));
    }
    return largest;
}

JointId rightmostJoint(const Skeleton& skeleton) {
    JointId hand = skeleton.joints().front().id;
    for (const Joint& joint : skeleton.joints())
        if (joint.position.x() > skeleton.joint(hand).position.x())
            hand = joint.id;
    return hand;
}

TEST(VertexMirror, PairsAJitteredSymmetricSurfaceMutuallyAndKeepsPlaneVerticesToThemselves) {
    const Mirrored m = mirroredBiped();
    const TriMesh& mesh = m.part.mesh;
    const double tolerance = vertexMirrorTolerance(mesh);
    int paired = 0, onPlane = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const int p = m.partner[v];
        if (p == kNoMirrorVertex)
            continue;
        ++paired;
        onPlane += p == v;
        EXPECT_EQ(m.partner[p], v) << "partners are mutual";
        const Vec3 reflected = m.symmetry.plane.reflect(mesh.vertices[v]);
        EXPECT_LE((mesh.vertices[p] - reflected).norm(), tolerance);
        // The partner is the vertex nearest the reflection (brute force).
        for (int w = 0; w < mesh.vertexCount(); ++w)
            ASSERT_GE((mesh.vertices[w] - reflected).norm(), (mesh.vertices[p] - reflected).norm())
                << v;
    }
    std::cout << paired << " of " << mesh.vertexCount() << " vertices paired, " << onPlane
              << " on the plane" << std::endl;
    // Measured: 3935 of 4708 (84%); without the jitter 4069 (86%), the hand
    // drawn biped 4191 of 4812 (87%): the two halves of a sketched surface
    // are not triangulated alike, and where a reflection lands between
    // vertices no one vertex is its image.
    EXPECT_GT(paired, 0.8 * mesh.vertexCount());
    EXPECT_GT(onPlane, 0);
}

// A dab on the right hand with X-mirror: every pair the dab changed has
// equal weights, bone by image bone, after Add, Subtract, Replace and
// Smooth, with each falloff and front faces only.
TEST(WeightMirrorPaint, EveryPaintedPairIsEqualOnAJitteredSurface) {
    const Mirrored start = mirroredBiped();
    const JointId hand = rightmostJoint(start.part.skeleton);
    const BoneId bone = *boneForJoint(start.part.skeleton, hand);
    ASSERT_NE(start.symmetry.imageOf(bone), bone);
    const Bone& forearm = start.part.skeleton.bone(bone);
    const Vec3 centre = 0.5 * (start.part.skeleton.joint(forearm.head).position +
                               start.part.skeleton.joint(forearm.tail).position);
    for (BrushMode mode :
         {BrushMode::Add, BrushMode::Subtract, BrushMode::Replace, BrushMode::Smooth})
        for (BrushFalloff falloff : {BrushFalloff::Smooth, BrushFalloff::Constant}) {
            Mirrored m = start;
            WeightPainter painter(m.part.mesh);
            WeightDab dab;
            dab.bone = bone;
            dab.mode = mode;
            dab.falloff = falloff;
            dab.value = 0.3;
            dab.strength = 0.7;
            dab.radius = 0.35;
            dab.mirror = true;
            dab.towardsViewer = Vec3(0.2, 0.1, 1.0);
            // A stroke of three dabs along the arm.
            int changed = 0, unpaired = 0;
            for (int k = 0; k < 3; ++k) {
                dab.centre = centre + Vec3(0.1 * (k - 1), 0.0, 0.0);
                const Part before = m.part;
                const DabResult result = painter.paint(m.part, dab);
                changed += static_cast<int>(result.changed.size());
                unpaired += result.unpaired;
                int compared = 0;
                EXPECT_LE(largestMirrorDifference(m, before, compared), 1e-9)
                    << static_cast<int>(mode) << " " << static_cast<int>(falloff) << " dab " << k;
                // Both sides changed: the dab's vertices and their partners.
                EXPECT_EQ(compared + result.unpaired, static_cast<int>(result.changed.size()));
            }
            EXPECT_GT(changed, 40) << static_cast<int>(mode);
            EXPECT_LT(unpaired, changed / 20 + 1) << static_cast<int>(mode);
            EXPECT_TRUE(m.part.validate().empty());
        }
}

// A dab across the plane: on the spine's bone (its own image) and on the
// right leg's bone at the crotch (a side bone, reaching both legs and the
// vertices on the plane). Pairs stay equal, the plane's vertices weigh the
// bone and its image alike.
TEST(WeightMirrorPaint, DabsAcrossThePlaneKeepPairsAndPlaneVerticesEqual) {
    const Mirrored start = mirroredBiped();
    const Skeleton& skeleton = start.part.skeleton;
    // The bone nearest the plane that is its own image, and the side bone
    // right of the plane whose head is nearest to it (a leg's at the
    // crotch, or an arm's at the shoulder).
    auto offPlane = [&](const Vec3& p) {
        return start.symmetry.plane.normal.dot(p - start.symmetry.plane.point);
    };
    BoneId middle = 0, side = 0;
    double nearest = 1e9, nearestSide = 1e9;
    for (const Bone& b : skeleton.bones()) {
        const Vec3& head = skeleton.joint(b.head).position;
        const Vec3& tail = skeleton.joint(b.tail).position;
        if (start.symmetry.imageOf(b.id) == b.id &&
            std::abs(offPlane(0.5 * (head + tail))) < nearest) {
            nearest = std::abs(offPlane(0.5 * (head + tail)));
            middle = b.id;
        }
        if (start.symmetry.imageOf(b.id) != b.id && offPlane(tail) > 0.0 &&
            std::abs(offPlane(head)) < nearestSide) {
            nearestSide = std::abs(offPlane(head));
            side = b.id;
        }
    }
    ASSERT_LT(nearest, 1e9);
    ASSERT_LT(nearestSide, 1e9);
    for (BoneId bone : {middle, side}) {
        Mirrored m = start;
        const Bone& b = skeleton.bone(bone);
        WeightDab dab;
        dab.bone = bone;
        dab.mode = BrushMode::Replace;
        dab.value = 0.5;
        dab.strength = 0.6;
        dab.mirror = true;
        // Centred a little right of the plane at the point of the bone
        // nearest it, wide enough to reach the other side.
        const Vec3& head = skeleton.joint(b.head).position;
        const Vec3& tail = skeleton.joint(b.tail).position;
        const Vec3 nearPlane = std::abs(offPlane(head)) < std::abs(offPlane(tail)) ? head : tail;
        // On the surface: the vertex nearest that point, moved to 0.05
        // right of the plane.
        const std::vector<Vec3>& vertices = m.part.mesh.vertices;
        Vec3 surface = vertices.front();
        for (const Vec3& v : vertices)
            if ((v - nearPlane).norm() < (surface - nearPlane).norm())
                surface = v;
        dab.centre = surface + (0.05 - offPlane(surface)) * start.symmetry.plane.normal;
        dab.radius = 0.4;
        const Part before = m.part;
        const DabResult result = paintWeights(m.part, dab);
        int compared = 0;
        EXPECT_LE(largestMirrorDifference(m, before, compared), 1e-9) << bone;
        EXPECT_GT(compared, 20) << bone;
        int planeChanged = 0, bothSides = 0;
        for (int v : result.changed) {
            planeChanged += m.partner[v] == v;
            // A vertex on the other side than the dab's centre the dab
            // reached itself.
            bothSides +=
                start.symmetry.plane.normal.dot(m.part.mesh.vertices[v] - dab.centre) < -0.1 &&
                (m.part.mesh.vertices[v] - dab.centre).norm() < dab.radius;
        }
        EXPECT_GT(planeChanged, 0) << bone;
        EXPECT_GT(bothSides, 0) << bone << ": the dab reached across the plane";
        EXPECT_TRUE(m.part.validate().empty());
    }
}

// Locks hold on both sides: with the right upper arm's bone and its image
// locked, a Replace stroke on the forearm leaves both bit for bit and the
// pairs equal.
TEST(WeightMirrorPaint, LockedBonesStayOnBothSidesAndPairsStayEqual) {
    Mirrored m = mirroredBiped();
    const Skeleton& skeleton = m.part.skeleton;
    const JointId hand = rightmostJoint(skeleton);
    const BoneId bone = *boneForJoint(skeleton, hand);
    const std::optional<BoneId> upper = skeleton.parentBone(bone);
    ASSERT_TRUE(upper.has_value());
    WeightDab dab;
    dab.bone = bone;
    dab.mode = BrushMode::Replace;
    dab.falloff = BrushFalloff::Constant;
    dab.strength = 1.0;
    dab.value = 0.9;
    dab.mirror = true;
    dab.locked = {*upper, m.symmetry.imageOf(*upper)};
    dab.centre = skeleton.joint(skeleton.bone(bone).head).position;
    dab.radius = 0.3;
    const Part before = m.part;
    const DabResult result = paintWeights(m.part, dab);
    ASSERT_FALSE(result.changed.empty());
    int compared = 0;
    EXPECT_LE(largestMirrorDifference(m, before, compared), 1e-9);
    EXPECT_GT(compared, 10);
    int lockedReached = 0;
    for (int v = 0; v < m.part.mesh.vertexCount(); ++v)
        for (BoneId locked : dab.locked) {
            ASSERT_EQ(weightOf(m.part, v, locked), weightOf(before, v, locked)) << v;
            lockedReached += m.part.weights.perVertex[v] != before.weights.perVertex[v] &&
                             weightOf(before, v, locked) > 0.0;
        }
    EXPECT_GT(lockedReached, 0) << "the dab reached the locked bones' vertices";
    EXPECT_TRUE(m.part.validate().empty());
}

}  // namespace
}  // namespace rigmesh
