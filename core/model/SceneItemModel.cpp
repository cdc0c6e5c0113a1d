#include "model/SceneItemModel.h"

#include "model/CountText.h"

#include "part/BoneWeights.h"

#include <algorithm>

#include "model/GuardedUndo.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/SetPartVisibleCommand.h"

namespace rigmesh::model {

SceneItemModel::SceneItemModel(Document* document, QObject* parent)
    : QAbstractItemModel(parent),
      document_(document),
      root_(std::make_unique<SceneNode>(SceneNode::Kind::Root)) {
    for (const PartNode& part : document->parts())
        root_->insertChild(root_->childCount(), makePartNode(part));
    connect(document, &Document::partInserted, this, &SceneItemModel::onPartInserted);
    connect(document, &Document::partAboutToBeRemoved, this, &SceneItemModel::onPartRemoved);
    connect(document, &Document::partChanged, this, &SceneItemModel::onPartChanged);
    connect(document, &QObject::destroyed, this, [this] {
        beginResetModel();
        root_ = std::make_unique<SceneNode>(SceneNode::Kind::Root);
        endResetModel();
    });
}

SceneItemModel::~SceneItemModel() = default;

const SceneNode* SceneItemModel::nodeAt(const QModelIndex& index) const {
    return index.isValid() ? static_cast<const SceneNode*>(index.internalPointer()) : root_.get();
}

QModelIndex SceneItemModel::indexOfNode(const SceneNode* node, int column) const {
    if (!node || node == root_.get())
        return {};
    return createIndex(node->row(), column, const_cast<SceneNode*>(node));
}

QModelIndex SceneItemModel::indexOfPart(PartId part, int column) const {
    return indexOfNode(root_->findPart(part), column);
}

QModelIndex SceneItemModel::indexOfJoint(PartId part, JointId joint, int column) const {
    const SceneNode* partNode = root_->findPart(part);
    return partNode ? indexOfNode(partNode->findJoint(joint), column) : QModelIndex();
}

QModelIndex SceneItemModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= ColumnCount || (parent.isValid() && parent.column() != 0))
        return {};
    const SceneNode* child = nodeAt(parent)->child(row);
    return child ? createIndex(row, column, const_cast<SceneNode*>(child)) : QModelIndex();
}

QModelIndex SceneItemModel::parent(const QModelIndex& index) const {
    if (!index.isValid())
        return {};
    return indexOfNode(nodeAt(index)->parent());
}

int SceneItemModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() && parent.column() != 0)
        return 0;
    return nodeAt(parent)->childCount();
}

int SceneItemModel::columnCount(const QModelIndex&) const {
    return ColumnCount;
}

QVariant SceneItemModel::displayData(const SceneNode& node, int column) const {
    const PartNode* part = document_ ? document_->findPart(node.partId()) : nullptr;
    switch (node.kind()) {
        case SceneNode::Kind::Root:
            return {};
        case SceneNode::Kind::Part:
            if (!part)
                return {};
            if (column == NameColumn)
                return part->name;
            if (!part->part)
                return {};
            return tr("%1 vertices, %2 faces")
                .arg(part->part->mesh.vertexCount())
                .arg(part->part->mesh.faceCount());
        case SceneNode::Kind::Skeleton:
            if (column == NameColumn)
                return tr("Skeleton");
            if (!part || !part->part)
                return {};
            return tr("%1, %2").arg(
                countText(part->part->skeleton.jointCount(), tr("1 joint"), tr("%1 joints")),
                countText(part->part->skeleton.boneCount(), tr("1 bone"), tr("%1 bones")));
        case SceneNode::Kind::Joint: {
            const Skeleton* skeleton = part && part->part ? &part->part->skeleton : nullptr;
            const bool known = skeleton && skeleton->hasJoint(node.jointId());
            if (column == NameColumn) {
                return known && skeleton->root() == node.jointId()
                           ? tr("Joint %1 (root)").arg(node.jointId())
                           : tr("Joint %1").arg(node.jointId());
            }
            if (!known)
                return {};
            const Vec3& p = skeleton->joint(node.jointId()).position;
            const QString position = QStringLiteral("(%1, %2, %3)")
                                         .arg(p.x(), 0, 'f', 3)
                                         .arg(p.y(), 0, 'f', 3)
                                         .arg(p.z(), 0, 'f', 3);
            QString text = position;
            // The bone ending at the joint and how many vertices it leads.
            for (const Bone& bone : skeleton->bones())
                if (bone.tail == node.jointId()) {
                    const std::map<BoneId, int> leads =
                        leadingVertexCounts(part->part->weights.perVertex);
                    const auto count = leads.find(bone.id);
                    text += tr(", bone %1: %n vertices", nullptr,
                               count == leads.end() ? 0 : count->second)
                                .arg(bone.id);
                }
            return part->pinnedJoints.contains(node.jointId()) ? tr("%1 (pinned)").arg(text) : text;
        }
    }
    return {};
}

QVariant SceneItemModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !checkIndex(index))
        return {};
    const SceneNode& node = *nodeAt(index);
    switch (role) {
        case Qt::DisplayRole:
        case Qt::EditRole:
        case Qt::ToolTipRole:  // the whole text where a narrow column cuts it
            return displayData(node, index.column());
        case Qt::CheckStateRole:
            if (node.kind() == SceneNode::Kind::Part && index.column() == NameColumn && document_) {
                if (const PartNode* part = document_->findPart(node.partId()))
                    return part->visible ? Qt::Checked : Qt::Unchecked;
            }
            return {};
        case KindRole:
            return static_cast<int>(node.kind());
        case PartIdRole:
            return static_cast<uint>(node.partId());
        case JointIdRole:
            return static_cast<uint>(node.jointId());
        default:
            return {};
    }
}

bool SceneItemModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || !checkIndex(index) || !document_)
        return false;
    const SceneNode& node = *nodeAt(index);
    if (node.kind() != SceneNode::Kind::Part || index.column() != NameColumn)
        return false;
    const PartNode* part = document_->findPart(node.partId());
    if (!part)
        return false;
    const PartId id = part->id;  // `node` and `part` may go with a failed edit
    try {
        if (role == Qt::EditRole) {
            const QString name = value.toString().trimmed();
            if (name.isEmpty())
                return false;
            if (name != part->name)
                pushCommand(*document_, std::make_unique<RenamePartCommand>(*document_, id, name));
            return true;
        }
        if (role == Qt::CheckStateRole) {
            const bool visible = value.value<Qt::CheckState>() == Qt::Checked;
            if (visible != part->visible)
                pushCommand(*document_,
                            std::make_unique<SetPartVisibleCommand>(*document_, id, visible));
            return true;
        }
    } catch (...) {
        if (editFailed)
            editFailed(std::current_exception());
        else
            qWarning("An edit of part %u failed; the document is unchanged.",
                     static_cast<unsigned>(id));
        return false;
    }
    return false;
}

Qt::ItemFlags SceneItemModel::flags(const QModelIndex& index) const {
    if (!index.isValid() || !checkIndex(index))
        return Qt::NoItemFlags;
    Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const SceneNode& node = *nodeAt(index);
    if (node.kind() == SceneNode::Kind::Part && index.column() == NameColumn)
        flags |= Qt::ItemIsEditable | Qt::ItemIsUserCheckable;
    if (node.childCount() == 0)
        flags |= Qt::ItemNeverHasChildren;
    return flags;
}

QVariant SceneItemModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
        case NameColumn:
            return tr("Name");
        case InfoColumn:
            return tr("Info");
        default:
            return {};
    }
}

void SceneItemModel::onPartInserted(PartId id, int index) {
    const PartNode* part = document_ ? document_->findPart(id) : nullptr;
    if (!part)
        return;
    const int row = std::clamp(index, 0, root_->childCount());
    beginInsertRows({}, row, row);
    root_->insertChild(row, makePartNode(*part));
    endInsertRows();
}

void SceneItemModel::onPartRemoved(PartId id, int) {
    const SceneNode* node = root_->findPart(id);
    if (!node)
        return;
    const int row = node->row();
    beginRemoveRows({}, row, row);
    root_->takeChild(row);
    endRemoveRows();
}

void SceneItemModel::onPartChanged(PartId id, Document::Changes what) {
    SceneNode* node = root_->findPart(id);
    const PartNode* part = document_ ? document_->findPart(id) : nullptr;
    if (!node || !part)
        return;
    const QModelIndex partIndex = indexOfNode(node);
    if (what & Document::Change::Geometry) {
        // A new skeleton: replace the part's subtree.
        if (node->childCount() > 0) {
            beginRemoveRows(partIndex, 0, node->childCount() - 1);
            while (node->childCount() > 0)
                node->takeChild(0);
            endRemoveRows();
        }
        static const Skeleton kEmpty;
        beginInsertRows(partIndex, 0, 0);
        node->insertChild(0, makeSkeletonNode(id, part->part ? part->part->skeleton : kEmpty));
        endInsertRows();
    }
    if (what & (Document::Change::Name | Document::Change::Visibility | Document::Change::Geometry))
        emit dataChanged(partIndex, indexOfNode(node, InfoColumn));
    if ((what & Document::Change::Pins) && !(what & Document::Change::Geometry) && part->part) {
        // Pin markers live in the joints' info column.
        for (const Joint& joint : part->part->skeleton.joints()) {
            if (const SceneNode* jointNode = node->findJoint(joint.id)) {
                const QModelIndex info = indexOfNode(jointNode, InfoColumn);
                emit dataChanged(info, info, {Qt::DisplayRole});
            }
        }
    }
}

}  // namespace rigmesh::model
