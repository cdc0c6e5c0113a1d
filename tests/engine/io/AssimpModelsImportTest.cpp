// Every rigged, skinned file of Debian's assimp-testmodels (scripts/setup.sh
// installs them) opens rigged: its bone names, a clip per animation, and at
// every key time of every clip our skinning of the imported part puts each
// vertex where the file's own bone animation does (linear blend skinning
// from Assimp's scene: the animated node transforms times the offset
// matrices); and it survives our export and import in glb, fbx and dae.
//
// The files are those `assimp info` lists with bones (a scan of
// /usr/share/assimp/models; see kModels), less the ones whose only "mesh"
// is the skeleton Assimp draws itself for formats that have none (BVH, CSM,
// COLLADA cameras and lights).
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "IoTestSupport.h"
#include "io/AssimpConversions.h"
#include "io/AssimpNodeTree.h"
#include "io/ExportFormat.h"
#include "io/InfluenceLimit.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"
#include "pose/Skinning.h"

namespace rigmesh {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

struct Model {
    std::string path;  // under kModels
    int clips;         // animations moving the rig
};

const std::vector<Model> kRigged = {
    {"X/Testwuson.X", 3},
    {"X/BCN_Epileptic.X", 1},
    {"X/anim_test.x", 1},
    {"FBX/animation_with_skeleton.fbx", 1},
    {"FBX/huesitos.fbx", 1},
    {"glTF2/simple_skin/simple_skin.gltf", 1},
    {"MD5/SimpleCube.md5mesh", 0},
    {"SMD/WusonSMD.smd", 1},
    {"SMD/holy_grailref.smd", 1},
    {"SMD/triangle.smd", 1},
    {"MDL/MDL (HL1)/man.mdl", 6},
    {"MDL/MDL (HL1)/unnamed_bones.mdl", 1},
    {"MDL/MDL (HL1)/alpha_test.mdl", 1},
    {"MDL/MDL (HL1)/blend_additive.mdl", 1},
    {"MDL/MDL (HL1)/chrome_sphere.mdl", 1},
    {"MDL/MDL (HL1)/duplicate_bodyparts.mdl", 1},
    {"MDL/MDL (HL1)/duplicate_sequences.mdl", 9},
    {"MDL/MDL (HL1)/duplicate_submodels.mdl", 1},
    {"MDL/MDL (HL1)/sequence_transitions.mdl", 7},
    {"MDL/MDL (HL1)/unnamed_bodyparts.mdl", 1},
    {"MDL/MDL (HL1)/unnamed_sequences.mdl", 9},
    {"MDL/MDL (HL1)/unnamed_sequence_groups/unnamed_sequence_groups.mdl", 9},
    {"MDL/MDL (HL1)/duplicate_sequence_groups/duplicate_sequence_groups.mdl", 9},
};

// The file as importScene reads it (SceneImport.cpp: same flags, same
// vertex order).
const aiScene* readLikeImportScene(Assimp::Importer& importer, const std::string& path) {
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_OPTIMIZE_EMPTY_ANIMATION_CURVES, false);
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);
    return importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                       aiProcess_SortByPType | aiProcess_ValidateDataStructure);
}

// FBX's unit, as importScene applies it (centimetres per file unit / 100).
double metresPerFileUnit(const aiScene& scene) {
    double centimetres = 100.0;
    float single = 100.0f;
    if (scene.mMetaData != nullptr && !scene.mMetaData->Get("UnitScaleFactor", centimetres) &&
        scene.mMetaData->Get("UnitScaleFactor", single))
        centimetres = single;
    return centimetres > 0 ? centimetres / 100.0 : 1.0;
}

// The skinned meshes in the order importScene takes them (nodes parent
// first, each mesh once).
std::vector<unsigned> skinnedMeshes(const aiScene& scene, const AssimpNodeTree& tree) {
    std::vector<unsigned> meshes;
    std::set<unsigned> seen;
    for (int n = 0; n < tree.size(); ++n)
        for (unsigned k = 0; k < tree.node(n).mNumMeshes; ++k) {
            const unsigned m = tree.node(n).mMeshes[k];
            if (seen.insert(m).second && scene.mMeshes[m]->mNumBones > 0 &&
                (scene.mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0)
                meshes.push_back(m);
        }
    return meshes;
}

// The file's own skinning at `ticks`: per vertex sum_b w_b G_t(node_b)
// offset_b v (weights normalised), every skinned mesh after the other. A
// bone without a node keeps the vertex where `rest` has it.
std::vector<Vec3> fileSkinning(const aiScene& scene, const AssimpNodeTree& tree,
                               const aiAnimation& animation, double ticks,
                               const std::vector<Vec3>& rest) {
    const std::vector<Eigen::Affine3d> globals = tree.animatedGlobals(animation, ticks);
    std::vector<Vec3> out;
    for (unsigned m : skinnedMeshes(scene, tree)) {
        const aiMesh& mesh = *scene.mMeshes[m];
        const std::size_t first = out.size();
        std::vector<Vec3> sum(mesh.mNumVertices, Vec3::Zero());
        std::vector<double> total(mesh.mNumVertices, 0.0);
        for (unsigned b = 0; b < mesh.mNumBones; ++b) {
            const aiBone& bone = *mesh.mBones[b];
            const int node = tree.find(bone.mName.C_Str());
            const Eigen::Affine3d skin =
                node >= 0 ? Eigen::Affine3d(globals[static_cast<std::size_t>(node)] *
                                            fromAi(bone.mOffsetMatrix))
                          : Eigen::Affine3d::Identity();
            for (unsigned w = 0; w < bone.mNumWeights; ++w) {
                const aiVertexWeight& weight = bone.mWeights[w];
                const Vec3 v = node >= 0 ? Vec3(skin * fromAi(mesh.mVertices[weight.mVertexId]))
                                         : rest.at(first + weight.mVertexId);
                sum[weight.mVertexId] += weight.mWeight * v;
                total[weight.mVertexId] += weight.mWeight;
            }
        }
        for (unsigned v = 0; v < mesh.mNumVertices; ++v)
            out.push_back(total[v] > 0 ? Vec3(sum[v] / total[v]) : Vec3(rest.at(first + v)));
    }
    return out;
}

// The rigged parts' vertices one after the other, posed by each part's clip
// `clip` at `seconds` (LBS, as the file skins).
std::vector<Vec3> ourSkinning(const ImportedScene& imported, std::size_t clip, double seconds) {
    std::vector<Vec3> out;
    for (const ImportedPart& part : imported.parts) {
        if (part.needsRig)
            continue;
        const Pose pose = clip < part.clips.size() ? part.clips[clip].evaluate(seconds) : Pose{};
        const PosedMesh posed = posePart(part.part, pose, {SkinningMethod::LinearBlend, 2});
        out.insert(out.end(), posed.mesh.vertices.begin(), posed.mesh.vertices.end());
    }
    return out;
}

std::vector<Vec3> restVertices(const ImportedScene& imported) {
    std::vector<Vec3> out;
    for (const ImportedPart& part : imported.parts)
        if (!part.needsRig)
            out.insert(out.end(), part.part.mesh.vertices.begin(), part.part.mesh.vertices.end());
    return out;
}

double diagonal(const std::vector<Vec3>& points) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : points)
        box.extend(p);
    return box.diagonal().norm();
}

double largestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double worst = 0;
    for (std::size_t v = 0; v < a.size(); ++v)
        worst = std::max(worst, (a[v] - b[v]).norm());
    return worst;
}

class AssimpModels : public testing::TestWithParam<Model> {};

TEST_P(AssimpModels, OpensRiggedWithItsBoneNamesAndEveryAnimation) {
    const std::string path = kModels + GetParam().path;
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " is missing: install assimp-testmodels";
    const ImportedScene imported = importScene(path);
    int rigged = 0;
    std::set<std::string> names;
    for (const ImportedPart& part : imported.parts) {
        if (part.needsRig)
            continue;
        ++rigged;
        EXPECT_TRUE(part.part.validate().empty()) << part.part.validate().front();
        EXPECT_EQ(static_cast<int>(part.clips.size()), GetParam().clips);
        names.insert(part.boneNames.begin(), part.boneNames.end());
    }
    ASSERT_GT(rigged, 0) << imported.message;
    Assimp::Importer importer;
    const aiScene& scene = *readLikeImportScene(importer, path);
    const AssimpNodeTree tree(scene, metresPerFileUnit(scene));
    for (unsigned m : skinnedMeshes(scene, tree))
        for (unsigned b = 0; b < scene.mMeshes[m]->mNumBones; ++b) {
            const std::string name = scene.mMeshes[m]->mBones[b]->mName.C_Str();
            if (!name.ends_with("_end")) {
                EXPECT_TRUE(names.contains(name)) << "bone " << name;
            }
        }
    // Every skinned mesh is in a rigged part.
    std::size_t skinnedVertices = 0;
    for (unsigned m : skinnedMeshes(scene, tree))
        skinnedVertices += scene.mMeshes[m]->mNumVertices;
    EXPECT_EQ(restVertices(imported).size(), skinnedVertices) << imported.message;
}

TEST_P(AssimpModels, PosesAsTheFileAnimatesAtEveryKey) {
    const std::string path = kModels + GetParam().path;
    const ImportedScene imported = importScene(path);
    Assimp::Importer importer;
    const aiScene& scene = *readLikeImportScene(importer, path);
    const AssimpNodeTree tree(scene, metresPerFileUnit(scene));
    const std::vector<Vec3> rest = restVertices(imported);
    ASSERT_FALSE(rest.empty());
    const double size = diagonal(rest);
    std::size_t clip = 0;
    for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
        const aiAnimation& animation = *scene.mAnimations[a];
        const double perSecond = animation.mTicksPerSecond > 0 ? animation.mTicksPerSecond : 1.0;
        const ImportedPart* owner = nullptr;
        for (const ImportedPart& part : imported.parts)
            if (!part.needsRig && clip < part.clips.size())
                owner = &part;
        if (!owner)
            break;
        const std::vector<double> times = owner->clips[clip].keyTimes();
        double worst = 0;
        for (std::size_t k = 0; k < times.size(); k += std::max<std::size_t>(1, times.size() / 6))
            worst = std::max(worst, largestDistance(ourSkinning(imported, clip, times[k]),
                                                    fileSkinning(scene, tree, animation,
                                                                 times[k] * perSecond, rest)));
        EXPECT_LE(worst, 1e-4 * size) << "animation " << a << " '" << animation.mName.C_Str()
                                      << "': the largest distance over its keys";
        ++clip;
    }
}

// A part's bones by name: parent's name, connected, head, tail.
struct NamedBone {
    std::string parent;
    bool connected = false;
    Vec3 head, tail;
};

std::map<std::string, NamedBone> bonesByName(const ImportedPart& imported) {
    const Skeleton& s = imported.part.skeleton;
    std::map<std::string, NamedBone> out;
    for (const Bone& bone : s.bones()) {
        const std::optional<BoneId> parent = s.parentBone(bone.id);
        out[imported.part.boneNames.at(bone.id)] = {
            parent ? imported.part.boneNames.at(*parent) : std::string(), s.isConnected(bone.id),
            s.joint(bone.head).position, s.joint(bone.tail).position};
    }
    return out;
}

// A part's vertex weights by bone name.
std::map<std::string, double> namedWeights(const ImportedPart& imported, std::size_t vertex) {
    std::map<std::string, double> out;
    for (const auto& [bone, w] : imported.part.weights.perVertex[vertex])
        out[imported.part.boneNames.at(bone)] += w;
    return out;
}

double weightDifference(const std::map<std::string, double>& a,
                        const std::map<std::string, double>& b) {
    double sum = 0;
    for (const auto& [name, w] : a)
        sum += std::abs(w - (b.contains(name) ? b.at(name) : 0.0));
    for (const auto& [name, w] : b)
        sum += a.contains(name) ? 0.0 : w;
    return sum;
}

// Per vertex of `before`, the vertex of `after` at its rest position; of
// several there (a file may split a vertex, e.g. DirectX's Testwuson: 1965
// of its 3205 vertices share a position with another, weighted
// differently), the one weighted most alike.
std::vector<int> matchVerticesAndWeights(const ImportedPart& before, const ImportedPart& after) {
    const std::vector<Vec3>& b = after.part.mesh.vertices;
    std::vector<int> match = iotest::matchVertices(before.part.mesh.vertices, b);
    std::map<std::array<double, 3>, std::vector<int>> samePlace;
    for (std::size_t v = 0; v < b.size(); ++v)
        samePlace[{b[v].x(), b[v].y(), b[v].z()}].push_back(static_cast<int>(v));
    for (std::size_t v = 0; v < match.size(); ++v) {
        if (match[v] < 0)
            continue;
        const Vec3& at = b[static_cast<std::size_t>(match[v])];
        const std::map<std::string, double> wanted = namedWeights(before, v);
        double best = INFINITY;
        for (int candidate : samePlace.at({at.x(), at.y(), at.z()})) {
            const double difference =
                weightDifference(wanted, namedWeights(after, static_cast<std::size_t>(candidate)));
            if (difference < best) {
                best = difference;
                match[v] = candidate;
            }
        }
    }
    return match;
}

// One file in one of the formats we write with a rig (ExportFormat.h:
// isRiggedFormat), a test each, so that each format's count shows.
class AssimpModelsRoundTrip : public testing::TestWithParam<std::tuple<Model, std::string>> {};

TEST_P(AssimpModelsRoundTrip, SurvivesOurExportAndImport) {
    const auto& [model, extension] = GetParam();
    const ImportedScene imported = importScene(kModels + model.path);
    std::vector<const ImportedPart*> rigged;
    std::vector<ExportPart> items;
    for (const ImportedPart& part : imported.parts)
        if (!part.needsRig) {
            rigged.push_back(&part);
            ExportPart item;
            item.part = &part.part;
            item.clip = part.clips.empty() ? nullptr : &part.clips.front();
            for (std::size_t c = 1; c < part.clips.size(); ++c)
                item.otherClips.push_back(&part.clips[c]);
            items.push_back(item);
        }
    ASSERT_FALSE(rigged.empty());
    // Names must be unique in a file: parts keep theirs, clips too.
    const double size = diagonal(restVertices(imported));
    {
        const std::string path = (iotest::scratchFolder() / ("back" + extension)).string();
        // Every influence the format carries (the default export keeps 4,
        // what game engines take; FBX/animation_with_skeleton.fbx has 1515
        // vertices with 5 or 6).
        ExportOptions everyInfluence;
        everyInfluence.maxInfluences = 0;
        exportScene(items, nullptr, path, everyInfluence);
        const ImportedScene back = importScene(path);
        std::vector<const ImportedPart*> again;
        for (const ImportedPart& part : back.parts)
            if (!part.needsRig)
                again.push_back(&part);
        ASSERT_EQ(again.size(), rigged.size()) << extension << ": " << back.message;
        for (std::size_t p = 0; p < rigged.size(); ++p) {
            const auto before = bonesByName(*rigged[p]), after = bonesByName(*again[p]);
            ASSERT_EQ(after.size(), before.size()) << extension;
            double worst = 0;
            for (const auto& [name, bone] : before) {
                ASSERT_TRUE(after.contains(name)) << extension << ": bone " << name;
                const NamedBone& other = after.at(name);
                EXPECT_EQ(other.parent, bone.parent) << extension << ": bone " << name;
                EXPECT_EQ(other.connected, bone.connected) << extension << ": bone " << name;
                worst = std::max(
                    {worst, (other.head - bone.head).norm(), (other.tail - bone.tail).norm()});
            }
            EXPECT_LE(worst, 1e-4 * size) << extension << ": the largest head or tail difference";
            EXPECT_EQ(again[p]->part.meshPieces.size(), rigged[p]->part.meshPieces.size())
                << extension;
            // Every clip with its keys (COLLADA keeps no animation names).
            ASSERT_EQ(again[p]->clips.size(), rigged[p]->clips.size()) << extension;
            for (std::size_t c = 0; c < rigged[p]->clips.size(); ++c) {
                const std::vector<double> times = rigged[p]->clips[c].keyTimes();
                const std::vector<double> timesBack = again[p]->clips[c].keyTimes();
                ASSERT_EQ(timesBack.size(), times.size()) << extension << ": clip " << c;
                for (std::size_t k = 0; k < times.size(); ++k)
                    EXPECT_NEAR(timesBack[k], times[k], 1e-6 * std::max(1.0, times[k]))
                        << extension;
            }
            // The same deformation at the first clip's keys (vertices matched
            // by rest position: the files join identical vertices).
            if (rigged[p]->clips.empty())
                continue;
            // The exception of glTF: Assimp 5.2.5's glTF writer keeps 4
            // influences per vertex (JOINTS_0/WEIGHTS_0 only, ExportFormat.h:
            // formatInfluenceLimit), so there the file's part is compared with
            // its weights cut to 4 (InfluenceLimit.h) as the export cuts them.
            ImportedPart expected = *rigged[p];
            if (const int limit = formatInfluenceLimit(exportFormatFromPath(path)); limit > 0)
                expected.part.weights = limitInfluences(expected.part.weights, limit);
            const std::vector<int> match = matchVerticesAndWeights(expected, *again[p]);
            const std::vector<double> times = rigged[p]->clips.front().keyTimes();
            double worstPose = 0;
            for (std::size_t k = 0; k < times.size();
                 k += std::max<std::size_t>(1, times.size() / 4)) {
                const PosedMesh ours =
                    posePart(expected.part, rigged[p]->clips.front().evaluate(times[k]),
                             {SkinningMethod::LinearBlend, 2});
                const PosedMesh theirs =
                    posePart(again[p]->part, again[p]->clips.front().evaluate(times[k]),
                             {SkinningMethod::LinearBlend, 2});
                for (std::size_t v = 0; v < match.size(); ++v)
                    worstPose = std::max(worstPose,
                                         (ours.mesh.vertices[v] -
                                          theirs.mesh.vertices[static_cast<std::size_t>(match[v])])
                                             .norm());
            }
            EXPECT_LE(worstPose, 1e-4 * size) << extension << ": posed at the first clip's keys";
        }
    }
}

std::string testName(const std::string& text) {
    std::string name = text;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Files, AssimpModels, testing::ValuesIn(kRigged),
                         [](const testing::TestParamInfo<Model>& test) {
                             return testName(test.param.path);
                         });

INSTANTIATE_TEST_SUITE_P(Files, AssimpModelsRoundTrip,
                         testing::Combine(testing::ValuesIn(kRigged),
                                          testing::Values(".glb", ".gltf", ".fbx", ".dae")),
                         [](const testing::TestParamInfo<std::tuple<Model, std::string>>& test) {
                             return testName(std::get<1>(test.param).substr(1) + "_" +
                                             std::get<0>(test.param).path);
                         });

}  // namespace
}  // namespace rigmesh
