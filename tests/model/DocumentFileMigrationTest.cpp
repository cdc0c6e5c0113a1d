// Documents of format version 1 named the bones of skin weights, failed bones
// and known closest bones by their position in the bone list. They still
// open, with every weight moved onto the bone's stable id.
#include <QFile>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "model/recipe/RecipeFile.h"

namespace rigmesh::model::test {
namespace {

const QString kFolder = QStringLiteral(RIGMESH_TEST_DATA "/documents/");

QByteArray fileBytes(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

// The y_branch sketch with bone 0 deleted, saved in format version 1: its
// bones 1 and 2 sit at positions 0 and 1 of the bone list.
class VersionOneDocument : public ::testing::Test {
  protected:
    void SetUp() override {
        const QByteArray bytes = fileBytes(kFolder + "y_branch_bone_deleted_v1.rigmesh");
        const nlohmann::json root = documentJson(bytes);
        ASSERT_EQ(root.at("version"), 1);
        stored = root.at("parts").at(0).at("part");
        loaded = DocumentFile::fromBytes(bytes);
        ASSERT_EQ(loaded.parts.size(), 1u);
        part = loaded.parts[0].part.get();
    }

    nlohmann::json stored;  // the part as the old version wrote it
    DocumentContents loaded;
    const Part* part = nullptr;
};

TEST_F(VersionOneDocument, StoredWeightsNameBonePositionsThatDifferFromTheIds) {
    ASSERT_TRUE(stored.at("weights").contains("perVertex"));
    ASSERT_FALSE(stored.at("weights").contains("byBoneId"));
    std::vector<BoneId> ids;
    for (const Bone& bone : part->skeleton.bones())
        ids.push_back(bone.id);
    EXPECT_EQ(ids, (std::vector<BoneId>{1, 2})) << "bone 0 was deleted";
}

TEST_F(VersionOneDocument, LoadsValidWithEveryWeightOnTheBoneAtItsStoredPosition) {
    const std::vector<Message> problems = part->validate();
    EXPECT_TRUE(problems.empty()) << problems.front();
    const nlohmann::json& perVertex = stored.at("weights").at("perVertex");
    ASSERT_EQ(perVertex.size(), part->weights.perVertex.size());
    for (std::size_t v = 0; v < perVertex.size(); ++v) {
        std::vector<std::pair<BoneId, double>> expected;
        for (std::size_t i = 0; i < perVertex[v].size(); i += 2)
            expected.emplace_back(part->skeleton.bones()[perVertex[v][i].get<int>()].id,
                                  perVertex[v][i + 1].get<double>());
        std::sort(expected.begin(), expected.end());
        ASSERT_EQ(part->weights.perVertex[v], expected) << "vertex " << v;
    }
    const nlohmann::json& known = stored.at("knownClosestBones");
    ASSERT_EQ(known.size(), part->knownClosestBones.size());
    for (std::size_t v = 0; v < known.size(); ++v)
        for (std::size_t i = 0; i < known[v].size(); i += 2)
            EXPECT_EQ(part->knownClosestBones[v][i / 2].first,
                      part->skeleton.bones()[known[v][i].get<int>()].id);
}

// The same steps replayed today give the same skeleton and weights keyed by
// the same ids: the conversion put every weight where the engine puts it
// now. Today's surface is finer on thin parts and its caps rounder (the end
// joints in the caps' middles move by up to a fifth of this
// document's 0.3 edge length), so each stored vertex is compared with
// today's nearest vertex: the same dominant bone.
TEST_F(VersionOneDocument, EqualsTheSameRecipeReplayedToday) {
    Document replay;
    runRecipeFile(replay, (kFolder + "y_branch_bone_deleted_v1.recipe.json").toStdString());
    ASSERT_EQ(replay.partCount(), 1);
    const PartNode& now = replay.parts()[0];
    ASSERT_EQ(now.part->skeleton.jointCount(), part->skeleton.jointCount());
    for (int j = 0; j < part->skeleton.jointCount(); ++j) {
        EXPECT_EQ(now.part->skeleton.joints()[j].id, part->skeleton.joints()[j].id);
        EXPECT_LT(
            (now.part->skeleton.joints()[j].position - part->skeleton.joints()[j].position).norm(),
            0.06);
    }
    auto dominant = [](const Part& p, int v) {
        const auto& list = p.weights.perVertex[v];
        return std::max_element(list.begin(), list.end(),
                                [](const auto& x, const auto& y) { return x.second < y.second; })
            ->first;
    };
    int same = 0;
    const auto& ours = now.part->mesh.vertices;
    for (int v = 0; v < part->mesh.vertexCount(); ++v) {
        const Vec3& p = part->mesh.vertices[v];
        const auto nearest = std::min_element(ours.begin(), ours.end(), [&](auto& x, auto& y) {
            return (x - p).squaredNorm() < (y - p).squaredNorm();
        });
        same += dominant(*part, v) == dominant(*now.part, int(nearest - ours.begin()));
    }
    std::printf("dominant bone as today's nearest vertex: %d of %d\n", same,
                part->mesh.vertexCount());
    EXPECT_GE(same, 0.95 * part->mesh.vertexCount());
    // The same pose and keys (a joint missing from a pose is at rest).
    auto samePose = [&](const Pose& a, const Pose& b) {
        for (const Joint& joint : part->skeleton.joints())
            if (a.rotation(joint.id).coeffs() != b.rotation(joint.id).coeffs())
                return false;
        return a.rootTranslation == b.rootTranslation;
    };
    EXPECT_TRUE(samePose(now.pose, loaded.parts[0].pose));
    ASSERT_EQ(now.clip.keyTimes(), loaded.parts[0].clip.keyTimes());
    for (double time : now.clip.keyTimes())
        EXPECT_TRUE(samePose(now.clip.key(time), loaded.parts[0].clip.key(time))) << time;
}

// Saving writes the current version (bones by id), which reads back exactly.
TEST_F(VersionOneDocument, SavesAsTheCurrentVersionAndReadsBackExactly) {
    const QByteArray saved = DocumentFile::toBytes(loaded);
    const nlohmann::json root = documentJson(saved);
    EXPECT_EQ(root.at("version"), DocumentFile::kFormatVersion);
    EXPECT_TRUE(root.at("parts").at(0).at("part").at("weights").contains("byBoneId"));
    const DocumentContents back = DocumentFile::fromBytes(saved);
    ASSERT_EQ(back.parts.size(), 1u);
    EXPECT_EQ(back.parts[0].part->weights, part->weights);
    EXPECT_EQ(back.parts[0].part->knownClosestBones, part->knownClosestBones);
    EXPECT_EQ(DocumentFile::toBytes(back), saved);
}

// Format 5 and older kept the notes of the skin weights as one English
// sentence (rig/BoneHeatSolver's wording then); they open as ids and
// arguments, which the studio shows in the user's language.
TEST(VersionFiveDocument, EnglishWeightNotesOpenAsMessageIds) {
    const DocumentContents today = DocumentFile::fromBytes(DocumentFile::toBytes(
        DocumentFile::fromBytes(fileBytes(kFolder + "y_branch_bone_deleted_v1.rigmesh"))));
    auto asVersionFive = [&](const std::string& sentence) {
        nlohmann::json root = documentJson(DocumentFile::toBytes(today));
        root["version"] = 5;
        nlohmann::json& weights = root["parts"][0]["part"]["weights"];
        weights.erase("warnings");
        weights["warning"] = sentence;
        const DocumentContents read = DocumentFile::fromBytes(documentBytes(root));
        return read.parts.at(0).part->weights.warnings;
    };
    const std::string solved =
        "Skin weights could not be solved for bones 0, 1; nearest-bone weights are used "
        "instead. 12 vertices see no bone from inside the shape and are heated by their "
        "nearest bone.";
    const std::vector<Message> notes = asVersionFive(solved);
    EXPECT_EQ(notes, (std::vector<Message>{{MessageId::WeightsBonesUnsolved, {"0, 1"}},
                                           {MessageId::WeightsVerticesSeeNoBone, {"12"}}}));
    EXPECT_EQ(englishText(notes), solved) << "the same words as before";
    EXPECT_EQ(asVersionFive("Skin weights could not be solved for bone 1; nearest-bone weights "
                            "are used instead."),
              (std::vector<Message>{{MessageId::WeightsBoneUnsolved, {"1"}}}));
    EXPECT_EQ(asVersionFive("Skin weights could not be solved for bones 0, 1 (the heat system "
                            "could not be factored); nearest-bone weights are used instead."),
              (std::vector<Message>{{MessageId::WeightsNotFactored, {}}}));
    EXPECT_TRUE(asVersionFive("").empty());
}

}  // namespace
}  // namespace rigmesh::model::test
