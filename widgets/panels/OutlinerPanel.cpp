#include "panels/OutlinerPanel.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QTreeView>
#include <QVBoxLayout>

#include "UserAction.h"
#include "model/Document.h"
#include "model/SceneItemModel.h"

namespace rigmesh::widgets {

OutlinerPanel::OutlinerPanel(QWidget* parent) : QWidget(parent), view_(new QTreeView(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(view_);
    view_->setHeaderHidden(false);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    view_->setUniformRowHeights(true);
}

OutlinerPanel::~OutlinerPanel() {
    view_->setModel(nullptr);
}

void OutlinerPanel::setDocument(model::Document* document) {
    if (document == document_)
        return;
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    view_->setModel(nullptr);
    model_.reset();
    document_ = document;
    if (!document_)
        return;
    model_ = std::make_unique<model::SceneItemModel>(document_);
    model_->editFailed = [this](const std::exception_ptr& thrown) {
        emit statusMessage(UserAction::failureText(tr("Outliner"), thrown), 8000);
    };
    view_->setModel(model_.get());
    // Names as wide as they need ("Joint 12 (root)"), the info column takes
    // the rest; a narrow dock scrolls sideways rather than cutting names.
    view_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    view_->header()->setStretchLastSection(true);
    view_->header()->setMinimumSectionSize(60);
    view_->expandToDepth(0);
    connect(model_.get(), &QAbstractItemModel::rowsInserted, view_,
            [this] { view_->expandToDepth(0); });
    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &OutlinerPanel::viewSelectionChanged);
    connect(document_, &model::Document::selectionChanged, this,
            &OutlinerPanel::documentSelectionChanged);
    documentSelectionChanged();
}

void OutlinerPanel::documentSelectionChanged() {
    if (syncing_ || !model_)
        return;
    syncing_ = true;
    const model::Selection selection = document_->selection();
    QModelIndex index = selection.joint != kNoJoint
                            ? model_->indexOfJoint(selection.part, selection.joint)
                            : model_->indexOfPart(selection.part);
    if (index.isValid()) {
        view_->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        view_->scrollTo(index);
    } else {
        view_->selectionModel()->clearSelection();
    }
    syncing_ = false;
}

void OutlinerPanel::viewSelectionChanged() {
    if (syncing_ || !model_)
        return;
    syncing_ = true;
    const QModelIndex current = view_->selectionModel()->currentIndex();
    model::Selection selection;
    if (current.isValid()) {
        selection.part = current.data(model::SceneItemModel::PartIdRole).toUInt();
        const QVariant joint = current.data(model::SceneItemModel::JointIdRole);
        selection.joint = joint.isValid() ? joint.toUInt() : kNoJoint;
    }
    document_->setSelection(selection);
    syncing_ = false;
}

}  // namespace rigmesh::widgets
