#include "part/PartJson.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>

#include "base/JsonRead.h"
#include "base/JsonWrite.h"

namespace rigmesh {

using nlohmann::json;
using namespace jsonread;

namespace {

// Skin weights of a vertex sum to 1 up to rounding (and float imports).
constexpr double kWeightSumTolerance = 1e-6;

json pairs(const std::vector<std::vector<std::pair<BoneId, double>>>& lists) {
    json out = json::array();
    for (const auto& list : lists) {
        json flat = json::array();
        for (const auto& [index, value] : list) {
            flat.push_back(index);
            flat.push_back(value);
        }
        out.push_back(std::move(flat));
    }
    return out;
}

// boneNames: [[bone id, name], ...] in bone id order.
json boneNamesJson(const std::map<BoneId, std::string>& names) {
    json out = json::array();
    for (const auto& [bone, name] : names)
        out.push_back(json::array({bone, name}));
    return out;
}

// The weight notes a document may hold, by a name that stays when MessageIds
// are renumbered: documents keep ids and arguments, and the studio shows the
// text in the user's language (base/Message.h).
struct WeightWarningKind {
    const char* name;
    MessageId id;
    std::size_t argumentCount;
};
constexpr std::array<WeightWarningKind, 4> kWeightWarnings = {{
    {"boneUnsolved", MessageId::WeightsBoneUnsolved, 1},
    {"bonesUnsolved", MessageId::WeightsBonesUnsolved, 1},
    {"notFactored", MessageId::WeightsNotFactored, 0},
    {"verticesSeeNoBone", MessageId::WeightsVerticesSeeNoBone, 1},
}};

json warningsJson(const std::vector<Message>& warnings) {
    json out = json::array();
    for (const Message& warning : warnings) {
        const auto kind = std::find_if(kWeightWarnings.begin(), kWeightWarnings.end(),
                                       [&](const auto& k) { return k.id == warning.id; });
        if (kind == kWeightWarnings.end() || !warning.nested.empty())
            throw std::logic_error("skin weights hold a warning that documents cannot store");
        out.push_back({{"id", kind->name}, {"args", warning.args}});
    }
    return out;
}

std::vector<Message> readWarnings(const json& list) {
    std::vector<Message> out;
    for (const json& entry : list) {
        const std::string name = text(field(entry, "id"), R"("weights" "warnings" "id")");
        const auto kind = std::find_if(kWeightWarnings.begin(), kWeightWarnings.end(),
                                       [&](const auto& k) { return name == k.name; });
        if (kind == kWeightWarnings.end())
            fail(MessageId::DataUnknownWeightNote, quoted(name.c_str()));
        Message warning{kind->id, {}};
        for (const json& argument : array(entry, "args"))
            warning.args.push_back(text(argument, R"("weights" "warnings" "args")"));
        if (warning.args.size() != kind->argumentCount)
            fail(MessageId::DataWeightNoteArguments, quoted(name.c_str()));
        out.push_back(std::move(warning));
    }
    return out;
}

}  // namespace

json partToJson(const Part& part) {
    json mesh;
    mesh["vertices"] = json::array();
    for (const Vec3& v : part.mesh.vertices)
        for (int k = 0; k < 3; ++k)
            mesh["vertices"].push_back(v[k]);
    mesh["faces"] = json::array();
    for (const auto& f : part.mesh.faces)
        for (int k = 0; k < 3; ++k)
            mesh["faces"].push_back(f[k]);

    json origins = {{"kind", json::array()},
                    {"region", json::array()},
                    {"section", json::array()},
                    {"axisPosition", json::array()},
                    {"onOutline", json::array()}};
    for (const VertexOrigin& o : part.origins) {
        origins["kind"].push_back(static_cast<int>(o.kind));
        origins["region"].push_back(o.region);
        origins["section"].push_back(o.section);
        origins["axisPosition"].push_back(o.axisPosition);
        origins["onOutline"].push_back(o.onOutline);
    }

    json joints = {{"ids", json::array()}, {"positions", json::array()}};
    for (const Joint& j : part.skeleton.joints()) {
        joints["ids"].push_back(j.id);
        for (int k = 0; k < 3; ++k)
            joints["positions"].push_back(j.position[k]);
    }
    json bones = {{"ids", json::array()}, {"heads", json::array()}, {"tails", json::array()}};
    for (const Bone& b : part.skeleton.bones()) {
        bones["ids"].push_back(b.id);
        bones["heads"].push_back(b.head);
        bones["tails"].push_back(b.tail);
    }

    json skeleton = {
        {"joints", std::move(joints)}, {"bones", std::move(bones)}, {"root", part.skeleton.root()}};
    // Written only for disconnected bones (format version 5), so connected
    // skeletons keep their bytes.
    if (!part.skeleton.attachments().empty()) {
        json attached = {{"joints", json::array()}, {"bones", json::array()}};
        for (const auto& [joint, bone] : part.skeleton.attachments()) {
            attached["joints"].push_back(joint);
            attached["bones"].push_back(bone);
        }
        skeleton["attachments"] = std::move(attached);
    }

    json out = {
        {"name", part.name},
        {"outline", jsonwrite::flatVec2s(part.outline)},
        {"mesh", std::move(mesh)},
        {"origins", std::move(origins)},
        {"mirror", part.mirror},
        {"skeleton", std::move(skeleton)},
        {"weights",
         {{"byBoneId", pairs(part.weights.perVertex)},
          {"failedBoneIds", part.weights.failedBones},
          {"warnings", warningsJson(part.weights.warnings)}}},
        {"knownClosestByBoneId", pairs(part.knownClosestBones)},
        {"boneNames", boneNamesJson(part.boneNames)},
    };
    // Written only when set, so parts nobody painted keep their bytes.
    if (!part.lockedBones.empty())
        out["lockedBones"] = part.lockedBones;
    if (part.weightsPainted)
        out["weightsPainted"] = true;
    if (!part.boneFrames.empty()) {  // [[bone id, w, x, y, z], ...] in bone id order
        json frames = json::array();
        for (const auto& [bone, q] : part.boneFrames)
            frames.push_back(json::array({bone, q.w(), q.x(), q.y(), q.z()}));
        out["boneFrames"] = std::move(frames);
    }
    if (!part.meshPieces.empty()) {
        json pieces = json::array();
        for (const PartMeshPiece& piece : part.meshPieces)
            pieces.push_back({{"name", piece.name},
                              {"vertexCount", piece.vertexCount},
                              {"faceCount", piece.faceCount}});
        out["meshPieces"] = std::move(pieces);
    }
    out["surfaceFromFile"] = part.surfaceFromFile;
    return out;
}

namespace {

enum class PairValues { Weights, Distances };

// A bone by id, or (documents before bone ids, `byIndex`) by its position in
// the skeleton's bone list, converted to its id here.
BoneId readBone(const json& value, const Skeleton& skeleton, bool byIndex, const char* what) {
    if (byIndex) {
        const int index = integer<int>(value, what);
        if (index < 0 || index >= skeleton.boneCount())
            fail(MessageId::DataMissingBoneAtIndex, what);
        return skeleton.bones()[index].id;
    }
    const auto bone = integer<BoneId>(value, what);
    if (!skeleton.hasBone(bone))
        fail(MessageId::DataMissingBone, what, bone);
    return bone;
}

// Per vertex: [bone, value, bone, value, ...] (bones as readBone reads them).
std::vector<std::vector<std::pair<BoneId, double>>> readPairs(const json& list, std::size_t count,
                                                              const Skeleton& skeleton,
                                                              bool byIndex, PairValues values,
                                                              const char* what) {
    if (!list.is_array() || (list.size() != count && !list.empty()))
        fail(MessageId::DataNotPerVertex, what);
    std::vector<std::vector<std::pair<BoneId, double>>> out;
    out.reserve(list.size());
    for (const json& flat : list) {
        if (!flat.is_array() || flat.size() % 2 != 0)
            fail(MessageId::DataMalformedEntry, what);
        auto& entry = out.emplace_back();
        for (std::size_t i = 0; i < flat.size(); i += 2) {
            const BoneId bone = readBone(flat[i], skeleton, byIndex, what);
            const double value = number(flat[i + 1], what);
            if (value < 0)
                fail(MessageId::DataNegative, what);
            entry.emplace_back(bone, value);
        }
        // Bone order is id order (positions and ids may differ in order).
        std::sort(entry.begin(), entry.end());
        if (values == PairValues::Weights && !entry.empty()) {
            double sum = 0;
            for (const auto& pair : entry)
                sum += pair.second;
            if (std::abs(sum - 1.0) > kWeightSumTolerance)
                fail(MessageId::DataWeightSum, out.size() - 1, std::to_string(sum));
        }
    }
    return out;
}

Skeleton readSkeleton(const json& object) {
    const json& joints = field(object, "joints");
    const json& jointIds = array(joints, "ids");
    const std::vector<double> positions =
        numbers(array(joints, "positions"), 3, R"("skeleton" "joints" "positions")");
    if (positions.size() != 3 * jointIds.size())
        fail(MessageId::DataJointCountsDiffer);
    std::vector<Joint> jointList;
    std::set<JointId> known;
    for (std::size_t i = 0; i < jointIds.size(); ++i) {
        const auto id = integer<JointId>(jointIds[i], R"("skeleton" "joints" "ids")");
        if (id == kNoJoint || !known.insert(id).second)
            fail(MessageId::DataJointIdRepeated);
        jointList.push_back(
            {id, Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2])});
    }
    const json& bones = field(object, "bones");
    const json& boneIds = array(bones, "ids");
    const json& heads = array(bones, "heads");
    const json& tails = array(bones, "tails");
    if (heads.size() != boneIds.size() || tails.size() != boneIds.size())
        fail(MessageId::DataBoneCountsDiffer);
    std::vector<Bone> boneList;
    std::set<BoneId> knownBones;
    for (std::size_t i = 0; i < boneIds.size(); ++i) {
        const Bone bone{integer<BoneId>(boneIds[i], R"("skeleton" "bones" "ids")"),
                        integer<JointId>(heads[i], R"("skeleton" "bones" "heads")"),
                        integer<JointId>(tails[i], R"("skeleton" "bones" "tails")")};
        if (!knownBones.insert(bone.id).second)
            fail(MessageId::DataBoneIdRepeated);
        if (!known.contains(bone.head) || !known.contains(bone.tail))
            fail(MessageId::DataBoneMissingJoint);
        boneList.push_back(bone);
    }
    const auto root = integer<JointId>(field(object, "root"), R"("skeleton" "root")");
    if (root != kNoJoint ? !known.contains(root) : !known.empty())
        fail(MessageId::DataRootNotJoint);
    std::map<JointId, BoneId> attachments;
    if (object.contains("attachments")) {  // since format version 5
        const json& attached = field(object, "attachments");
        const json& attachedJoints = array(attached, "joints");
        const json& parents = array(attached, "bones");
        if (attachedJoints.size() != parents.size())
            fail(MessageId::DataAttachmentCountsDiffer);
        for (std::size_t i = 0; i < attachedJoints.size(); ++i) {
            const auto joint =
                integer<JointId>(attachedJoints[i], R"("skeleton" "attachments" "joints")");
            const auto bone = integer<BoneId>(parents[i], R"("skeleton" "attachments" "bones")");
            if (!known.contains(joint) || (bone != kNoBone && !knownBones.contains(bone)) ||
                !attachments.emplace(joint, bone).second)
                fail(MessageId::DataAttachmentMissing);
        }
    }
    Skeleton skeleton =
        Skeleton::restore(std::move(jointList), std::move(boneList), root, std::move(attachments));
    if (skeleton.jointCount() > 0)
        if (const std::vector<Message> problems = skeleton.validate(); !problems.empty())
            fail(MessageId::DataSkeletonNotTree, problems.front());
    return skeleton;
}

}  // namespace

Part partFromJson(const json& object) {
    Part stored;
    Part* part = &stored;
    part->name = text(field(object, "name"), R"("part" "name")");
    part->outline = readVec2s(field(object, "outline"), R"("part" "outline")");

    const json& mesh = field(object, "mesh");
    const std::vector<double> vertices =
        numbers(array(mesh, "vertices"), 3, R"("mesh" "vertices")");
    for (std::size_t i = 0; i < vertices.size(); i += 3)
        part->mesh.vertices.emplace_back(vertices[i], vertices[i + 1], vertices[i + 2]);
    const int vertexCount = part->mesh.vertexCount();
    const json& faces = array(mesh, "faces");
    if (faces.size() % 3 != 0)
        fail(MessageId::DataWrongLength, R"("mesh" "faces")");
    for (std::size_t i = 0; i < faces.size(); i += 3) {
        std::array<int, 3> face{};
        for (int k = 0; k < 3; ++k) {
            face[k] = integer<int>(faces[i + k], R"("mesh" "faces")");
            if (face[k] < 0 || face[k] >= vertexCount)
                fail(MessageId::DataFaceMissingVertex);
        }
        part->mesh.faces.push_back(face);
    }

    const json& origins = field(object, "origins");
    const json& kind = array(origins, "kind");
    const json& region = array(origins, "region");
    const json& section = array(origins, "section");
    const json& axis = array(origins, "axisPosition");
    const json& outline = array(origins, "onOutline");
    const std::size_t originCount = kind.size();
    if (region.size() != originCount || section.size() != originCount ||
        axis.size() != originCount || outline.size() != originCount ||
        (originCount != 0 && originCount != vertices.size() / 3))
        fail(MessageId::DataNotPerVertex, R"("origins")");
    for (std::size_t i = 0; i < originCount; ++i) {
        const int k = integer<int>(kind[i], R"("origins" "kind")");
        if (k != static_cast<int>(RegionKind::Cylindrical) &&
            k != static_cast<int>(RegionKind::Connecting))
            fail(MessageId::DataUnknownOriginKind);
        part->origins.push_back({static_cast<RegionKind>(k),
                                 integer<int>(region[i], R"("origins" "region")"),
                                 integer<int>(section[i], R"("origins" "section")"),
                                 number(axis[i], R"("origins" "axisPosition")"),
                                 boolean(outline[i], R"("origins" "onOutline")")});
    }

    const json& mirror = array(object, "mirror");
    if (!mirror.empty() && static_cast<int>(mirror.size()) != vertexCount)
        fail(MessageId::DataNotPerVertex, R"("mirror")");
    for (const json& m : mirror) {
        const int index = integer<int>(m, R"("mirror")");
        if (index < 0 || index >= vertexCount)
            fail(MessageId::DataMirrorMissingVertex);
        part->mirror.push_back(index);
    }

    part->skeleton = readSkeleton(field(object, "skeleton"));
    const int boneCount = part->skeleton.boneCount();
    // Documents written before skin weights were keyed by bone id (format
    // version 1) name bones by their position in the bone list.
    const json& weights = field(object, "weights");
    const bool byIndex = !weights.contains("byBoneId");
    const json& perVertex = array(weights, byIndex ? "perVertex" : "byBoneId");
    if (boneCount > 0 && static_cast<int>(perVertex.size()) != vertexCount)
        fail(MessageId::DataWeightsMissing);
    part->weights.perVertex =
        readPairs(perVertex, vertexCount, part->skeleton, byIndex, PairValues::Weights,
                  byIndex ? R"("weights" "perVertex")" : R"("weights" "byBoneId")");
    for (const json& b : array(weights, byIndex ? "failedBones" : "failedBoneIds"))
        part->weights.failedBones.push_back(
            readBone(b, part->skeleton, byIndex, R"("weights" "failedBones")"));
    part->weights.warnings = readWarnings(array(weights, "warnings"));
    part->knownClosestBones = readPairs(
        array(object, byIndex ? "knownClosestBones" : "knownClosestByBoneId"), vertexCount,
        part->skeleton, byIndex, PairValues::Distances, R"("knownClosestBones")");
    if (object.contains("boneNames"))  // optional: older files lack it
        for (const json& entry : array(object, "boneNames")) {
            if (!entry.is_array() || entry.size() != 2)
                fail(MessageId::DataBoneNameMalformed);
            const auto bone = integer<BoneId>(entry[0], R"("boneNames")");
            if (!part->skeleton.hasBone(bone) || part->boneNames.contains(bone))
                fail(MessageId::DataBoneNameMissingBone);
            part->boneNames[bone] = text(entry[1], R"("boneNames")");
        }
    if (object.contains("lockedBones"))  // optional: older files lack it
        for (const json& entry : array(object, "lockedBones")) {
            const auto bone = integer<BoneId>(entry, R"("lockedBones")");
            if (!part->skeleton.hasBone(bone) || !part->lockedBones.insert(bone).second)
                fail(MessageId::DataLockedBoneMissing);
        }
    if (object.contains("weightsPainted"))  // optional: older files lack it
        part->weightsPainted = boolean(field(object, "weightsPainted"), R"("weightsPainted")");
    if (object.contains("boneFrames"))  // since format version 5
        for (const json& entry : array(object, "boneFrames")) {
            if (!entry.is_array() || entry.size() != 5)
                fail(MessageId::DataBoneFrameMalformed);
            const auto bone = integer<BoneId>(entry[0], R"("boneFrames")");
            const Eigen::Quaterniond q(
                number(entry[1], R"("boneFrames")"), number(entry[2], R"("boneFrames")"),
                number(entry[3], R"("boneFrames")"), number(entry[4], R"("boneFrames")"));
            if (!part->skeleton.hasBone(bone) || std::abs(q.squaredNorm() - 1.0) > 1e-6 ||
                !part->boneFrames.emplace(bone, q).second)
                fail(MessageId::DataBoneFrameInvalid);
        }
    if (object.contains("meshPieces"))  // since format version 5
        for (const json& entry : array(object, "meshPieces"))
            part->meshPieces.push_back(
                {text(field(entry, "name"), R"("meshPieces" "name")"),
                 integer<int>(field(entry, "vertexCount"), R"("meshPieces" "vertexCount")"),
                 integer<int>(field(entry, "faceCount"), R"("meshPieces" "faceCount")")});
    if (!part->meshPieces.empty())
        if (const std::vector<Message> problems = part->validate(); !problems.empty())
            fail(MessageId::DataPartInvalid, problems.front());
    // Parts written before the flag was stored: a sketch's surface (it keeps
    // its outline) was made here; of the others (merges, cuts, imports) one
    // that is closed, manifold and oriented is treated as made here, so the
    // loader keeps checking it, and any other was an import, kept as it was.
    part->surfaceFromFile = object.contains("surfaceFromFile")
                                ? boolean(field(object, "surfaceFromFile"), R"("surfaceFromFile")")
                                : part->outline.empty() && !part->validateSolid().empty();
    return stored;
}

}  // namespace rigmesh
