// A rig made elsewhere in the studio: Debian's assimp-testmodels
// X/Testwuson.X imported with File > Import keeps its disconnected bones;
// Edit > Connect Bone asks for a joint when none is selected and connects
// the selected disconnected bone to its parent's tail in one undo step
// named after the bone.
#include <gtest/gtest.h>

#include <QAction>
#include <QMenuBar>
#include <QStatusBar>
#include <optional>

#include "StudioFixture.h"
#include "model/DocumentFile.h"

namespace rigmesh {
namespace {

const QString kWuson = QStringLiteral("/usr/share/assimp/models/X/Testwuson.X");

class StudioImportedRig : public test::StudioFixture {
  protected:
    QString status() const { return window->statusBar()->currentMessage(); }
};

// The first bone hanging disconnected from another bone.
std::optional<BoneId> firstBoneHangingFromABone(const Skeleton& skeleton) {
    for (const auto& [joint, parent] : skeleton.attachments())
        if (parent != kNoBone && !skeleton.childrenOf(joint).empty())
            return skeleton.childrenOf(joint).front();
    return std::nullopt;
}

TEST_F(StudioImportedRig, EditConnectBoneConnectsTheSelectedDisconnectedBoneInOneUndoStep) {
    window->exchange()->importPath(kWuson);
    test::waitForJobs();
    ASSERT_EQ(document()->partCount(), 1);
    const model::PartNode& node = document()->parts().front();
    ASSERT_FALSE(node.part->skeleton.isConnectedTree());
    const std::optional<BoneId> bone = firstBoneHangingFromABone(node.part->skeleton);
    ASSERT_TRUE(bone.has_value());
    ASSERT_FALSE(node.part->skeleton.isConnected(*bone));

    QAction* connect = menuAction(QStringLiteral("&Edit"), QStringLiteral("Co&nnect Bone"));
    ASSERT_NE(connect, nullptr) << "Edit > Connect Bone";
    const int steps = document()->undoStack()->count();
    const QByteArray imported = model::DocumentFile::toBytes(*document());

    // Nothing selected: the studio says what to do and changes nothing.
    document()->setSelection({node.id, kNoJoint});
    connect->trigger();
    EXPECT_EQ(status(), QStringLiteral("Select the joint of the bone to connect first"));
    EXPECT_EQ(document()->undoStack()->count(), steps);

    // The bone's head selected (the joint its chain hangs from).
    document()->setSelection({node.id, node.part->skeleton.bone(*bone).head});
    connect->trigger();
    ASSERT_EQ(document()->undoStack()->count(), steps + 1) << status().toStdString();
    const Part& connected = *document()->parts().front().part;
    EXPECT_TRUE(connected.skeleton.isConnected(*bone));
    const std::vector<Message> problems = connected.validate();
    EXPECT_TRUE(problems.empty()) << problems.front();
    // The status and the undo step name the bone as its file did.
    const QString expected = QStringLiteral("Connect Bone %1 of %2")
                                 .arg(QString::fromStdString(connected.boneNames.at(*bone)),
                                      document()->parts().front().name);
    EXPECT_EQ(status(), expected);
    EXPECT_EQ(document()->undoStack()->text(steps), expected);

    document()->undoStack()->undo();
    EXPECT_EQ(model::DocumentFile::toBytes(*document()), imported);
}

}  // namespace
}  // namespace rigmesh
