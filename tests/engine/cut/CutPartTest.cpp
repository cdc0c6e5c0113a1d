// Cutting a rigged part by a plane (paper 3.1): every shared sketch cut
// across its width at three places in both styles gives two closed,
// manifold, genus-0 rigged pieces whose volumes add up to the part's, or is
// refused with a message; untouched vertices keep their positions.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "SharedSketchPart.h"
#include "base/Error.h"
#include "cut/CutPart.h"
#include "mesh/MeshChecks.h"

namespace rigmesh {
namespace {

struct CutCase {
    std::string sketch;
    double at;  // along the bounding box's longer side, 0..1
    CutStyle style;
};

Eigen::AlignedBox3d boxOf(const TriMesh& mesh) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v);
    return box;
}

CutRequest planeAcross(const Part& part, double at, CutStyle style) {
    const Eigen::AlignedBox3d box = boxOf(part.mesh);
    const int axis = box.sizes().x() >= box.sizes().y() ? 0 : 1;
    CutRequest request;
    request.point = box.min() + at * box.sizes();
    // Slightly tilted, so no plane runs along a sketch's symmetry.
    request.normal = Vec3::Unit(axis) + 0.1 * Vec3::Unit(1 - axis);
    request.style = style;
    return request;
}

class CutSharedSketch : public testing::TestWithParam<CutCase> {};

TEST_P(CutSharedSketch, GivesTwoValidPiecesOrARefusal) {
    const CutCase& c = GetParam();
    const Part& part = testsupport::sharedSketchPart(c.sketch);
    CutResult result;
    try {
        result = cutPart(part, planeAcross(part, c.at, c.style));
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_TRUE(message.find("more than once") != std::string::npos ||
                    message.find("without a bone") != std::string::npos)
            << message;
        return;
    }
    double volume = 0.0;
    int patchVertices = 0;
    for (int k = 0; k < 2; ++k) {
        const Part& piece = result.pieces[k];
        const MeshReport report = analyseMesh(piece.mesh, true);
        EXPECT_TRUE(report.isWatertightGenus0()) << "piece " << k;
        EXPECT_TRUE(report.isOutwardOriented()) << "piece " << k;
        EXPECT_EQ(report.selfIntersectingFacePairs, 0) << "piece " << k;
        const auto problems = piece.validateSolid();
        EXPECT_TRUE(problems.empty()) << englishText(problems);
        volume += report.volume;
        patchVertices += static_cast<int>(result.patches[k].size());
        // Untouched vertices keep their positions bit for bit.
        for (int v = 0; v < piece.mesh.vertexCount(); ++v) {
            const VertexSource& s = result.sources[k][v];
            if (s.kind == VertexSource::Kind::Vertex) {
                ASSERT_EQ(piece.mesh.vertices[v], part.mesh.vertices[s.index]);
            }
        }
    }
    const double whole = analyseMesh(part.mesh, false).volume;
    if (c.style == CutStyle::Sharp) {
        // Flat patches: the pieces share the part's volume exactly.
        EXPECT_NEAR(volume / whole, 1.0, 1e-6);
    } else {
        // A smooth patch bulges (Fig. 7 middle), by less than a hemisphere
        // on a disc of the hole's area for each patch.
        double bulge = 0.0;
        for (int k = 0; k < 2; ++k) {
            const Part& piece = result.pieces[k];
            std::vector<char> patch(piece.mesh.vertexCount(), 0);
            for (int v : result.patches[k])
                patch[v] = 1;
            double area = 0.0;
            for (const auto& f : piece.mesh.faces)
                if (patch[f[0]] || patch[f[1]] || patch[f[2]])
                    area += 0.5 * (piece.mesh.vertices[f[1]] - piece.mesh.vertices[f[0]])
                                      .cross(piece.mesh.vertices[f[2]] - piece.mesh.vertices[f[0]])
                                      .norm();
            bulge += 2.0 / 3.0 * std::pow(area, 1.5) / std::sqrt(M_PI);
        }
        EXPECT_GE(volume, whole * (1.0 - 1e-6));
        EXPECT_LE(volume - whole, bulge);
    }
    EXPECT_GT(patchVertices, 0);
    // Each piece keeps one tree; every bone went to a piece (split ones in
    // two halves, one per piece).
    for (const Part& piece : result.pieces) {
        EXPECT_TRUE(piece.skeleton.validate().empty());
        EXPECT_GT(piece.skeleton.boneCount(), 0);
    }
    EXPECT_GE(result.pieces[0].skeleton.boneCount() + result.pieces[1].skeleton.boneCount(),
              part.skeleton.boneCount());
}

std::vector<CutCase> cutCases() {
    std::vector<CutCase> list;
    for (const std::string& sketch : testsupport::sharedSketchNames(false))
        for (double at : {0.3, 0.5, 0.7})
            for (CutStyle style : {CutStyle::Smooth, CutStyle::Sharp})
                list.push_back({sketch, at, style});
    return list;
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, CutSharedSketch, testing::ValuesIn(cutCases()),
                         [](const testing::TestParamInfo<CutCase>& param) {
                             return param.param.sketch + "_" +
                                    std::to_string(static_cast<int>(param.param.at * 100)) +
                                    (param.param.style == CutStyle::Smooth ? "_smooth" : "_sharp");
                         });

TEST(CutRefusals, APlaneBesideThePartIsRefused) {
    const Part& part = testsupport::sharedSketchPart("tube");
    CutRequest request = planeAcross(part, 0.5, CutStyle::Smooth);
    request.point += 100.0 * request.normal;
    try {
        cutPart(part, request);
        FAIL() << "cut a plane that misses the part";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("does not cross"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rigmesh

#include "merge/MergeParts.h"

namespace rigmesh {
namespace {

// Cut then merge back (paper 3.3's way of refining a bone): the two smooth
// pieces, snapped at the joint the cut made, merge into one valid part.
TEST(CutThenMerge, TheTwoPiecesOfACutMergeBackIntoOneValidPart) {
    for (const std::string sketch : {"tube", "banana", "camel_leg"}) {
        SCOPED_TRACE(sketch);
        const Part& part = testsupport::sharedSketchPart(sketch);
        const CutResult cut = cutPart(part, planeAcross(part, 0.5, CutStyle::Smooth));
        // The joint both pieces share: made by the cut, at the same place.
        JointId shared = kNoJoint;
        for (const Joint& joint : cut.pieces[0].skeleton.joints())
            if (!part.skeleton.hasJoint(joint.id) && cut.pieces[1].skeleton.hasJoint(joint.id))
                shared = joint.id;
        ASSERT_NE(shared, kNoJoint);
        MergeRequest request;
        request.join.mode = MergeMode::Snap;
        request.join.draggedJoint = shared;
        request.join.targetJoint = shared;
        const MergeResult merged = mergeParts(cut.pieces[0], cut.pieces[1], request);
        EXPECT_TRUE(merged.part.validateSolid().empty());
        EXPECT_TRUE(analyseMesh(merged.part.mesh, false).isWatertightGenus0());
        EXPECT_EQ(merged.draggedTranslation, Vec3::Zero());
    }
}

}  // namespace
}  // namespace rigmesh

#include "cut/CutSurface.h"

namespace rigmesh {
namespace {

// Paper 3.1: a curved stroke cuts along the surface it sweeps in the view
// direction. A "<" across each part, swept along z: two valid pieces whose
// flat patch lies on that bent surface, not on a plane.
TEST(CurvedCut, ABentStrokeCutsAlongTheSurfaceItSweeps) {
    for (const std::string sketch : {"tube", "banana", "camel_body"}) {
        SCOPED_TRACE(sketch);
        const Part& part = testsupport::sharedSketchPart(sketch);
        const Eigen::AlignedBox3d box = boxOf(part.mesh);
        const bool wide = box.sizes().x() >= box.sizes().y();
        // Across the shorter side, bending by a quarter of the part's width.
        const double across = wide ? box.sizes().y() : box.sizes().x();
        auto at = [&](double along, double side) {
            const Vec3 c = box.center();
            return wide ? Vec3(c.x() + along, c.y() + side, 0.0)
                        : Vec3(c.x() + side, c.y() + along, 0.0);
        };
        CutRequest request;
        request.style = CutStyle::Sharp;
        request.sweep = Vec3::UnitZ();
        const double bend = 0.25 * across;
        for (int i = 0; i <= 8; ++i) {
            const double s = -0.75 * across + 1.5 * across * i / 8.0;
            request.stroke.push_back(at(bend * (1.0 - std::abs(s) / (0.75 * across)), s));
        }
        const CutResult cut = cutPart(part, request);
        const CutSurface surface = CutSurface::swept(request.stroke, request.sweep);
        const Vec3 chordNormal =
            (request.stroke.back() - request.stroke.front()).cross(Vec3::UnitZ()).normalized();
        double offChord = 0.0;
        for (int k = 0; k < 2; ++k) {
            const Part& piece = cut.pieces[k];
            const MeshReport report = analyseMesh(piece.mesh, true);
            EXPECT_TRUE(report.isWatertightGenus0());
            EXPECT_EQ(report.selfIntersectingFacePairs, 0);
            EXPECT_TRUE(piece.validateSolid().empty());
            for (int v : cut.patches[k]) {
                EXPECT_LT(std::abs(surface.side(piece.mesh.vertices[v])), 1e-6 * across);
                offChord = std::max(offChord, std::abs(chordNormal.dot(piece.mesh.vertices[v] -
                                                                       request.stroke.front())));
            }
        }
        EXPECT_GT(offChord, 0.1 * bend) << "the patch follows the bent stroke";
        const double whole = analyseMesh(part.mesh, false).volume;
        EXPECT_NEAR((analyseMesh(cut.pieces[0].mesh, false).volume +
                     analyseMesh(cut.pieces[1].mesh, false).volume) /
                        whole,
                    1.0, 1e-6);
    }
}

// Paper 3.1 with Blender's knife: only the surface where the stroke was
// drawn cuts. A short stroke across the biped's upper arm, whose line
// extended would also cross the hip, takes the arm off: two pieces, the
// larger the body with the legs, the arm's bones on the smaller one.
TEST(CutNearTheStroke, AStrokeAcrossTheUpperArmTakesTheArmOff) {
    const Part& biped = testsupport::sharedSketchPart("biped");
    CutRequest request;
    request.sweep = Vec3::UnitZ();
    request.stroke = {Vec3(0.9, 0.65, 0.0), Vec3(1.15, 1.55, 0.0)};
    // The line through the stroke meets the hip further down: as a plane
    // this cut makes three pieces and is refused.
    CutRequest plane;
    plane.point = request.stroke.front();
    plane.normal = (request.stroke.back() - request.stroke.front()).cross(Vec3::UnitZ());
    try {
        cutPart(biped, plane);
        ADD_FAILURE() << "the plane through the stroke crosses the biped once only";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::CutCrossesTwice);
    }

    const CutResult cut = cutPart(biped, request);
    const int body = cut.larger();
    const Part& arm = cut.pieces[1 - body];
    EXPECT_GT(cut.volumes[body], 5.0 * cut.volumes[1 - body]);
    for (int k = 0; k < 2; ++k) {
        EXPECT_TRUE(analyseMesh(cut.pieces[k].mesh, true).isWatertightGenus0());
        EXPECT_TRUE(cut.pieces[k].validateSolid().empty());
    }
    // The arm piece lies right of the stroke, the body keeps the rest.
    for (const Vec3& v : arm.mesh.vertices)
        EXPECT_GT(v.x(), 0.75);
    const Eigen::AlignedBox3d bodyBox = boxOf(cut.pieces[body].mesh);
    EXPECT_LT(bodyBox.min().y(), -2.0);  // the legs
    EXPECT_GT(bodyBox.max().y(), 2.9);   // the head
    EXPECT_LT(bodyBox.max().x(), 1.2);   // not the hand
    // The volumes add up: nothing else was cut.
    EXPECT_NEAR((cut.volumes[0] + cut.volumes[1]) / analyseMesh(biped.mesh, false).volume, 1.0,
                0.02);
}

}  // namespace
}  // namespace rigmesh
