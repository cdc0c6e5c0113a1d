// Random merges and cuts: whatever the placement or plane, the result is a
// valid rigged part (or two) or an Error with a message; never a crash and
// never an invalid part.
#include <random>

#include "MergeTestSupport.h"
#include "base/Error.h"
#include "cut/CutPart.h"

namespace rigmesh::mergetest {
namespace {

TEST(MergeRandom, EveryRandomMergeIsValidOrRefused) {
    std::mt19937 random(20261124);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const std::vector<std::string> sketches{"biped", "banana", "tube", "y_branch", "camel_leg"};
    int merged = 0, refused = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const Part& target = sharedSketchPart(sketches[trial % sketches.size()]);
        Part dragged = rotated(sharedSketchPart(sketches[(trial / 2 + 1) % sketches.size()]),
                               Vec3(unit(random), unit(random), unit(random)), 3.0 * unit(random));
        const JointId anchor = target.skeleton.joints()[trial % target.skeleton.jointCount()].id;
        dragged = translated(dragged, target.skeleton.joint(anchor).position +
                                          0.3 * Vec3(unit(random), unit(random), unit(random)) -
                                          dragged.skeleton.joints().front().position);
        MergeRequest request;
        request.join.mode = static_cast<MergeMode>(trial % 3);
        request.join.draggedJoint = dragged.skeleton.joints().front().id;
        request.join.targetJoint = anchor;
        request.join.targetBone = target.skeleton.bones()[trial % target.skeleton.boneCount()].id;
        request.join.splitPoint = target.skeleton.joint(anchor).position;
        try {
            const MergeResult result = mergeParts(target, dragged, request);
            EXPECT_TRUE(result.part.validateSolid().empty()) << "trial " << trial;
            ++merged;
        } catch (const Error& e) {
            EXPECT_GT(std::string(e.what()).size(), 10u) << "trial " << trial;
            ++refused;
        }
    }
    EXPECT_GT(merged, 12) << refused << " refused";
}

TEST(CutRandom, EveryRandomPlaneGivesValidPiecesOrARefusal) {
    std::mt19937 random(1124);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int cut = 0;
    for (const std::string& sketch : testsupport::sharedSketchNames(false)) {
        const Part& part = sharedSketchPart(sketch);
        Eigen::AlignedBox3d box;
        for (const Vec3& v : part.mesh.vertices)
            box.extend(v);
        for (int trial = 0; trial < 4; ++trial) {
            CutRequest request;
            request.point = box.center() +
                            0.4 * box.sizes().cwiseProduct(Vec3(unit(random), unit(random), 0.0));
            request.normal = Vec3(unit(random), unit(random), 0.3 * unit(random));
            request.style = trial % 2 ? CutStyle::Sharp : CutStyle::Smooth;
            try {
                const CutResult result = cutPart(part, request);
                for (const Part& piece : result.pieces)
                    EXPECT_TRUE(piece.validateSolid().empty()) << sketch << " trial " << trial;
                ++cut;
            } catch (const Error& e) {
                EXPECT_GT(std::string(e.what()).size(), 10u) << sketch;
            }
        }
    }
    EXPECT_GT(cut, 10);
}

}  // namespace
}  // namespace rigmesh::mergetest
