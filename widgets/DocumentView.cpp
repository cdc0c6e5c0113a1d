#include "DocumentView.h"

#include <QVBoxLayout>

#include "base/Error.h"
#include "model/ErrorText.h"
#include "model/commands/CreatePartCommand.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

DocumentView::DocumentView(std::unique_ptr<model::Document> document, QWidget* parent)
    : QWidget(parent), document_(std::move(document)) {
    document_->setParent(nullptr);
    viewport_ = new Viewport(document_.get(), this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(viewport_);
    connect(viewport_, &Viewport::statusMessage, this,
            [this](const QString& m) { emit statusMessage(m); });
}

DocumentView::~DocumentView() {
    // The viewport reads the document until it is gone.
    delete viewport_;
}

void DocumentView::createPartFromStroke(const std::vector<Vec2>& stroke,
                                        const model::Placement& plane) {
    try {
        model::BuildOptions options;
        options.targetEdgeLength = defaultEdgeLength_;
        auto command = model::CreatePartCommand::create(*document_, stroke, {}, options, plane);
        const model::PartId id = command->partId();
        document_->undoStack()->push(command.release());
        document_->setSelection({id, kNoJoint});
        emit statusMessage(tr("Created %1").arg(document_->part(id).name), 4000);
    } catch (const rigmesh::Error& error) {
        emit statusMessage(tr("Nothing created: %1").arg(model::errorText(error)), 8000);
    }
}

}  // namespace rigmesh::widgets
