// A merge keeps the dragged part's pose, pins and keys on its new joint ids
// where they still turn the same bones, and says what it dropped; undo restores both parts exactly
// and the history replays.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/commands/MergePartsCommand.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

const Eigen::Quaterniond kLegAtZero(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
const Eigen::Quaterniond kLegAtOne(Eigen::AngleAxisd(-0.4, Vec3::UnitZ()));
const Eigen::Quaterniond kLegNow(Eigen::AngleAxisd(0.2, Vec3(1, 1, 0).normalized()));
const Eigen::Quaterniond kBody(Eigen::AngleAxisd(0.1, Vec3::UnitZ()));

json rotations(const std::vector<JointId>& joints, const Eigen::Quaterniond& q) {
    json out = json::object();
    for (JointId joint : joints)
        out[std::to_string(joint)] = {q.w(), q.x(), q.y(), q.z()};
    return out;
}

// The camel body and a leg overlapping its front; the leg keyed at 0 and 1 s
// and posed, its root pinned; the body keyed at 0.5 s.
struct Scene {
    Document document;
    PartId body = kNoPart, leg = kNoPart;
    JointId legRoot = kNoJoint, legEnd = kNoJoint;
};

void build(Scene& s) {
    runSteps(s.document, {{{"command", "sketch"},
                           {"points", pointsOf(sharedStroke("camel_body"))},
                           {"name", "body"}},
                          {{"command", "sketch"},
                           {"points", pointsOf(sharedStroke("camel_leg"))},
                           {"name", "leg"},
                           {"placement", {{"translation", {1.7, -0.55, 0.3}}}}}});
    s.body = s.document.parts()[0].id;
    s.leg = s.document.parts()[1].id;
    const Skeleton& leg = s.document.part(s.leg).part->skeleton;
    ASSERT_EQ(leg.jointCount(), 2);
    s.legRoot = leg.root();
    for (const Joint& joint : leg.joints())
        if (joint.id != s.legRoot)
            s.legEnd = joint.id;
    const std::vector<JointId> both{s.legRoot, s.legEnd};
    runSteps(s.document,
             {{{"command", "pose"}, {"part", "leg"}, {"rotations", rotations(both, kLegAtZero)}},
              {{"command", "key"}, {"part", "leg"}, {"time", 0.0}},
              {{"command", "pose"}, {"part", "leg"}, {"rotations", rotations(both, kLegAtOne)}},
              {{"command", "key"}, {"part", "leg"}, {"time", 1.0}},
              {{"command", "pose"}, {"part", "leg"}, {"rotations", rotations(both, kLegNow)}},
              {{"command", "pin"}, {"part", "leg"}, {"joint", s.legRoot}},
              {{"command", "pose"}, {"part", "body"}, {"rotations", rotations({0}, kBody)}},
              {{"command", "key"}, {"part", "body"}, {"time", 0.5}}});
}

// A leg joint's place in the document (connect moves nothing).
Vec3 placeOf(const Document& document, PartId part, JointId joint) {
    const PartNode& node = document.part(part);
    return node.placement.rotation * node.part->skeleton.joint(joint).position +
           node.placement.translation;
}

// The merged part's joint at `at` (the body's placement is the identity).
JointId jointAt(const Part& merged, const Vec3& at) {
    for (const Joint& joint : merged.skeleton.joints())
        if ((joint.position - at).norm() < 1e-9)
            return joint.id;
    ADD_FAILURE() << "no merged joint at " << at.transpose();
    return kNoJoint;
}

std::unique_ptr<MergePartsCommand> connectAt(Scene& s, JointId legJoint) {
    MergeSpec spec;
    spec.mode = MergeMode::Connect;
    spec.draggedJoint = legJoint;
    spec.target = JointId{2};
    return MergePartsCommand::create(s.document, s.leg, s.body, spec);
}

// Connected by its root, the leg hangs from the body as it hung from its
// root: both rotations, the pin and both keys carry over onto the new ids.
TEST(MergeCarriesDraggedRig, ConnectedByItsRootTheLegKeepsItsPosePinAndKeys) {
    Scene s;
    build(s);
    const Vec3 rootAt = placeOf(s.document, s.leg, s.legRoot);
    const Vec3 endAt = placeOf(s.document, s.leg, s.legEnd);
    const Clip legClip = s.document.part(s.leg).clip;
    const Pose legPose = s.document.part(s.leg).pose;
    const Clip bodyClip = s.document.part(s.body).clip;
    const QByteArray before = bytesOf(s.document);
    const int steps = s.document.undoStack()->count();

    auto merge = connectAt(s, s.legRoot);
    const QString summary = merge->summary();
    s.document.undoStack()->push(merge.release());
    ASSERT_EQ(s.document.partCount(), 1);
    EXPECT_EQ(s.document.undoStack()->count(), steps + 1);
    EXPECT_TRUE(summary.contains(
        QStringLiteral("from leg: kept the rotations of 2 joint(s), 1 pin(s), 2 key(s)")))
        << summary.toStdString();
    EXPECT_FALSE(summary.contains(QStringLiteral("dropped"))) << summary.toStdString();

    const PartNode& merged = s.document.parts()[0];
    const JointId root = jointAt(*merged.part, rootAt);
    const JointId end = jointAt(*merged.part, endAt);
    // The leg root's rotation turned the whole leg; after the merge the root
    // ends the connecting bone, so it moves into the leg's bone (its world
    // rotation was the root's times its own). Same axes: bit for bit.
    auto legBone = [](const Pose& pose, JointId rootJoint, JointId endJoint) {
        return (pose.rotation(rootJoint) * pose.rotation(endJoint)).normalized();
    };
    EXPECT_FALSE(merged.pose.rotations.contains(root)) << "the connecting bone is not turned";
    EXPECT_EQ(merged.pose.rotation(end).coeffs(), legBone(legPose, s.legRoot, s.legEnd).coeffs());
    EXPECT_EQ(merged.pose.rotation(0).coeffs(), kBody.coeffs()) << "the body's own pose stays";
    EXPECT_TRUE(merged.pinnedJoints.contains(root));
    EXPECT_EQ(merged.clip.keyTimes(), (std::vector<double>{0.0, 0.5, 1.0}));
    for (double time : {0.0, 0.5, 1.0}) {
        const Pose& key = merged.clip.key(time);
        EXPECT_EQ(key.rotation(end).coeffs(),
                  legBone(legClip.evaluate(time), s.legRoot, s.legEnd).coeffs())
            << time;
        EXPECT_FALSE(key.rotations.contains(root)) << time;
        EXPECT_EQ(key.rotation(0).coeffs(), bodyClip.evaluate(time).rotation(0).coeffs()) << time;
    }
    EXPECT_EQ(merged.clip.key(1.0).rotation(end).coeffs(),
              (kLegAtOne * kLegAtOne).normalized().coeffs());

    // Undo gives both parts back exactly; redo and the history agree.
    const QByteArray after = bytesOf(s.document);
    s.document.undoStack()->undo();
    EXPECT_EQ(bytesOf(s.document), before);
    s.document.undoStack()->redo();
    EXPECT_EQ(bytesOf(s.document), after);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(s.document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
}

// Connected by its far end, the leg hangs the other way: a rotation at
// either joint would turn other bones than before, so both are dropped and
// named; the pin survives (its joint does), and keys without a surviving
// rotation add nothing to the body's clip.
TEST(MergeCarriesDraggedRig, ConnectedByItsEndTheLegsRotationsAreDroppedAndNamed) {
    Scene s;
    build(s);
    const Clip bodyClip = s.document.part(s.body).clip;
    const QByteArray before = bytesOf(s.document);
    auto merge = connectAt(s, s.legEnd);
    const QString summary = merge->summary();
    s.document.undoStack()->push(merge.release());
    ASSERT_EQ(s.document.partCount(), 1);
    const JointId low = std::min(s.legRoot, s.legEnd), high = std::max(s.legRoot, s.legEnd);
    EXPECT_TRUE(summary.contains(QStringLiteral("from leg: kept 1 pin(s); dropped the rotations "
                                                "of joint(s) %1, %2 (in the merged skeleton they "
                                                "would turn other bones)")
                                     .arg(low)
                                     .arg(high)))
        << summary.toStdString();
    const PartNode& merged = s.document.parts()[0];
    for (const auto& [joint, rotation] : merged.pose.rotations)
        EXPECT_TRUE(joint == 0 || rotation.vec().isZero(0.0)) << "only the body's rotation";
    EXPECT_TRUE(identicalClips(merged.clip, bodyClip));
    s.document.undoStack()->undo();
    EXPECT_EQ(bytesOf(s.document), before);
}

// The recipe's merge step runs the same command: the leg's keys reach the
// merged clip there too.
TEST(MergeCarriesDraggedRig, TheRecipeStepCarriesTheLegsKeys) {
    Scene s;
    build(s);
    runSteps(s.document, {{{"command", "merge"},
                           {"part", "leg"},
                           {"into", "body"},
                           {"mode", "connect"},
                           {"joint", s.legRoot},
                           {"target", 2}}});
    ASSERT_EQ(s.document.partCount(), 1);
    EXPECT_EQ(s.document.parts()[0].clip.keyTimes(), (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_EQ(s.document.parts()[0].pinnedJoints.size(), 1u);
}

}  // namespace
}  // namespace rigmesh::model::test
