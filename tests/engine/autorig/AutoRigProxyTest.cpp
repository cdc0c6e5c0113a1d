// Rigging on a wrapped proxy (autorig/RigSurface, ProxyWrap, WeightTransfer):
// the proxy is closed around any soup, small floating pieces follow one
// bone, a blob gets one chain along its main axis, a mesh too large to flow
// directly is rigged on a proxy, and every region stays near a bone.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "AutoRigTestSupport.h"
#include "TestShapes.h"
#include "autorig/AutoRig.h"
#include "autorig/AxisChain.h"
#include "autorig/ProxyWrap.h"
#include "io/SceneImport.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/MeshTopologyCheck.h"

namespace rigmesh {
namespace {

Part unrigged(TriMesh mesh) {
    Part part;
    part.name = "Figure";
    part.mesh = std::move(mesh);
    return part;
}

bool said(const AutoRigResult& result, MessageId id) {
    return std::any_of(result.repairs.begin(), result.repairs.end(),
                       [&](const Message& m) { return m.id == id; });
}

double diagonalOf(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box.diagonal().norm();
}

TEST(ProxyWrap, AnOpenSheetIsWrappedIntoAClosedManifoldVolume) {
    // A square sheet of 2 x 2 units: no volume at all.
    TriMesh sheet;
    const int n = 10;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            sheet.vertices.push_back(Vec3(2.0 * i / n, 2.0 * j / n, 0.0));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * (n + 1) + j;
            sheet.faces.push_back({a, a + n + 1, a + 1});
            sheet.faces.push_back({a + 1, a + n + 1, a + n + 2});
        }
    const ProxyWrapResult wrap = wrapIntoProxy(sheet);
    const MeshReport report = analyseMesh(wrap.mesh, true);
    EXPECT_TRUE(report.isClosed());
    EXPECT_TRUE(report.isManifold());
    EXPECT_EQ(report.components, 1);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
    EXPECT_GT(report.volume, 0.0);
    const double diagonal = diagonalOf(sheet);
    EXPECT_GE(wrap.alpha, diagonal / 90.0 - 1e-12);
    EXPECT_LE(wrap.alpha, diagonal / 30.0 + 1e-12);
    EXPECT_DOUBLE_EQ(wrap.offset, wrap.alpha / 10.0);
}

TEST(AutoRigProxy, ASmallPieceBesideTheBodyFollowsOneBoneAsAWhole) {
    // A rod with an "eye" floating beside its upper end.
    TriMesh mesh = makeCylinderTube(24, 24, 0.3, 2.0);
    const int body = mesh.vertexCount();
    TriMesh eye = makeIcosphere(2, 0.08);
    for (Vec3& v : eye.vertices)
        v += Vec3(0.35, 0.0, 1.6);
    testshapes::append(mesh, eye);
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
    EXPECT_EQ(result.floatingPieces, 1);
    EXPECT_TRUE(said(result, MessageId::AutoRigPiecesFollowBone));
    const auto& weights = result.part.weights.perVertex;
    std::set<BoneId> eyeBones;
    for (int v = body; v < mesh.vertexCount(); ++v) {
        ASSERT_EQ(weights[v].size(), 1u);
        EXPECT_EQ(weights[v].front().second, 1.0);
        eyeBones.insert(weights[v].front().first);
    }
    EXPECT_EQ(eyeBones.size(), 1u);
}

TEST(AutoRigProxy, ABlobWithoutBranchesGetsOneChainAlongItsMainAxis) {
    // An egg: a sphere stretched along x, no limbs. (Its radius, 19% of the
    // diagonal, is farther from any chain than the 15% coverage rule.)
    TriMesh egg = makeIcosphere(3, 1.0);
    for (Vec3& v : egg.vertices)
        v.x() *= 2.2;
    const AutoRigResult result = autoRigPart(unrigged(egg));
    const Skeleton& skeleton = result.part.skeleton;
    EXPECT_EQ(autorigtest::leafCount(skeleton), 2);
    double low = 1e9, high = -1e9;
    for (const Joint& joint : skeleton.joints()) {
        EXPECT_LE(skeleton.degree(joint.id), 2);
        EXPECT_LT(joint.position.tail<2>().norm(), 0.1);  // on the long axis
        low = std::min(low, joint.position.x());
        high = std::max(high, joint.position.x());
    }
    EXPECT_GT(high - low, 2.2);  // along at least half of the 4.4-unit egg
}

// A closed box of 8 corners, 2 x 1 x 1, outward.
TriMesh box() {
    TriMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back(Vec3(i & 1 ? 2.0 : 0.0, i & 2 ? 1.0 : 0.0, i & 4 ? 1.0 : 0.0));
    mesh.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                  {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return mesh;
}

// Meshes so coarse that the flow contracts them to a point or a stub and
// bone heat has a value per corner only (a box, a tetrahedron: edges longer
// than a tenth of the diagonal) are rigged on a proxy, said so, and get
// bones inside them, never a refusal.
TEST(AutoRigProxy, ACoarseMeshIsRiggedOnAProxyWithBonesInsideAndSaid) {
    for (const TriMesh& mesh : {box(), testshapes::tetrahedron()}) {
        const AutoRigResult result = autoRigPart(unrigged(mesh));
        EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
        EXPECT_TRUE(said(result, MessageId::AutoRigCoarseMesh));
        EXPECT_EQ(result.part.mesh.vertices, mesh.vertices);
        const Skeleton& skeleton = result.part.skeleton;
        ASSERT_GE(skeleton.boneCount(), 1);
        EXPECT_TRUE(skeleton.validate().empty());
        EXPECT_EQ(autorigtest::bonePointsOutside(result.part), 0);
        autorigtest::expectPositiveWeightsSummingToOne(result.part.weights.perVertex,
                                                       mesh.vertexCount());
    }
}

TEST(AutoRigProxy, AMeshOverTheDirectLimitIsRiggedOnAProxyAndSaid) {
    const TriMesh mesh = makeCylinderTube(24, 24, 0.3, 2.0);
    AutoRigOptions options;
    options.surface.directVertexLimit = mesh.vertexCount() - 1;
    const AutoRigResult result = autoRigPart(unrigged(mesh), options);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
    EXPECT_TRUE(said(result, MessageId::AutoRigLargeMesh));
    EXPECT_TRUE(said(result, MessageId::AutoRigProxyWrapped));
    EXPECT_EQ(result.part.mesh.vertices, mesh.vertices);
    EXPECT_LE(farthestFromBones(mesh, result.part.skeleton), 0.15 * diagonalOf(mesh));
}

// The figure made in Blender from crossing primitives (tests/data/autorig,
// made by tests/external/make_blender_meshes.py): legs of separate
// cylinders whose soles come within 0.11 of each other, every piece's
// vertices in the file's order.
TriMesh blenderPrimitives() {
    TriMesh joined;
    for (const ImportedPart& part : importScene(RIGMESH_TEST_DATA "/autorig/primitives.obj").parts)
        testshapes::append(joined, part.part.mesh);
    return joined;
}

// Each vertex's piece: connected by faces over vertices at one place.
std::vector<int> piecesOf(const TriMesh& mesh) {
    std::vector<int> piece(mesh.vertices.size());
    std::iota(piece.begin(), piece.end(), 0);
    const auto find = [&](int v) {
        while (piece[v] != v)
            v = piece[v] = piece[piece[v]];
        return v;
    };
    const auto join = [&](int a, int b) { piece[find(a)] = find(b); };
    for (const auto& face : mesh.faces) {
        join(face[0], face[1]);
        join(face[1], face[2]);
    }
    std::map<std::array<double, 3>, int> first;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        const Vec3& p = mesh.vertices[v];
        const auto [at, added] = first.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, v);
        if (!added)
            join(v, at->second);
    }
    for (int v = 0; v < mesh.vertexCount(); ++v)
        piece[v] = find(v);
    return piece;
}

// A gap narrower than alpha between two pieces joined elsewhere (the soles
// of two legs hanging from one body) closes a loop the pieces do not: the
// wrap has a handle. It is wrapped again finer until the handle is gone.
TEST(ProxyWrap, AHandleAGapBetweenPiecesMadeIsWrappedAwayFiner) {
    const TriMesh figure = blenderPrimitives();
    const ProxyWrapResult wrap = wrapIntoProxy(figure);
    EXPECT_EQ(wrap.handles, 0);
    EXPECT_EQ(wrap.components, 1);
    EXPECT_GT(wrap.wraps, 1);
    EXPECT_LT(wrap.alpha, chooseWrapAlpha(figure, {}));
    const MeshReport report = analyseMeshTopology(wrap.mesh);
    EXPECT_TRUE(report.isWatertightGenus0());
}

// A handle of the shape itself stays at every alpha: the first, coarsest
// wrap is kept.
TEST(ProxyWrap, AHandleOfTheShapeItselfKeepsTheFirstAlpha) {
    const TriMesh ring = testshapes::torus(48, 16, 1.0, 0.3);
    const ProxyWrapResult wrap = wrapIntoProxy(ring);
    EXPECT_EQ(wrap.handles, 1);
    EXPECT_EQ(wrap.components, 1);
    EXPECT_DOUBLE_EQ(wrap.alpha, chooseWrapAlpha(ring, {}));
}

// The same figure rigged: each leg's sole is weighted by bones no vertex of
// the other sole is (on a proxy that bridged the soles, each leg's heat
// reached the other foot).
TEST(AutoRigProxy, LegsWhoseSolesAlmostTouchMoveOnlyTheirOwnFoot) {
    const TriMesh figure = blenderPrimitives();
    const AutoRigResult result = autoRigPart(unrigged(figure));
    const std::vector<int> piece = piecesOf(figure);
    // The two legs: the pieces of the two lowest vertices on either side.
    std::map<int, double> lowest;  // piece -> its lowest y
    for (int v = 0; v < figure.vertexCount(); ++v) {
        const auto [at, added] = lowest.emplace(piece[v], figure.vertices[v].y());
        if (!added)
            at->second = std::min(at->second, figure.vertices[v].y());
    }
    std::vector<std::pair<double, int>> byLowest;
    for (const auto& [p, y] : lowest)
        byLowest.emplace_back(y, p);
    std::sort(byLowest.begin(), byLowest.end());
    ASSERT_GE(byLowest.size(), 2u);
    std::array<std::set<BoneId>, 2> soleBones;
    for (int leg = 0; leg < 2; ++leg) {
        const auto [y, p] = byLowest[leg];
        for (int v = 0; v < figure.vertexCount(); ++v)
            if (piece[v] == p && figure.vertices[v].y() < y + 0.05)
                for (const auto& [bone, weight] : result.part.weights.perVertex[v])
                    soleBones[leg].insert(bone);
        ASSERT_FALSE(soleBones[leg].empty());
    }
    std::vector<BoneId> shared;
    std::set_intersection(soleBones[0].begin(), soleBones[0].end(), soleBones[1].begin(),
                          soleBones[1].end(), std::back_inserter(shared));
    EXPECT_TRUE(shared.empty()) << shared.size() << " bones weight both soles";
}

}  // namespace
}  // namespace rigmesh
