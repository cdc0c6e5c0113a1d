#include "model/DocumentFile.h"

#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>
#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "base/JsonRead.h"
#include "model/BoundedCbor.h"
#include "model/ClipModes.h"
#include "model/DocumentMigration.h"
#include "model/DocumentNodeJson.h"
#include "model/ErrorText.h"
#include "model/PartBuilder.h"
#include "model/PartClips.h"
#include "part/PartJson.h"
#include "pose/LegacyPose.h"

namespace rigmesh::model {

namespace {

using nlohmann::json;
using namespace jsonread;

// A document nests about 7 levels; anything deeper is not ours.
constexpr int kMaxNesting = 32;
// Placement rotations are unit quaternions up to rounding.
constexpr double kUnitTolerance = 1e-6;

// CBOR's "self-described CBOR" tag (RFC 8949, 3.4.6): the file's magic.
constexpr unsigned char kMagic[] = {0xD9, 0xD9, 0xF7};

[[noreturn]] void fail(const QString& message) {
    throw DocumentFileError(message.toStdString());
}

// The context of every text here. lupdate reads only literals: each
// detail names it in QT_TRANSLATE_NOOP, each translate() call in full.
constexpr const char* kContext = "rigmesh::model::DocumentFile";

QString argumentText(const QString& text) {
    return text;
}
QString argumentText(const std::string& text) {
    return QString::fromStdString(text);
}
template <std::integral Integer>
QString argumentText(Integer value) {
    return QString::number(value);
}

[[noreturn]] void corrupt(const QString& detail) {
    fail(QCoreApplication::translate("rigmesh::model::DocumentFile", "The document is corrupt: %1.")
             .arg(detail));
}

// "The document is corrupt: " and `detail` translated, its markers filled
// with `args` in one pass.
template <class... Args>
[[noreturn]] void corrupt(const char* detail, const Args&... args) {
    const QString text = QCoreApplication::translate(kContext, detail);
    if constexpr (sizeof...(Args) == 0)
        corrupt(text);
    else
        corrupt(text.arg(argumentText(args)...));
}

// What an engine value's refusal says, translated (model/ErrorText).
[[noreturn]] void corrupt(const std::exception& error) {
    corrupt(errorText(error));
}

QString partLabel(const PartNode& node) {
    return QCoreApplication::translate("rigmesh::model::DocumentFile", "part %1 (\"%2\")")
        .arg(QString::number(node.id), node.name);
}

// Every part keeps Part::validate(); a rigged part whose surface was made
// here (not read from another program's file) is also closed, manifold and
// consistently oriented, which merge and cut rely on (Part::validateSolid).
void checkPartInvariants(const PartNode& node) {
    const Part& part = *node.part;
    std::vector<Message> problems = part.validate();
    if (problems.empty() && part.skeleton.boneCount() > 0 && !part.surfaceFromFile)
        problems = part.validateSolid();
    if (!problems.empty()) {
        QString problem = messageText(problems.front());
        if (problem.endsWith(QLatin1Char('.')))
            problem.chop(1);  // corrupt() ends the sentence
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "%1: %2"), partLabel(node),
                problem);
    }
}

// `path`: the value's place in the file; `notAJoint`: the sentence that
// names it when it is no joint of the part's skeleton (%1 the joint, %2 the
// part).
JointId readJointOf(const PartNode& node, const json& value, const char* path,
                    const char* notAJoint) {
    const auto joint = integer<JointId>(value, path);
    if (!node.part->skeleton.hasJoint(joint))
        corrupt(notAJoint, joint, partLabel(node));
    return joint;
}

rigmesh::Pose readPoseValue(const PartNode& node, const json& pose) {
    rigmesh::Pose out;
    for (const json& entry : array(pose, "rotations")) {
        if (!entry.is_array() || entry.size() != 5)
            corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                      "a pose rotation of %1 is not [joint, w, x, y, z]"),
                    partLabel(node));
        const JointId joint =
            readJointOf(node, entry[0], R"("pose" "rotations")",
                        QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                          "pose joint %1 of %2 is not a joint of its skeleton"));
        const Eigen::Quaterniond q(rawNumber(entry[1], R"("pose" "rotations")"),
                                   rawNumber(entry[2], R"("pose" "rotations")"),
                                   rawNumber(entry[3], R"("pose" "rotations")"),
                                   rawNumber(entry[4], R"("pose" "rotations")"));
        if (!q.coeffs().allFinite() || q.coeffs().squaredNorm() == 0.0)
            corrupt(
                QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the pose rotation of joint %1 of %2 is not finite or is zero"),
                joint, partLabel(node));
        if (!out.rotations.emplace(joint, q).second)
            corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                      "the pose of %1 rotates joint %2 twice"),
                    partLabel(node), joint);
    }
    const std::vector<double> t =
        numbers(array(pose, "rootTranslation"), 3, R"("pose" "rootTranslation")", &rawNumber);
    if (t.size() != 3)
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the pose root translation of %1 has the wrong length"),
                partLabel(node));
    out.rootTranslation = Vec3(t[0], t[1], t[2]);
    if (!out.rootTranslation.allFinite())
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the pose root translation of %1 is not finite"),
                partLabel(node));
    return out;
}

// Absent (files written before poses were stored): the rest pose.
rigmesh::Pose readPose(const PartNode& node, const json& object) {
    if (!object.contains("pose"))
        return restPoseOf(node);
    return readPoseValue(node, field(object, "pose"));
}

// `unknown`: the sentence naming a name that is no mode (%1 the name).
template <typename Enum>
Enum readMode(const json& value, const char* path, const char* unknown,
              std::optional<Enum> (*fromName)(std::string_view)) {
    const std::string name = text(value, path);
    if (const std::optional<Enum> mode = fromName(name))
        return *mode;
    corrupt(unknown, name);
}

rigmesh::Clip readClipValue(const PartNode& node, const json& clip) {
    const double fps = rawNumber(field(clip, "framesPerSecond"), R"("clip" "framesPerSecond")");
    if (!std::isfinite(fps) || !(fps > 0))
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the clip frame rate of %1 is not positive"),
                partLabel(node));
    // Keys go in with a vanishing tolerance, so keys closer than half a frame
    // (left by a frame rate change) come back exactly; the frame rate is set
    // last.
    rigmesh::Clip out(std::numeric_limits<double>::max());
    std::vector<std::pair<double, rigmesh::Pose>> keys;
    double start = 0.0;
    for (const json& key : array(clip, "keys")) {
        const double time = rawNumber(field(key, "time"), R"("clip" "keys" "time")");
        if (!std::isfinite(time))
            corrupt(
                QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "a key time of %1 is not finite"),
                partLabel(node));
        start = std::min(start, time);
        keys.emplace_back(time, readPoseValue(node, field(key, "pose")));
    }
    // Keys lie at 0 s or later (pose/Clip.h); older versions let them go
    // below, so such a clip moves as a whole to start at 0 s, as an import does.
    for (auto& [time, pose] : keys) {
        const int before = out.keyCount();
        out.setKey(time - start, pose);
        if (out.keyCount() != before + 1)
            corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                      "the clip of %1 has two keys at one time"),
                    partLabel(node));
    }
    out.setFramesPerSecond(fps);
    out.interpolation = readMode(
        field(clip, "interpolation"), R"("clip" "interpolation")",
        QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "unknown clip interpolation \"%1\""),
        &interpolationFromName);
    out.mode =
        readMode(field(clip, "playback"), R"("clip" "playback")",
                 QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "unknown clip playback \"%1\""),
                 &playbackFromName);
    if (clip.contains("name"))  // optional: older files lack it
        out.name = text(field(clip, "name"), R"("clip" "name")");
    return out;
}

// Absent (files written before clips were stored): no keys at 24 fps.
rigmesh::Clip readClip(const PartNode& node, const json& object) {
    if (!object.contains("clip"))
        return rigmesh::Clip();
    return readClipValue(node, field(object, "clip"));
}

// The part's other named clips (format version 2), unique by name.
std::vector<rigmesh::Clip> readOtherClips(const PartNode& node, const json& object) {
    std::vector<rigmesh::Clip> out;
    for (const json& clip : array(object, "otherClips"))
        out.push_back(readClipValue(node, clip));
    try {
        checkClipNamesUnique(node.clip, out);
    } catch (const Error& e) {
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "%1: %2"), partLabel(node),
                errorText(e));
    }
    return sortedByName(std::move(out));
}

TimelineSettings readTimeline(const json& root, int& currentFrame) {
    const json& timeline = field(root, "timeline");
    TimelineSettings out;
    out.startFrame = integer<int>(field(timeline, "startFrame"), R"("timeline" "startFrame")");
    out.endFrame = integer<int>(field(timeline, "endFrame"), R"("timeline" "endFrame")");
    out.framesPerSecond =
        number(field(timeline, "framesPerSecond"), R"("timeline" "framesPerSecond")");
    currentFrame = integer<int>(field(timeline, "currentFrame"), R"("timeline" "currentFrame")");
    try {
        checkTimelineSettings(out);
        checkFrame(currentFrame);
    } catch (const Error& e) {
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "the timeline: %1"),
                errorText(e));
    }
    return out;
}

std::set<JointId> readPinned(const PartNode& node, const json& object) {
    std::set<JointId> out;
    if (!object.contains("pinned"))
        return out;
    for (const json& value : array(object, "pinned")) {
        if (!out.insert(readJointOf(node, value, R"("pinned")",
                                    QT_TRANSLATE_NOOP(
                                        "rigmesh::model::DocumentFile",
                                        "pinned joint %1 of %2 is not a joint of its skeleton")))
                 .second)
            corrupt(
                QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "a joint of %1 is pinned twice"),
                partLabel(node));
    }
    return out;
}

PartNode readNode(const json& object) {
    PartNode node;
    node.id = integer<PartId>(field(object, "id"), R"("parts" "id")");
    if (node.id == kNoPart)
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "a part has no id"));
    node.name = QString::fromStdString(text(field(object, "name"), R"("parts" "name")"));
    node.visible = boolean(field(object, "visible"), R"("parts" "visible")");
    const json& placement = field(object, "placement");
    const std::vector<double> t =
        numbers(array(placement, "translation"), 3, R"("placement" "translation")");
    const std::vector<double> r =
        numbers(array(placement, "rotation"), 4, R"("placement" "rotation")");
    if (t.size() != 3 || r.size() != 4)
        corrupt(
            QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "a placement has the wrong length"));
    node.placement.translation = Vec3(t[0], t[1], t[2]);
    node.placement.rotation = Eigen::Quaterniond(r[0], r[1], r[2], r[3]);
    if (std::abs(node.placement.rotation.norm() - 1.0) > kUnitTolerance)
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the placement rotation of part %1 is not a unit quaternion"),
                node.id);
    node.stroke = readVec2s(field(object, "stroke"), R"("stroke")");
    const json& options = field(object, "options");
    node.options.targetEdgeLength =
        number(field(options, "targetEdgeLength"), R"("options" "targetEdgeLength")");
    node.options.smoothing = boolean(field(options, "smoothing"), R"("options" "smoothing")");
    // Parts saved before symmetric outlines got mirrored joints rebuild as
    // they were made.
    node.options.mirrorJoints = options.contains("mirrorJoints") &&
                                boolean(options.at("mirrorJoints"), R"("options" "mirrorJoints")");
    try {
        checkBuildOptions(node.stroke, node.options);
    } catch (const Error& e) {
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "part %1: %2"), node.id,
                errorText(e));
    }
    if (!object.contains("part"))
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "a part has no geometry"));
    node.part = std::make_shared<const Part>(partFromJson(object.at("part")));
    checkPartInvariants(node);
    node.pose = readPose(node, object);
    node.pinnedJoints = readPinned(node, object);
    node.clip = readClip(node, object);
    node.otherClips = readOtherClips(node, object);
    return node;
}

// Version 1 stored one rotation per joint, turning every bone leaving it:
// the same bone transforms as per-bone rotations (pose/LegacyPose.h). A
// version 1 part has one clip (the migration gives it no other).
void convertJointRotations(PartNode& node) {
    if (!node.part || !node.part->skeleton.hasJoint(node.part->skeleton.root()))
        return;
    const PoseHierarchy hierarchy(node.part->skeleton);
    node.pose = poseFromJointRotations(hierarchy, node.pose);
    node.clip = clipFromJointRotations(hierarchy, node.clip);
}

DocumentContents readContents(json root) {
    if (!root.is_object() || !root.contains("format") || !root["format"].is_string() ||
        root["format"].get<std::string>() != DocumentFile::kFormatName)
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile",
                                         "This is not a RigMesh Studio document."));
    const json& versionField = field(root, "version");
    if (!versionField.is_number_integer() || versionField.get<std::int64_t>() < 1)
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "invalid format version"));
    const std::int64_t version = versionField.get<std::int64_t>();
    if (version > DocumentFile::kFormatVersion)
        fail(QCoreApplication::translate(
                 "rigmesh::model::DocumentFile",
                 "This document was saved by a newer RigMesh Studio (format version %1); this "
                 "version reads format version %2 and older. Please update RigMesh Studio.")
                 .arg(version)
                 .arg(DocumentFile::kFormatVersion));

    migrateDocument(root, version);

    DocumentContents contents;
    contents.timeline = readTimeline(root, contents.currentFrame);
    std::set<PartId> ids;
    for (const json& node : array(root, "parts")) {
        contents.parts.push_back(readNode(node));
        if (!ids.insert(contents.parts.back().id).second)
            corrupt(
                QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile", "two parts have the same id"));
        if (version < 2)
            convertJointRotations(contents.parts.back());
    }
    contents.nextPartId = integer<PartId>(field(root, "nextPartId"), R"("nextPartId")");
    if (contents.nextPartId == kNoPart || (!ids.empty() && contents.nextPartId <= *ids.rbegin()))
        corrupt(QT_TRANSLATE_NOOP("rigmesh::model::DocumentFile",
                                  "the next part id is already in use"));
    return contents;
}

}  // namespace

namespace DocumentFile {

QByteArray toBytes(const DocumentContents& contents) {
    json root = {{"format", kFormatName},
                 {"version", kFormatVersion},
                 {"nextPartId", contents.nextPartId},
                 {"timeline",
                  {{"startFrame", contents.timeline.startFrame},
                   {"endFrame", contents.timeline.endFrame},
                   {"framesPerSecond", contents.timeline.framesPerSecond},
                   {"currentFrame", contents.currentFrame}}},
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
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile", "The file is empty."));
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.constData());
    const auto size = static_cast<std::size_t>(bytes.size());
    if (size < sizeof kMagic || !std::equal(std::begin(kMagic), std::end(kMagic), data))
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile",
                                         "This is not a RigMesh Studio document."));
    json root;
    try {
        root = parseBoundedCbor(data + sizeof kMagic, data + size, kMaxNesting);
    } catch (const json::exception& e) {
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile",
                                         "The document is corrupt or truncated (%1).")
                 .arg(messageText(parseErrorReason(e))));
    } catch (const Error& e) {
        corrupt(e);
    }
    try {
        return readContents(std::move(root));
    } catch (const json::exception& e) {
        corrupt(messageText(parseErrorReason(e)));
    } catch (const DocumentFileError&) {
        throw;
    } catch (const Error& e) {  // an engine value refused what the file holds
        corrupt(e);
    }
}

void write(const Document& document, const QString& path) {
    const QByteArray bytes = toBytes(document);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile", "Cannot save \"%1\": %2")
                 .arg(path, file.errorString()));
}

void save(Document& document, const QString& path) {
    write(document, path);
    document.markSaved(path);
}

DocumentContents read(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile", "Cannot open \"%1\": %2")
                 .arg(path, file.errorString()));
    const QByteArray bytes = file.readAll();
    try {
        return fromBytes(bytes);
    } catch (const DocumentFileError& e) {
        fail(QCoreApplication::translate("rigmesh::model::DocumentFile", "Cannot open \"%1\": %2")
                 .arg(path, QString::fromStdString(e.what())));
    }
}

std::unique_ptr<Document> load(const QString& path, QObject* parent) {
    auto document = std::make_unique<Document>(read(path), parent);
    document->setFilePath(path);
    return document;
}

}  // namespace DocumentFile

}  // namespace rigmesh::model
