// Bad meshes: what is safe is repaired and said; what is not (pieces, large
// openings, crossing faces) is rigged on a wrapped proxy and said; only a
// mesh nothing can be rigged from is refused. The part keeps its mesh as
// it was given, every vertex weighted.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>

#include "AutoRigTestSupport.h"
#include "MeshInside.h"
#include "TestShapes.h"
#include "autorig/AutoRig.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

// A capsule-like rod along z: 2 units long, radius 0.3.
TriMesh rod() {
    return makeCylinderTube(24, 24, 0.3, 2.0);
}

Part unrigged(TriMesh mesh) {
    Part part;
    part.name = "Rod";
    part.mesh = std::move(mesh);
    return part;
}

bool said(const AutoRigResult& result, MessageId id) {
    return std::any_of(result.repairs.begin(), result.repairs.end(),
                       [&](const Message& m) { return m.id == id; });
}

MessageId refusal(const TriMesh& mesh) {
    try {
        autoRigPart(unrigged(mesh));
    } catch (const Error& error) {
        return error.message().id;
    }
    return MessageId::None;
}

// The rig holds on the mesh as given: same vertices and faces, a valid
// tree inside the surface it was computed on, every vertex's weights
// positive and summing to 1.
void expectRiggedAsGiven(const AutoRigResult& result, const TriMesh& given) {
    EXPECT_EQ(result.part.mesh.vertices, given.vertices);
    std::vector<std::array<int, 3>> shown = given.faces;  // faces that repeat a corner show nothing
    std::erase_if(shown, [](const std::array<int, 3>& f) {
        return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
    });
    EXPECT_EQ(result.part.mesh.faces, shown);
    EXPECT_TRUE(result.part.validate().empty());
    EXPECT_GE(result.part.skeleton.boneCount(), 1);
    EXPECT_TRUE(analyseMesh(result.rigSurface).isClosed());
    for (const Joint& joint : result.part.skeleton.joints())
        EXPECT_GT(parttest::windingNumber(result.rigSurface, joint.position), 0.5);
    autorigtest::expectPositiveWeightsSummingToOne(result.part.weights.perVertex,
                                                   given.vertexCount());
}

TEST(AutoRigRepair, AClosedRodIsRiggedWithoutRepairsAlongItsLength) {
    const TriMesh mesh = rod();
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_TRUE(result.repairs.empty());
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Input);
    const Skeleton& skeleton = result.part.skeleton;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Joint& joint : skeleton.joints()) {
        EXPECT_LT(joint.position.head<2>().norm(), 0.05);  // on the rod's axis
        low = std::min(low, joint.position.z());
        high = std::max(high, joint.position.z());
    }
    EXPECT_GT(high - low, 1.2);  // reaches well along the 2-unit rod
}

TEST(AutoRigRepair, SplitSeamsAreJoinedAndSaidAndCopiesShareWeights) {
    // Every face with its own three corners, as a careless exporter writes.
    const TriMesh closed = rod();
    TriMesh soup;
    std::vector<int> original;
    for (const auto& face : closed.faces) {
        const int first = soup.vertexCount();
        for (int corner : face) {
            soup.vertices.push_back(closed.vertices[corner]);
            original.push_back(corner);
        }
        soup.faces.push_back({first, first + 1, first + 2});
    }
    const AutoRigResult result = autoRigPart(unrigged(soup));
    expectRiggedAsGiven(result, soup);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Repaired);
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairWelded));
    EXPECT_EQ(result.rigSurface.vertexCount(), closed.vertexCount());
    // Copies of one vertex move together: a seam does not open when posed.
    std::vector<int> firstCopy(closed.vertices.size(), -1);
    for (int v = 0; v < soup.vertexCount(); ++v) {
        int& first = firstCopy[original[v]];
        if (first < 0)
            first = v;
        else
            EXPECT_EQ(result.part.weights.perVertex[v], result.part.weights.perVertex[first]);
    }
}

TEST(AutoRigRepair, InwardFacesAreTurnedOutward) {
    TriMesh mesh = rod();
    for (auto& face : mesh.faces)
        std::swap(face[1], face[2]);
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairFlipped));
    EXPECT_GT(analyseMesh(result.rigSurface).volume, 0.0);
}

TEST(AutoRigRepair, FacesWithoutAreaAndDuplicatesAndUnusedVerticesAreLeftOutOfTheRig) {
    TriMesh mesh = rod();
    mesh.faces.push_back({0, 0, 1});
    mesh.faces.push_back(mesh.faces.front());
    mesh.vertices.push_back(Vec3(5, 5, 5));
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairDegenerate));
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairDuplicateFaces));
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairUnusedVertices));
    EXPECT_EQ(result.rigSurface.vertexCount(), rod().vertexCount());
}

TEST(AutoRigRepair, ASmallHoleIsFilledInTheRigSurfaceOnly) {
    TriMesh mesh = rod();
    // Drop the faces around one vertex in the middle of the side.
    const int centre = 12 * 24 + 5;
    std::erase_if(mesh.faces, [&](const std::array<int, 3>& f) {
        return f[0] == centre || f[1] == centre || f[2] == centre;
    });
    ASSERT_FALSE(analyseMesh(mesh).isClosed());
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Repaired);
    EXPECT_TRUE(said(result, MessageId::AutoRigRepairHoles));
    EXPECT_TRUE(analyseMesh(result.rigSurface).isWatertightGenus0());
}

TEST(AutoRigRepair, ALargeOpeningIsRiggedOnAProxyAndSaidByName) {
    TriMesh mesh = rod();
    // Remove the whole cap at one end: a missing piece of the shape.
    const int capCentre = mesh.vertexCount() - 1;
    std::erase_if(mesh.faces, [&](const std::array<int, 3>& f) {
        return f[0] == capCentre || f[1] == capCentre || f[2] == capCentre;
    });
    ASSERT_FALSE(analyseMesh(mesh).isClosed());
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
    ASSERT_TRUE(said(result, MessageId::AutoRigOpenBorder));
    const auto open =
        std::find_if(result.repairs.begin(), result.repairs.end(),
                     [](const Message& m) { return m.id == MessageId::AutoRigOpenBorder; });
    EXPECT_EQ(open->args, (std::vector<std::string>{"1", "24"}));
    EXPECT_TRUE(said(result, MessageId::AutoRigProxyWrapped));
}

TEST(AutoRigRepair, SeveralPiecesAreRiggedTogetherOnAProxy) {
    TriMesh mesh = rod();
    TriMesh other = rod();
    for (Vec3& v : other.vertices)
        v.x() += 2.0;
    testshapes::append(mesh, other);
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
    const auto pieces =
        std::find_if(result.repairs.begin(), result.repairs.end(),
                     [](const Message& m) { return m.id == MessageId::AutoRigSeveralPieces; });
    ASSERT_NE(pieces, result.repairs.end());
    EXPECT_NE(englishText(*pieces).find("2 separate pieces"), std::string::npos);
}

TEST(AutoRigRepair, PiecesTouchingAtAVertexAreRiggedOnAProxy) {
    // Two tetrahedra sharing one corner: not a manifold there.
    TriMesh mesh = testshapes::tetrahedron();
    TriMesh other = testshapes::tetrahedron(Vec3(-1, -1, -1) + Vec3::Zero());
    for (Vec3& v : other.vertices)
        v = -v;  // mirrored through the shared corner (the origin)
    for (auto& face : other.faces)
        std::swap(face[1], face[2]);
    testshapes::append(mesh, other);
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
}

TEST(AutoRigRepair, ASelfIntersectingMeshIsRiggedOnAProxyAndTheCrossingsSaid) {
    TriMesh mesh = rod();
    // Push one side vertex through the rod and out of the far side.
    const int v = 12 * 24 + 5;
    mesh.vertices[v] = -mesh.vertices[v] * 2.0 + Vec3(0, 0, 2 * mesh.vertices[v].z());
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
    EXPECT_TRUE(said(result, MessageId::AutoRigSelfIntersecting));
}

TEST(AutoRigRepair, ASingleTriangleIsRiggedAsASheetWithVolume) {
    TriMesh mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.faces = {{0, 1, 2}};
    const AutoRigResult result = autoRigPart(unrigged(mesh));
    expectRiggedAsGiven(result, mesh);
    EXPECT_EQ(result.surfaceKind, RigSurface::Kind::Proxy);
}

TEST(AutoRigRepair, OnlyFacesWithoutThreeCornersAreRefused) {
    TriMesh mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.faces = {{0, 0, 1}, {2, 2, 2}};
    EXPECT_EQ(refusal(mesh), MessageId::AutoRigTooFewFaces);
}

TEST(AutoRigRepair, CorruptPositionsAndIndicesAreRefused) {
    TriMesh mesh = rod();
    mesh.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(refusal(mesh), MessageId::AutoRigNotFinite);
    TriMesh outOfRange = rod();
    outOfRange.faces[7][1] = outOfRange.vertexCount();
    EXPECT_EQ(refusal(outOfRange), MessageId::AutoRigFaceOutOfRange);
}

TEST(AutoRigRepair, AMeshOverTheMemoryBudgetIsRefused) {
    AutoRigOptions options;
    options.surface.memoryBudgetBytes = 1024.0;
    try {
        autoRigPart(unrigged(rod()), options);
        FAIL() << "a mesh over the budget was rigged";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::AutoRigOverMemoryBudget);
    }
}

TEST(AutoRigRepair, AMeshWithAHandleGetsATree) {
    const AutoRigResult result = autoRigPart(unrigged(testshapes::torus(48, 16, 1.0, 0.3)));
    EXPECT_TRUE(result.part.validate().empty());
    EXPECT_TRUE(result.part.skeleton.validate().empty());
    EXPECT_GE(result.part.skeleton.boneCount(), 3);
}

TEST(AutoRig, ARiggedPartIsRefusedAndLeftAsItIs) {
    Part part = autoRigPart(unrigged(rod())).part;
    const Part before = part;
    try {
        autoRigPart(part);
        FAIL() << "a rigged part was rigged again";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::AutoRigPartIsRigged);
    }
    EXPECT_EQ(part.skeleton.boneCount(), before.skeleton.boneCount());
    EXPECT_EQ(part.weights, before.weights);
}

TEST(AutoRig, TheSameMeshGivesTheSameRigWhateverTheHeapHolds) {
    const TriMesh mesh = testshapes::torus(40, 12, 1.0, 0.35);
    const AutoRigResult first = autoRigPart(unrigged(mesh));
    // Scatter the heap: blocks of many sizes, every other one freed.
    std::vector<std::unique_ptr<char[]>> blocks;
    for (int i = 0; i < 20000; ++i)
        blocks.emplace_back(new char[16 + (i * 7919) % 512]);
    for (std::size_t i = 0; i < blocks.size(); i += 2)
        blocks[i].reset();
    const AutoRigResult second = autoRigPart(unrigged(mesh));
    ASSERT_EQ(second.part.skeleton.jointCount(), first.part.skeleton.jointCount());
    for (int j = 0; j < first.part.skeleton.jointCount(); ++j)
        EXPECT_EQ(second.part.skeleton.joints()[j].position,
                  first.part.skeleton.joints()[j].position);
    EXPECT_EQ(second.part.weights, first.part.weights);
}

TEST(AutoRig, ProgressRisesToOneAndCancelStops) {
    std::vector<double> reported;
    autoRigPart(unrigged(rod()), {}, [&](double fraction) {
        reported.push_back(fraction);
        return true;
    });
    ASSERT_GE(reported.size(), 4u);
    EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
    EXPECT_EQ(reported.front(), 0.0);
    EXPECT_EQ(reported.back(), 1.0);

    int calls = 0;
    try {
        autoRigPart(unrigged(rod()), {},
                    [&](double fraction) { return ++calls < 3 || fraction < 0; });
        FAIL() << "a cancelled rig finished";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::AutoRigCancelled);
    }
    EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace rigmesh
