// Documents and recipes of format version 1, whose poses held one rotation
// per joint turning every bone leaving it, open and replay with per-bone
// rotations (pose/LegacyPose.h) to exactly the same deformed surface.
//
// tests/data/legacy: posed_biped_v1.rigmesh was written by the version 1
// studio (commit c713b01) with `rigmesh run posed_biped_v1.recipe.json`, and
// posed_biped_v1_current.obj by its `rigmesh export --current-pose`.
#include <QFile>
#include <fstream>
#include <sstream>

#include "ModelTestSupport.h"
#include "model/DocumentExport.h"
#include "model/recipe/RecipeFile.h"
#include "pose/Skinning.h"

namespace rigmesh::model::test {
namespace {

const std::string kLegacy = std::string(RIGMESH_TEST_DATA) + "/legacy/";

QByteArray fileBytes(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

// The "v x y z" lines of an OBJ file.
std::vector<Vec3> objVertices(const std::string& path) {
    std::ifstream in(path);
    std::vector<Vec3> vertices;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("v ", 0) != 0)
            continue;
        std::istringstream fields(line.substr(2));
        Vec3 v;
        fields >> v.x() >> v.y() >> v.z();
        vertices.push_back(v);
    }
    return vertices;
}

std::vector<Vec3> deformed(const PartNode& node, const rigmesh::Pose& pose) {
    return posePart(*node.part, pose).mesh.vertices;
}

TEST(LegacyDocument, VersionOneDocumentOpensWithIdenticalDeformedVertices) {
    const auto document =
        DocumentFile::load(QString::fromStdString(kLegacy + "posed_biped_v1.rigmesh"));
    ASSERT_EQ(document->partCount(), 1);
    const PartNode& node = document->parts().front();
    // The root's old rotation turned the whole body: it now lives on the
    // bones leaving the root, and the root itself is at rest.
    EXPECT_FALSE(node.pose.rotations.contains(node.part->skeleton.root()));
    ASSERT_EQ(node.clip.keyCount(), 2);

    // Exported as the version 1 studio did: the same bytes (the same file
    // name too: the OBJ names its .mtl).
    QTemporaryDir folder;
    const QString obj = folder.filePath(QStringLiteral("posed_biped_v1_current.obj"));
    ExportOptions options;
    options.restPose = false;
    exportDocument(*document, obj.toStdString(), options);
    EXPECT_EQ(fileBytes(obj),
              fileBytes(QString::fromStdString(kLegacy + "posed_biped_v1_current.obj")))
        << "the current pose deforms the surface differently from version 1";

    // And in doubles: our skinning within the OBJ's float rounding.
    const std::vector<Vec3> old = objVertices(kLegacy + "posed_biped_v1_current.obj");
    const std::vector<Vec3> now = deformed(node, node.pose);
    ASSERT_EQ(old.size(), now.size());
    double largest = 0;
    for (std::size_t v = 0; v < now.size(); ++v)
        largest = std::max(largest, (old[v] - now[v]).norm());
    std::printf("largest gap to the version 1 export: %.3g\n", largest);
    EXPECT_LT(largest, 1e-6);
}

// The recipe replayed today converts its poses as the document's were
// converted: the same joints and bit for bit the same per-bone rotations at
// every key. The surface itself is today's (thin parts are finer
// and caps rounder than in version 1; an end joint sits in the middle of its cap, so it moves
// by up to 0.031 on this 5.4-high biped), so the deformed vertices are
// compared through the document's own mesh above, not here.
TEST(LegacyDocument, VersionOneRecipeReplaysToTheVersionOneDocument) {
    Document replayed;
    runRecipeFile(replayed, kLegacy + "posed_biped_v1.recipe.json");
    const auto loaded =
        DocumentFile::load(QString::fromStdString(kLegacy + "posed_biped_v1.rigmesh"));
    ASSERT_EQ(replayed.partCount(), 1);
    const PartNode& a = replayed.parts().front();
    const PartNode& b = loaded->parts().front();
    ASSERT_EQ(a.part->skeleton.jointCount(), b.part->skeleton.jointCount());
    for (int j = 0; j < a.part->skeleton.jointCount(); ++j)
        EXPECT_LT(
            (a.part->skeleton.joints()[j].position - b.part->skeleton.joints()[j].position).norm(),
            0.04)
            << "joint " << j;
    EXPECT_TRUE(identicalPoses(a.pose, b.pose));
    ASSERT_EQ(a.clip.keyTimes(), b.clip.keyTimes());
    for (double t : {0.0, 0.3, 0.5, 1.0})
        EXPECT_TRUE(identicalPoses(a.clip.evaluate(t), b.clip.evaluate(t))) << t << " s";
    // Saved again, the document is of the current version.
    EXPECT_TRUE(identicalPoses(
        DocumentFile::fromBytes(DocumentFile::toBytes(*loaded)).parts[0].pose, b.pose));
}

}  // namespace
}  // namespace rigmesh::model::test
