// QAbstractItemModel adapter of a Document for views (outliner): the tree of
// SceneTree.h with two columns, the name and a short line of figures. Part
// names are editable in place (pushes RenamePartCommand) and part rows are
// checkable for visibility (pushes SetPartVisibleCommand). Updates follow the
// document's signals incrementally; a rebuilt part (new skeleton) has its
// skeleton row removed and inserted again. Pinned joints show "(pinned)" in
// the info column (updated on Change::Pins).
#pragma once

#include <QAbstractItemModel>
#include <QPointer>
#include <exception>
#include <functional>
#include <memory>

#include "model/Document.h"
#include "model/SceneTree.h"

namespace rigmesh::model {

class SceneItemModel : public QAbstractItemModel {
    Q_OBJECT
  public:
    enum Column { NameColumn = 0, InfoColumn = 1, ColumnCount = 2 };
    enum Role {
        KindRole = Qt::UserRole + 1,  // int(SceneNode::Kind)
        PartIdRole,                   // PartId (uint)
        JointIdRole,                  // JointId (uint), kNoJoint when not a joint
    };

    explicit SceneItemModel(Document* document, QObject* parent = nullptr);
    ~SceneItemModel() override;

    Document* document() const { return document_; }
    QModelIndex indexOfPart(PartId part, int column = NameColumn) const;
    QModelIndex indexOfJoint(PartId part, JointId joint, int column = NameColumn) const;
    // Kind, part and joint of an index (the root for an invalid one).
    const SceneNode* nodeAt(const QModelIndex& index) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& index) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    // Never throws (Qt's item views and delegates call it): what a command
    // throws goes to editFailed with the document as it was
    // (model/GuardedUndo.h), and setData returns false.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Told what a rename or visibility change threw; without it the failure
    // is only logged (qWarning).
    std::function<void(std::exception_ptr)> editFailed;

  private:
    QModelIndex indexOfNode(const SceneNode* node, int column = NameColumn) const;
    QVariant displayData(const SceneNode& node, int column) const;
    void onPartInserted(PartId id, int index);
    void onPartRemoved(PartId id, int index);
    void onPartChanged(PartId id, Document::Changes what);

    QPointer<Document> document_;
    std::unique_ptr<SceneNode> root_;
};

}  // namespace rigmesh::model
