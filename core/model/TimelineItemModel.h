// The document's clips as a Qt item model, as Krita's time-based
// item models are: rows are parts (the active clip of each), each with one
// child row per joint; columns are frames 0..frameCount()-1. The timeline
// dock is a view over it, and it is tested without a display
// (QAbstractItemModelTester).
//
// A key shows in the column of its nearest frame (keys are kept in seconds,
// Timeline.h). A joint row has a key where the part's key rotates that joint,
// and a hold where the joint's rotation stays the same to the next key (the
// bar Blender's dope sheet draws). The current frame and the range are
// header data of the frame columns. Updates follow the document's signals:
// rows are inserted and removed with the parts, a new skeleton replaces the
// joint rows, and a change of the column count (the range, or a key past the
// end) resets the model.
#pragma once

#include <QAbstractItemModel>
#include <QPointer>
#include <map>
#include <vector>

#include "model/Document.h"

namespace rigmesh::model {

class TimelineItemModel : public QAbstractItemModel {
    Q_OBJECT
  public:
    enum Role {
        KeyRole = Qt::UserRole + 1,  // bool: a key in this frame
        KeyTimeRole,                 // double: its exact time in seconds (invalid without one)
        HoldRole,                    // bool (joint rows): the same rotation at the next key
        PartIdRole,                  // PartId (uint)
        JointIdRole,                 // JointId (uint), kNoJoint on part rows
        ClipNameRole,                // QString: the part's active clip (part rows)
        // Header data of a frame column (Qt::Horizontal):
        CurrentFrameRole,  // bool: the document's current frame
        InRangeRole,       // bool: within the timeline's frame range
        SecondsRole,       // double: the frame's time in seconds
    };

    explicit TimelineItemModel(Document* document, QObject* parent = nullptr);

    Document* document() const { return document_; }
    // Frames shown: up to the range's end or the last key, whichever is later.
    int frameCount() const { return frameCount_; }
    QModelIndex indexOfPart(PartId part, int frame = 0) const;
    QModelIndex indexOfJoint(PartId part, JointId joint, int frame = 0) const;
    // The key frames of the part's active clip with their exact times.
    const std::map<int, double>& keyFrames(PartId part) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& index) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

  private:
    struct Row {
        PartId id = kNoPart;
        std::vector<JointId> joints;
        std::map<int, double> keys;  // frame -> exact key time
    };
    Row rowOf(const PartNode& node) const;
    int wantedFrameCount() const;
    int rowIndex(PartId id) const;
    const Row* rowAt(const QModelIndex& index) const;
    void onPartInserted(PartId id, int index);
    void onPartAboutToBeRemoved(PartId id, int index);
    void onPartChanged(PartId id, Document::Changes what);
    void onCurrentFrameChanged(int frame);
    void onTimelineChanged();
    // Resets the model when the frame count changed; true if it did.
    bool refitColumns();

    QPointer<Document> document_;
    std::vector<Row> rows_;
    int frameCount_ = 1;
    int shownFrame_ = 0;  // the current frame as last announced
};

}  // namespace rigmesh::model
