#include "model/TimelineItemModel.h"

#include <algorithm>

#include "model/PartClips.h"

namespace rigmesh::model {

namespace {

// Rotations equal up to rounding: a joint that holds still between keys.
bool sameRotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return std::abs(std::abs(a.normalized().dot(b.normalized())) - 1.0) < 1e-12;
}

}  // namespace

TimelineItemModel::TimelineItemModel(Document* document, QObject* parent)
    : QAbstractItemModel(parent), document_(document) {
    for (const PartNode& node : document->parts())
        rows_.push_back(rowOf(node));
    frameCount_ = wantedFrameCount();
    shownFrame_ = document->currentFrame();
    connect(document, &Document::partInserted, this, &TimelineItemModel::onPartInserted);
    connect(document, &Document::partAboutToBeRemoved, this,
            &TimelineItemModel::onPartAboutToBeRemoved);
    connect(document, &Document::partRemoved, this, [this] {
        endRemoveRows();
        refitColumns();
    });
    connect(document, &Document::partChanged, this, &TimelineItemModel::onPartChanged);
    connect(document, &Document::currentFrameChanged, this,
            &TimelineItemModel::onCurrentFrameChanged);
    connect(document, &Document::timelineChanged, this, &TimelineItemModel::onTimelineChanged);
}

TimelineItemModel::Row TimelineItemModel::rowOf(const PartNode& node) const {
    Row row;
    row.id = node.id;
    if (node.part)
        for (const Joint& joint : node.part->skeleton.joints())
            row.joints.push_back(joint.id);
    const TimelineSettings& timeline = document_->timeline();
    for (const auto& [time, pose] : node.clip.keys()) {
        const double frame = timeline.frameOfTime(time);
        if (frame >= 0 && frame <= kMaxFrame)
            row.keys.try_emplace(static_cast<int>(frame), time);
    }
    return row;
}

int TimelineItemModel::wantedFrameCount() const {
    int last = document_->timeline().endFrame;
    for (const Row& row : rows_)
        if (!row.keys.empty())
            last = std::max(last, row.keys.rbegin()->first);
    return last + 1;
}

int TimelineItemModel::rowIndex(PartId id) const {
    const auto it =
        std::find_if(rows_.begin(), rows_.end(), [id](const Row& row) { return row.id == id; });
    return it == rows_.end() ? -1 : static_cast<int>(it - rows_.begin());
}

const TimelineItemModel::Row* TimelineItemModel::rowAt(const QModelIndex& index) const {
    if (!index.isValid())
        return nullptr;
    if (index.internalId() == 0)
        return &rows_[index.row()];
    const int parentRow = rowIndex(static_cast<PartId>(index.internalId()));
    return parentRow < 0 ? nullptr : &rows_[parentRow];
}

QModelIndex TimelineItemModel::indexOfPart(PartId part, int frame) const {
    const int row = rowIndex(part);
    return row < 0 ? QModelIndex() : index(row, frame);
}

QModelIndex TimelineItemModel::indexOfJoint(PartId part, JointId joint, int frame) const {
    const int row = rowIndex(part);
    if (row < 0)
        return {};
    const auto& joints = rows_[row].joints;
    const auto it = std::find(joints.begin(), joints.end(), joint);
    if (it == joints.end())
        return {};
    return index(static_cast<int>(it - joints.begin()), frame, index(row, 0));
}

const std::map<int, double>& TimelineItemModel::keyFrames(PartId part) const {
    static const std::map<int, double> none;
    const int row = rowIndex(part);
    return row < 0 ? none : rows_[row].keys;
}

QModelIndex TimelineItemModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= frameCount_ || row < 0)
        return {};
    if (!parent.isValid())
        return row < static_cast<int>(rows_.size()) ? createIndex(row, column, quintptr(0))
                                                    : QModelIndex();
    if (parent.internalId() != 0 || parent.column() != 0 ||
        parent.row() >= static_cast<int>(rows_.size()))
        return {};
    const Row& part = rows_[parent.row()];
    if (row >= static_cast<int>(part.joints.size()))
        return {};
    return createIndex(row, column, quintptr(part.id));
}

QModelIndex TimelineItemModel::parent(const QModelIndex& index) const {
    if (!index.isValid() || index.internalId() == 0)
        return {};
    const int row = rowIndex(static_cast<PartId>(index.internalId()));
    return row < 0 ? QModelIndex() : createIndex(row, 0, quintptr(0));
}

int TimelineItemModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid())
        return static_cast<int>(rows_.size());
    if (parent.internalId() != 0 || parent.column() != 0)
        return 0;
    return static_cast<int>(rows_[parent.row()].joints.size());
}

int TimelineItemModel::columnCount(const QModelIndex&) const {
    return frameCount_;
}

QVariant TimelineItemModel::data(const QModelIndex& index, int role) const {
    const Row* row = rowAt(index);
    if (!row || !document_)
        return {};
    const PartNode& node = document_->part(row->id);
    const bool jointRow = index.internalId() != 0;
    const JointId joint = jointRow ? row->joints[index.row()] : kNoJoint;
    const auto key = row->keys.find(index.column());
    const bool keyed = key != row->keys.end() &&
                       (!jointRow || node.clip.keys().at(key->second).rotations.contains(joint));
    switch (role) {
        case Qt::DisplayRole:
        case Qt::ToolTipRole: {
            const QString name = jointRow ? jointDisplayName(joint) : node.name;
            if (role == Qt::DisplayRole || !keyed)
                return name;
            return tr("%1: key at frame %2 (%3 s)").arg(name).arg(key->first).arg(key->second);
        }
        case KeyRole:
            return keyed;
        case KeyTimeRole:
            return keyed ? QVariant(key->second) : QVariant();
        case HoldRole: {
            if (!keyed || !jointRow)
                return false;
            const auto& keys = node.clip.keys();
            const auto here = keys.find(key->second);
            const auto next = std::next(here);
            return next != keys.end() && next->second.rotations.contains(joint) &&
                   sameRotation(here->second.rotation(joint), next->second.rotation(joint));
        }
        case PartIdRole:
            return QVariant::fromValue(uint(row->id));
        case JointIdRole:
            return QVariant::fromValue(uint(joint));
        case ClipNameRole:
            return jointRow ? QVariant() : QVariant(QString::fromStdString(clipName(node.clip)));
        default:
            return {};
    }
}

Qt::ItemFlags TimelineItemModel::flags(const QModelIndex& index) const {
    return index.isValid() ? Qt::ItemIsEnabled | Qt::ItemIsSelectable : Qt::NoItemFlags;
}

QVariant TimelineItemModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || section < 0 || section >= frameCount_ || !document_)
        return {};
    const TimelineSettings& timeline = document_->timeline();
    switch (role) {
        case Qt::DisplayRole:
            return section;
        case Qt::ToolTipRole:
            return tr("Frame %1: %2 s").arg(section).arg(timeline.timeOfFrame(section));
        case CurrentFrameRole:
            return section == document_->currentFrame();
        case InRangeRole:
            return section >= timeline.startFrame && section <= timeline.endFrame;
        case SecondsRole:
            return timeline.timeOfFrame(section);
        default:
            return {};
    }
}

void TimelineItemModel::onPartInserted(PartId id, int index) {
    beginInsertRows({}, index, index);
    rows_.insert(rows_.begin() + index, rowOf(document_->part(id)));
    endInsertRows();
    refitColumns();
}

void TimelineItemModel::onPartAboutToBeRemoved(PartId, int index) {
    beginRemoveRows({}, index, index);
    rows_.erase(rows_.begin() + index);
    // endRemoveRows() on Document::partRemoved.
}

void TimelineItemModel::onPartChanged(PartId id, Document::Changes what) {
    const int row = rowIndex(id);
    if (row < 0 ||
        !(what & (Document::Change::Geometry | Document::Change::Clip | Document::Change::Name)))
        return;
    Row fresh = rowOf(document_->part(id));
    const QModelIndex parent = index(row, 0);
    if (fresh.joints != rows_[row].joints) {
        if (!rows_[row].joints.empty()) {
            beginRemoveRows(parent, 0, static_cast<int>(rows_[row].joints.size()) - 1);
            rows_[row].joints.clear();
            endRemoveRows();
        }
        if (!fresh.joints.empty()) {
            beginInsertRows(parent, 0, static_cast<int>(fresh.joints.size()) - 1);
            rows_[row].joints = fresh.joints;
            endInsertRows();
        }
    }
    rows_[row].keys = std::move(fresh.keys);
    if (refitColumns())
        return;
    emit dataChanged(index(row, 0), index(row, frameCount_ - 1));
    const int joints = static_cast<int>(rows_[row].joints.size());
    if (joints > 0)
        emit dataChanged(index(0, 0, parent), index(joints - 1, frameCount_ - 1, parent));
}

void TimelineItemModel::onCurrentFrameChanged(int frame) {
    const int previous = shownFrame_;
    shownFrame_ = frame;
    for (const int section : {previous, frame})
        if (section < frameCount_)
            emit headerDataChanged(Qt::Horizontal, section, section);
}

void TimelineItemModel::onTimelineChanged() {
    // A new rate moves keys between columns (SetTimelineCommand retimes them
    // first, so the frames stay; a clip_settings rate change does not).
    for (Row& row : rows_)
        row.keys = rowOf(document_->part(row.id)).keys;
    if (!refitColumns()) {
        emit headerDataChanged(Qt::Horizontal, 0, frameCount_ - 1);
        if (!rows_.empty())
            emit dataChanged(index(0, 0),
                             index(static_cast<int>(rows_.size()) - 1, frameCount_ - 1));
    }
}

bool TimelineItemModel::refitColumns() {
    const int wanted = wantedFrameCount();
    if (wanted == frameCount_)
        return false;
    beginResetModel();
    frameCount_ = wanted;
    endResetModel();
    return true;
}

}  // namespace rigmesh::model
