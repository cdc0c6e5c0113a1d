#include "model/Document.h"

#include <QFileInfo>
#include <algorithm>
#include <stdexcept>

#include "base/Error.h"
#include "model/PartClips.h"

namespace rigmesh::model {

namespace {

const Skeleton* skeletonOf(const PartNode& node) {
    return node.part ? &node.part->skeleton : nullptr;
}

void checkJoint(const PartNode& node, JointId joint) {
    const Skeleton* skeleton = skeletonOf(node);
    if (!skeleton || !skeleton->hasJoint(joint))
        throw Error(MessageId::DocumentPartHasNoJoint, node.id, joint);
}

void checkPose(const PartNode& node, const rigmesh::Pose& pose) {
    if (!pose.isFinite())
        throw Error(MessageId::DocumentPoseInvalid, node.id);
    for (const auto& entry : pose.rotations)
        checkJoint(node, entry.first);
}

void checkPins(const PartNode& node, const std::set<JointId>& pinned) {
    for (const JointId joint : pinned)
        checkJoint(node, joint);
}

bool identicalClipLists(const std::vector<rigmesh::Clip>& a, const std::vector<rigmesh::Clip>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), &identicalClips);
}

void checkClip(const PartNode& node, const rigmesh::Clip& clip) {
    for (const auto& [time, pose] : clip.keys()) {
        if (!pose.isFinite())
            throw Error(MessageId::DocumentKeyPoseInvalid, std::to_string(time), node.id);
        for (const auto& entry : pose.rotations)
            checkJoint(node, entry.first);
    }
}

}  // namespace

Document::Document(QObject* parent) : Document(DocumentContents{}, parent) {}

Document::Document(DocumentContents contents, QObject* parent)
    : QObject(parent), contents_(std::move(contents)) {
    for (const PartNode& node : contents_.parts)
        contents_.nextPartId = std::max(contents_.nextPartId, node.id + 1);
    connect(&undoStack_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() {
    // Commands refer to this document: drop them before its contents go.
    undoStack_.clear();
}

int Document::indexOf(PartId id) const {
    const auto it = std::find_if(contents_.parts.begin(), contents_.parts.end(),
                                 [id](const PartNode& node) { return node.id == id; });
    return it == contents_.parts.end() ? -1 : static_cast<int>(it - contents_.parts.begin());
}

const PartNode* Document::findPart(PartId id) const {
    const int index = indexOf(id);
    return index < 0 ? nullptr : &contents_.parts[index];
}

const PartNode& Document::part(PartId id) const {
    if (const PartNode* node = findPart(id))
        return *node;
    throw Error(MessageId::DocumentNoSuchPart, id);
}

PartNode& Document::mutablePart(PartId id) {
    return const_cast<PartNode&>(part(id));
}

void Document::setFilePath(const QString& path) {
    if (path == filePath_)
        return;
    filePath_ = path;
    emit filePathChanged(path);
}

void Document::setUntitledName(const QString& name) {
    untitledName_ = name;
    emit filePathChanged(filePath_);  // the displayed name changed
}

QString Document::displayName() const {
    if (!filePath_.isEmpty())
        return QFileInfo(filePath_).fileName();
    return untitledName_.isEmpty() ? tr("Untitled") : untitledName_;
}

void Document::markSaved(const QString& path) {
    setFilePath(path);
    undoStack_.setClean();
}

void Document::setSelection(const Selection& selection) {
    Selection valid;
    if (const PartNode* node = findPart(selection.part)) {
        valid.part = selection.part;
        if (node->part && node->part->skeleton.hasJoint(selection.joint))
            valid.joint = selection.joint;
    }
    if (valid == selection_)
        return;
    selection_ = valid;
    emit selectionChanged(selection_);
}

PartId Document::allocatePartId() {
    return contents_.nextPartId++;
}

void Document::releasePartId(PartId id) {
    if (id + 1 == contents_.nextPartId && !contains(id))
        contents_.nextPartId = id;
}

void Document::insertPart(int index, PartNode node) {
    if (node.id == kNoPart || contains(node.id))
        throw std::logic_error("Part id " + std::to_string(node.id) + " is already in use.");
    index = std::clamp(index, 0, partCount());
    const PartId id = node.id;
    contents_.nextPartId = std::max(contents_.nextPartId, id + 1);
    contents_.parts.insert(contents_.parts.begin() + index, std::move(node));
    emit partInserted(id, index);
}

PartNode Document::removePart(PartId id) {
    const int index = indexOf(id);
    if (index < 0)
        throw Error(MessageId::DocumentNoSuchPart, id);
    if (selection_.part == id)
        clearSelection();
    emit partAboutToBeRemoved(id, index);
    PartNode node = std::move(contents_.parts[index]);
    contents_.parts.erase(contents_.parts.begin() + index);
    emit partRemoved(id, index);
    return node;
}

void Document::replaceNode(PartId id, PartNode node) {
    PartNode& old = mutablePart(id);
    if (node.id != id)
        throw std::logic_error("Part " + std::to_string(id) + " cannot be replaced by part " +
                               std::to_string(node.id) + ".");
    checkPose(node, node.pose);
    checkPins(node, node.pinnedJoints);
    checkClip(node, node.clip);
    for (const rigmesh::Clip& other : node.otherClips)
        checkClip(node, other);
    checkClipNamesUnique(node.clip, node.otherClips);
    node.otherClips = sortedByName(std::move(node.otherClips));
    Changes what;
    if (old.name != node.name)
        what |= Change::Name;
    if (!(old.placement == node.placement))
        what |= Change::Placement;
    if (old.visible != node.visible)
        what |= Change::Visibility;
    if (old.part != node.part)
        what |= Change::Geometry;
    if (!(old.options == node.options) || old.stroke != node.stroke)
        what |= Change::Options;
    if (!identicalPoses(old.pose, node.pose))
        what |= Change::Pose;
    if (old.pinnedJoints != node.pinnedJoints)
        what |= Change::Pins;
    if (!identicalClips(old.clip, node.clip) ||
        !identicalClipLists(old.otherClips, node.otherClips))
        what |= Change::Clip;
    if (!what)
        return;
    old = std::move(node);
    if (selection_.part == id && (!old.part || !old.part->skeleton.hasJoint(selection_.joint)))
        setSelection({id, kNoJoint});
    emit partChanged(id, what);
}

void Document::restoreContents(const DocumentContents& contents, const Selection& selection) {
    auto kept = [&](PartId id) {
        return std::any_of(contents.parts.begin(), contents.parts.end(),
                           [&](const PartNode& node) { return node.id == id; });
    };
    std::vector<PartId> added;
    for (const PartNode& node : contents_.parts)
        if (!kept(node.id))
            added.push_back(node.id);
    for (const PartId id : added)
        removePart(id);
    for (int i = 0; i < static_cast<int>(contents.parts.size()); ++i) {
        const PartNode& node = contents.parts[static_cast<std::size_t>(i)];
        const int at = indexOf(node.id);
        if (at == i) {
            replaceNode(node.id, node);
            continue;
        }
        if (at >= 0)
            removePart(node.id);  // it is after i: the parts before i are in place
        insertPart(i, node);
    }
    contents_.nextPartId = contents.nextPartId;
    setTimeline(contents.timeline);
    if (contents_.currentFrame != contents.currentFrame) {
        contents_.currentFrame = contents.currentFrame;
        emit currentFrameChanged(contents_.currentFrame);
    }
    setSelection(selection);
}

void Document::setName(PartId id, const QString& name) {
    PartNode& node = mutablePart(id);
    if (node.name == name)
        return;
    node.name = name;
    emit partChanged(id, Change::Name);
}

void Document::setPlacement(PartId id, const Placement& placement) {
    PartNode& node = mutablePart(id);
    if (node.placement == placement)
        return;
    node.placement = placement;
    emit partChanged(id, Change::Placement);
}

void Document::setVisible(PartId id, bool visible) {
    PartNode& node = mutablePart(id);
    if (node.visible == visible)
        return;
    node.visible = visible;
    emit partChanged(id, Change::Visibility);
}

void Document::replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options,
                           const rigmesh::Pose& pose, std::set<JointId> pinned,
                           const rigmesh::Clip& clip) {
    replacePart(id, std::move(part), options, pose, std::move(pinned), clip,
                this->part(id).otherClips);
}

void Document::replacePart(PartId id, std::shared_ptr<const Part> part, const BuildOptions& options,
                           const rigmesh::Pose& pose, std::set<JointId> pinned,
                           const rigmesh::Clip& clip, std::vector<rigmesh::Clip> otherClips) {
    PartNode node = this->part(id);
    node.part = std::move(part);
    node.options = options;
    node.pose = pose;
    node.pinnedJoints = std::move(pinned);
    node.clip = clip;
    node.otherClips = std::move(otherClips);
    replaceNode(id, std::move(node));
}

void Document::replacePart(PartId id, std::shared_ptr<const Part> part,
                           const BuildOptions& options) {
    const PartNode& node = this->part(id);
    if (node.part == part) {
        replacePart(id, std::move(part), options, node.pose, node.pinnedJoints, node.clip);
        return;
    }
    PartNode probe;
    probe.part = part;
    const rigmesh::Pose rest = restPoseOf(probe);
    std::vector<rigmesh::Clip> others;
    for (const rigmesh::Clip& other : node.otherClips)
        others.push_back(emptiedClip(other));
    replacePart(id, std::move(part), options, rest, {}, emptiedClip(node.clip), std::move(others));
}

void Document::replaceSkinning(PartId id, std::shared_ptr<const Part> part) {
    PartNode& node = mutablePart(id);
    if (!part || !node.part || part->mesh.vertexCount() != node.part->mesh.vertexCount() ||
        part->skeleton.boneCount() != node.part->skeleton.boneCount() ||
        part->skeleton.jointCount() != node.part->skeleton.jointCount())
        throw std::logic_error("Only the skin weights of a part can change this way.");
    if (node.part == part)
        return;
    node.part = std::move(part);
    emit partChanged(id, Change::Geometry);
}

void Document::setPose(PartId id, const rigmesh::Pose& pose) {
    PartNode& node = mutablePart(id);
    checkPose(node, pose);
    if (identicalPoses(node.pose, pose))
        return;
    node.pose = pose;
    emit partChanged(id, Change::Pose);
}

void Document::setPinnedJoints(PartId id, std::set<JointId> pinned) {
    PartNode& node = mutablePart(id);
    checkPins(node, pinned);
    if (node.pinnedJoints == pinned)
        return;
    node.pinnedJoints = std::move(pinned);
    emit partChanged(id, Change::Pins);
}

void Document::setClip(PartId id, const rigmesh::Clip& clip) {
    PartNode& node = mutablePart(id);
    checkClip(node, clip);
    checkClipNamesUnique(clip, node.otherClips);
    if (identicalClips(node.clip, clip))
        return;
    node.clip = clip;
    emit partChanged(id, Change::Clip);
}

void Document::setClips(PartId id, const rigmesh::Clip& active, std::vector<rigmesh::Clip> others) {
    PartNode& node = mutablePart(id);
    checkClip(node, active);
    for (const rigmesh::Clip& other : others)
        checkClip(node, other);
    checkClipNamesUnique(active, others);
    others = sortedByName(std::move(others));
    if (identicalClips(node.clip, active) && identicalClipLists(node.otherClips, others))
        return;
    node.clip = active;
    node.otherClips = std::move(others);
    emit partChanged(id, Change::Clip);
}

void Document::editClip(PartId id, const ClipEdit& edit) {
    PartNode& node = mutablePart(id);
    for (const auto& [time, pose] : edit.added)
        for (const auto& entry : pose.rotations)
            checkJoint(node, entry.first);
    if (edit.changesNothing())
        return;
    edit.applyTo(node.clip);
    emit partChanged(id, Change::Clip);
}

}  // namespace rigmesh::model
