#include "model/DocumentFile.h"

#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "model/BoundedCbor.h"
#include "model/ClipModes.h"
#include "model/DocumentNodeJson.h"
#include "model/PartBuilder.h"

namespace rigmesh::model {

namespace {

using nlohmann::json;

// A document nests about 7 levels; anything deeper is not ours.
constexpr int kMaxNesting = 32;
// Skin weights of a vertex sum to 1 up to rounding (and float imports).
constexpr double kWeightSumTolerance = 1e-6;
// Placement rotations are unit quaternions up to rounding.
constexpr double kUnitTolerance = 1e-6;

// CBOR's "self-described CBOR" tag (RFC 8949, 3.4.6): the file's magic.
constexpr unsigned char kMagic[] = {0xD9, 0xD9, 0xF7};

QString tr(const char* text) {
    return QCoreApplication::translate("DocumentFile", text);
}

[[noreturn]] void fail(const QString& message) {
    throw DocumentFileError(message.toStdString());
}

[[noreturn]] void corrupt(const std::string& detail) {
    fail(tr("The document is corrupt: %1.").arg(QString::fromStdString(detail)));
}

// ---- Reading: every access checked, every failure a DocumentFileError ----

const json& field(const json& object, const char* key) {
    if (!object.is_object())
        corrupt("expected a map holding \"" + std::string(key) + "\"");
    const auto it = object.find(key);
    if (it == object.end())
        corrupt("missing \"" + std::string(key) + "\"");
    return *it;
}

const json& array(const json& object, const char* key) {
    const json& value = field(object, key);
    if (!value.is_array())
        corrupt("\"" + std::string(key) + "\" is not a list");
    return value;
}

// Any number, finite or not: for readers that name the part in their own
// finiteness message.
double rawNumber(const json& value, const char* what) {
    if (!value.is_number())
        corrupt(std::string(what) + " is not a number");
    return value.get<double>();
}

// Every number in a document is finite: NaN or infinity anywhere is damage.
double number(const json& value, const char* what) {
    const double out = rawNumber(value, what);
    if (!std::isfinite(out))
        corrupt(std::string(what) + " holds a value that is not finite");
    return out;
}

template <typename Int>
Int integer(const json& value, const char* what) {
    if (!value.is_number_integer())
        corrupt(std::string(what) + " is not an integer");
    if (value.is_number_unsigned()) {
        const auto v = value.get<std::uint64_t>();
        if (v > static_cast<std::uint64_t>(std::numeric_limits<Int>::max()))
            corrupt(std::string(what) + " is out of range");
        return static_cast<Int>(v);
    }
    const auto v = value.get<std::int64_t>();
    if (v < static_cast<std::int64_t>(std::numeric_limits<Int>::min()) ||
        (v > 0 && static_cast<std::uint64_t>(v) >
                      static_cast<std::uint64_t>(std::numeric_limits<Int>::max())))
        corrupt(std::string(what) + " is out of range");
    return static_cast<Int>(v);
}

bool boolean(const json& value, const char* what) {
    if (!value.is_boolean())
        corrupt(std::string(what) + " is not true or false");
    return value.get<bool>();
}

std::string text(const json& value, const char* what) {
    if (!value.is_string())
        corrupt(std::string(what) + " is not text");
    return value.get<std::string>();
}

std::vector<double> numbers(const json& list, std::size_t multiple, const char* what,
                            double (*read)(const json&, const char*) = &number) {
    if (!list.is_array() || list.size() % multiple != 0)
        corrupt(std::string(what) + " has the wrong length");
    std::vector<double> out;
    out.reserve(list.size());
    for (const json& v : list)
        out.push_back(read(v, what));
    return out;
}

std::vector<Vec2> readVec2s(const json& list, const char* what) {
    const std::vector<double> flat = numbers(list, 2, what);
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < flat.size(); i += 2)
        out.emplace_back(flat[i], flat[i + 1]);
    return out;
}

enum class PairValues { Weights, Distances };

std::vector<std::vector<std::pair<int, double>>> readPairs(const json& list, std::size_t count,
                                                           int indexLimit, PairValues values,
                                                           const char* what) {
    if (!list.is_array() || (list.size() != count && !list.empty()))
        corrupt(std::string(what) + " does not have one entry per vertex");
    std::vector<std::vector<std::pair<int, double>>> out;
    out.reserve(list.size());
    for (const json& flat : list) {
        if (!flat.is_array() || flat.size() % 2 != 0)
            corrupt(std::string(what) + " has a malformed entry");
        auto& entry = out.emplace_back();
        for (std::size_t i = 0; i < flat.size(); i += 2) {
            const int index = integer<int>(flat[i], what);
            if (index < 0 || index >= indexLimit)
                corrupt(std::string(what) + " refers to a missing bone");
            const double value = number(flat[i + 1], what);
            if (value < 0)
                corrupt(std::string(what) + " holds a negative value");
            entry.emplace_back(index, value);
        }
        if (values == PairValues::Weights && !entry.empty()) {
            double sum = 0;
            for (const auto& pair : entry)
                sum += pair.second;
            if (std::abs(sum - 1.0) > kWeightSumTolerance)
                corrupt(std::string(what) + " of vertex " + std::to_string(out.size() - 1) +
                        " sum to " + std::to_string(sum) + " instead of 1");
        }
    }
    return out;
}

Skeleton readSkeleton(const json& object) {
    const json& joints = field(object, "joints");
    const json& jointIds = array(joints, "ids");
    const std::vector<double> positions = numbers(array(joints, "positions"), 3, "joint positions");
    if (positions.size() != 3 * jointIds.size())
        corrupt("joint ids and positions differ in number");
    std::vector<Joint> jointList;
    std::set<JointId> known;
    for (std::size_t i = 0; i < jointIds.size(); ++i) {
        const auto id = integer<JointId>(jointIds[i], "joint id");
        if (id == kNoJoint || !known.insert(id).second)
            corrupt("duplicate or invalid joint id");
        jointList.push_back(
            {id, Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2])});
    }
    const json& bones = field(object, "bones");
    const json& boneIds = array(bones, "ids");
    const json& heads = array(bones, "heads");
    const json& tails = array(bones, "tails");
    if (heads.size() != boneIds.size() || tails.size() != boneIds.size())
        corrupt("bone ids, heads and tails differ in number");
    std::vector<Bone> boneList;
    std::set<BoneId> knownBones;
    for (std::size_t i = 0; i < boneIds.size(); ++i) {
        const Bone bone{integer<BoneId>(boneIds[i], "bone id"),
                        integer<JointId>(heads[i], "bone head"),
                        integer<JointId>(tails[i], "bone tail")};
        if (!knownBones.insert(bone.id).second)
            corrupt("duplicate bone id");
        if (!known.contains(bone.head) || !known.contains(bone.tail))
            corrupt("a bone refers to a missing joint");
        boneList.push_back(bone);
    }
    const auto root = integer<JointId>(field(object, "root"), "skeleton root");
    if (root != kNoJoint ? !known.contains(root) : !known.empty())
        corrupt("the skeleton root is not one of its joints");
    Skeleton skeleton = Skeleton::restore(std::move(jointList), std::move(boneList), root);
    if (skeleton.jointCount() > 0)
        if (const std::vector<std::string> problems = skeleton.validate(); !problems.empty())
            corrupt("the skeleton is not a tree: " + problems.front());
    return skeleton;
}

std::shared_ptr<const Part> readPart(const json& object) {
    auto part = std::make_shared<Part>();
    part->name = text(field(object, "name"), "part name");
    part->outline = readVec2s(field(object, "outline"), "outline");

    const json& mesh = field(object, "mesh");
    const std::vector<double> vertices = numbers(array(mesh, "vertices"), 3, "mesh vertices");
    for (std::size_t i = 0; i < vertices.size(); i += 3)
        part->mesh.vertices.emplace_back(vertices[i], vertices[i + 1], vertices[i + 2]);
    const int vertexCount = part->mesh.vertexCount();
    const json& faces = array(mesh, "faces");
    if (faces.size() % 3 != 0)
        corrupt("mesh faces have the wrong length");
    for (std::size_t i = 0; i < faces.size(); i += 3) {
        std::array<int, 3> face{};
        for (int k = 0; k < 3; ++k) {
            face[k] = integer<int>(faces[i + k], "face index");
            if (face[k] < 0 || face[k] >= vertexCount)
                corrupt("a face refers to a missing vertex");
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
        corrupt("vertex origins do not have one entry per vertex");
    for (std::size_t i = 0; i < originCount; ++i) {
        const int k = integer<int>(kind[i], "origin kind");
        if (k != static_cast<int>(RegionKind::Cylindrical) &&
            k != static_cast<int>(RegionKind::Connecting))
            corrupt("unknown vertex origin kind");
        part->origins.push_back(
            {static_cast<RegionKind>(k), integer<int>(region[i], "origin region"),
             integer<int>(section[i], "origin section"), number(axis[i], "origin axis position"),
             boolean(outline[i], "origin on outline")});
    }

    const json& mirror = array(object, "mirror");
    if (!mirror.empty() && static_cast<int>(mirror.size()) != vertexCount)
        corrupt("the mirror map does not have one entry per vertex");
    for (const json& m : mirror) {
        const int index = integer<int>(m, "mirror index");
        if (index < 0 || index >= vertexCount)
            corrupt("the mirror map refers to a missing vertex");
        part->mirror.push_back(index);
    }

    part->skeleton = readSkeleton(field(object, "skeleton"));
    const int boneCount = part->skeleton.boneCount();
    const json& weights = field(object, "weights");
    if (boneCount > 0 && static_cast<int>(array(weights, "perVertex").size()) != vertexCount)
        corrupt("a rigged part needs skin weights for every vertex");
    part->weights.perVertex = readPairs(array(weights, "perVertex"), vertexCount, boneCount,
                                        PairValues::Weights, "skin weights");
    for (const json& b : array(weights, "failedBones")) {
        const int bone = integer<int>(b, "failed bone");
        if (bone < 0 || bone >= boneCount)
            corrupt("failed bones refer to a missing bone");
        part->weights.failedBones.push_back(bone);
    }
    part->weights.warning = text(field(weights, "warning"), "weights warning");
    part->knownClosestBones = readPairs(array(object, "knownClosestBones"), vertexCount, boneCount,
                                        PairValues::Distances, "known closest bones");
    if (object.contains("boneNames"))  // since issue 18
        for (const json& entry : array(object, "boneNames")) {
            if (!entry.is_array() || entry.size() != 2)
                corrupt("a bone name is not [bone id, name]");
            const auto bone = integer<BoneId>(entry[0], "named bone");
            if (!part->skeleton.hasBone(bone) || part->boneNames.contains(bone))
                corrupt("a bone name refers to a missing bone, or twice to one");
            part->boneNames[bone] = text(entry[1], "bone name");
        }
    return part;
}

std::string partLabel(const PartNode& node) {
    return "part " + std::to_string(node.id) + " (\"" + node.name.toStdString() + "\")";
}

JointId readJointOf(const PartNode& node, const json& value, const char* what) {
    const auto joint = integer<JointId>(value, what);
    if (!node.part->skeleton.hasJoint(joint))
        corrupt(std::string(what) + " " + std::to_string(joint) + " of " + partLabel(node) +
                " is not a joint of its skeleton");
    return joint;
}

rigmesh::Pose readPoseValue(const PartNode& node, const json& pose) {
    rigmesh::Pose out;
    for (const json& entry : array(pose, "rotations")) {
        if (!entry.is_array() || entry.size() != 5)
            corrupt("a pose rotation of " + partLabel(node) + " is not [joint, w, x, y, z]");
        const JointId joint = readJointOf(node, entry[0], "pose joint");
        const Eigen::Quaterniond q(
            rawNumber(entry[1], "pose rotation"), rawNumber(entry[2], "pose rotation"),
            rawNumber(entry[3], "pose rotation"), rawNumber(entry[4], "pose rotation"));
        if (!q.coeffs().allFinite() || q.coeffs().squaredNorm() == 0.0)
            corrupt("the pose rotation of joint " + std::to_string(joint) + " of " +
                    partLabel(node) + " is not finite or is zero");
        if (!out.rotations.emplace(joint, q).second)
            corrupt("the pose of " + partLabel(node) + " rotates joint " + std::to_string(joint) +
                    " twice");
    }
    const std::vector<double> t =
        numbers(array(pose, "rootTranslation"), 3, "pose root translation", &rawNumber);
    if (t.size() != 3)
        corrupt("the pose root translation of " + partLabel(node) + " has the wrong length");
    out.rootTranslation = Vec3(t[0], t[1], t[2]);
    if (!out.rootTranslation.allFinite())
        corrupt("the pose root translation of " + partLabel(node) + " is not finite");
    return out;
}

// Absent (files written before poses were stored): the rest pose.
rigmesh::Pose readPose(const PartNode& node, const json& object) {
    if (!object.contains("pose"))
        return restPoseOf(node);
    return readPoseValue(node, field(object, "pose"));
}

template <typename Enum>
Enum readMode(const json& value, const char* what,
              std::optional<Enum> (*fromName)(std::string_view)) {
    const std::string name = text(value, what);
    if (const std::optional<Enum> mode = fromName(name))
        return *mode;
    corrupt(std::string("unknown ") + what + " \"" + name + "\"");
}

// Absent (files written before clips were stored): no keys at 24 fps.
rigmesh::Clip readClip(const PartNode& node, const json& object) {
    if (!object.contains("clip"))
        return rigmesh::Clip();
    const json& clip = field(object, "clip");
    const double fps = rawNumber(field(clip, "framesPerSecond"), "clip frame rate");
    if (!std::isfinite(fps) || !(fps > 0))
        corrupt("the clip frame rate of " + partLabel(node) + " is not positive");
    // Keys go in with a vanishing tolerance, so keys closer than half a frame
    // (left by a frame rate change) come back exactly; the frame rate is set
    // last.
    rigmesh::Clip out(std::numeric_limits<double>::max());
    for (const json& key : array(clip, "keys")) {
        const double time = rawNumber(field(key, "time"), "key time");
        if (!std::isfinite(time))
            corrupt("a key time of " + partLabel(node) + " is not finite");
        const int before = out.keyCount();
        out.setKey(time, readPoseValue(node, field(key, "pose")));
        if (out.keyCount() != before + 1)
            corrupt("the clip of " + partLabel(node) + " has two keys at one time");
    }
    out.setFramesPerSecond(fps);
    out.interpolation =
        readMode(field(clip, "interpolation"), "clip interpolation", &interpolationFromName);
    out.mode = readMode(field(clip, "playback"), "clip playback", &playbackFromName);
    if (clip.contains("name"))  // since issue 18
        out.name = text(field(clip, "name"), "clip name");
    return out;
}

std::set<JointId> readPinned(const PartNode& node, const json& object) {
    std::set<JointId> out;
    if (!object.contains("pinned"))
        return out;
    for (const json& value : array(object, "pinned")) {
        if (!out.insert(readJointOf(node, value, "pinned joint")).second)
            corrupt("a joint of " + partLabel(node) + " is pinned twice");
    }
    return out;
}

PartNode readNode(const json& object) {
    PartNode node;
    node.id = integer<PartId>(field(object, "id"), "part id");
    if (node.id == kNoPart)
        corrupt("a part has no id");
    node.name = QString::fromStdString(text(field(object, "name"), "part name"));
    node.visible = boolean(field(object, "visible"), "part visibility");
    const json& placement = field(object, "placement");
    const std::vector<double> t = numbers(array(placement, "translation"), 3, "translation");
    const std::vector<double> r = numbers(array(placement, "rotation"), 4, "rotation");
    if (t.size() != 3 || r.size() != 4)
        corrupt("a placement has the wrong length");
    node.placement.translation = Vec3(t[0], t[1], t[2]);
    node.placement.rotation = Eigen::Quaterniond(r[0], r[1], r[2], r[3]);
    if (std::abs(node.placement.rotation.norm() - 1.0) > kUnitTolerance)
        corrupt("the placement rotation of part " + std::to_string(node.id) +
                " is not a unit quaternion");
    node.stroke = readVec2s(field(object, "stroke"), "stroke");
    const json& options = field(object, "options");
    node.options.targetEdgeLength =
        number(field(options, "targetEdgeLength"), "target edge length");
    node.options.smoothing = boolean(field(options, "smoothing"), "smoothing");
    try {
        checkBuildOptions(node.stroke, node.options);
    } catch (const Error& e) {
        corrupt("part " + std::to_string(node.id) + ": " + e.what());
    }
    if (!object.contains("part"))
        corrupt("a part has no geometry");
    node.part = readPart(object.at("part"));
    node.pose = readPose(node, object);
    node.pinnedJoints = readPinned(node, object);
    node.clip = readClip(node, object);
    return node;
}

DocumentContents readContents(const json& root) {
    if (!root.is_object() || !root.contains("format") || !root["format"].is_string() ||
        root["format"].get<std::string>() != DocumentFile::kFormatName)
        fail(tr("This is not a RigMesh Studio document."));
    const json& versionField = field(root, "version");
    if (!versionField.is_number_integer() || versionField.get<std::int64_t>() < 1)
        corrupt("invalid format version");
    const std::int64_t version = versionField.get<std::int64_t>();
    if (version > DocumentFile::kFormatVersion)
        fail(tr("This document was saved by a newer RigMesh Studio (format version %1); this "
                "version reads format version %2 and older. Please update RigMesh Studio.")
                 .arg(version)
                 .arg(DocumentFile::kFormatVersion));

    DocumentContents contents;
    std::set<PartId> ids;
    for (const json& node : array(root, "parts")) {
        contents.parts.push_back(readNode(node));
        if (!ids.insert(contents.parts.back().id).second)
            corrupt("two parts have the same id");
    }
    contents.nextPartId = integer<PartId>(field(root, "nextPartId"), "next part id");
    if (contents.nextPartId == kNoPart || (!ids.empty() && contents.nextPartId <= *ids.rbegin()))
        corrupt("the next part id is already in use");
    return contents;
}

}  // namespace

namespace DocumentFile {

QByteArray toBytes(const DocumentContents& contents) {
    json root = {{"format", kFormatName},
                 {"version", kFormatVersion},
                 {"nextPartId", contents.nextPartId},
                 {"parts", json::array()}};
    for (const PartNode& node : contents.parts)
        root["parts"].push_back(documentNodeJson(node));
    std::vector<std::uint8_t> bytes(std::begin(kMagic), std::end(kMagic));
    json::to_cbor(root, bytes);
    return QByteArray(reinterpret_cast<const char*>(bytes.data()),
                      static_cast<qsizetype>(bytes.size()));
}

DocumentContents fromBytes(const QByteArray& bytes) {
    if (bytes.isEmpty())
        fail(tr("The file is empty."));
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.constData());
    const auto size = static_cast<std::size_t>(bytes.size());
    if (size < sizeof kMagic || !std::equal(std::begin(kMagic), std::end(kMagic), data))
        fail(tr("This is not a RigMesh Studio document."));
    json root;
    try {
        root = parseBoundedCbor(data + sizeof kMagic, data + size, kMaxNesting);
    } catch (const json::exception& e) {
        fail(tr("The document is corrupt or truncated (%1).").arg(QString::fromUtf8(e.what())));
    } catch (const Error& e) {
        corrupt(e.what());
    }
    try {
        return readContents(root);
    } catch (const json::exception& e) {
        corrupt(e.what());
    } catch (const DocumentFileError&) {
        throw;
    } catch (const Error& e) {  // an engine value refused what the file holds
        corrupt(e.what());
    }
}

void write(const Document& document, const QString& path) {
    const QByteArray bytes = toBytes(document);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        fail(tr("Cannot save \"%1\": %2").arg(path, file.errorString()));
}

void save(Document& document, const QString& path) {
    write(document, path);
    document.markSaved(path);
}

DocumentContents read(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        fail(tr("Cannot open \"%1\": %2").arg(path, file.errorString()));
    const QByteArray bytes = file.readAll();
    try {
        return fromBytes(bytes);
    } catch (const DocumentFileError& e) {
        fail(tr("Cannot open \"%1\": %2").arg(path, QString::fromStdString(e.what())));
    }
}

std::unique_ptr<Document> load(const QString& path, QObject* parent) {
    auto document = std::make_unique<Document>(read(path), parent);
    document->setFilePath(path);
    return document;
}

}  // namespace DocumentFile

}  // namespace rigmesh::model
