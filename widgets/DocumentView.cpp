#include "DocumentView.h"

#include <QPointer>
#include <QVBoxLayout>
#include <optional>

#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/ErrorText.h"
#include "model/PartBuilder.h"
#include "model/commands/CreatePartCommand.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// The point a StrokeCrossesItselfNear error names ("(x, y)", in the
// stroke's coordinates), if it is one.
std::optional<Vec2> crossingOf(const Error& error) {
    const Message& message = error.message();
    if (message.id != MessageId::StrokeCrossesItselfNear || message.args.empty())
        return std::nullopt;
    QString text = QString::fromStdString(message.args.front());
    text.remove(QLatin1Char('(')).remove(QLatin1Char(')'));
    const QStringList xy = text.split(QLatin1Char(','));
    bool okX = false, okY = false;
    const double x = xy.value(0).trimmed().toDouble(&okX);
    const double y = xy.value(1).trimmed().toDouble(&okY);
    if (!okX || !okY)
        return std::nullopt;
    return Vec2(x, y);
}

}  // namespace

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
    // The engine builds off the GUI thread from copies (a fine edge length
    // can take seconds); the command is made and pushed here when done.
    const double documentLength = model::documentEdgeLength(*document_);
    const QString name = tr("Part %1").arg(document_->nextPartId());
    // The preferred edge length (Preferences; 0 = the document's).
    model::BuildOptions options;
    options.targetEdgeLength = defaultEdgeLength_;
    QPointer<model::Document> document(document_.get());
    JobRunner::runOn(
        viewport_->jobRunner(), tr("Building %1").arg(name),
        [=, this]() -> JobRunner::Apply {
            model::BuiltPart built;
            try {
                built = model::buildPartAtDocumentLength(documentLength, stroke, name, options);
            } catch (const Error& error) {
                // Where a stroke crosses itself is shown, not told in
                // coordinates (the engine's message names the point).
                const std::optional<Vec2> at = crossingOf(error);
                if (!at)
                    throw;
                return [=, this]() {
                    viewport_->setProblemMark(toQt(plane.toWorld(Vec3(at->x(), at->y(), 0.0))));
                    emit statusMessage(tr("Nothing created: the stroke crosses itself where "
                                          "the red cross is; draw a silhouette that does not "
                                          "cross itself"),
                                       8000);
                };
            }
            return [=, this]() mutable {
                if (!document)
                    return;
                auto command = model::CreatePartCommand::fromBuilt(*document, stroke, name,
                                                                   std::move(built), plane);
                const model::PartId id = command->partId();
                document->undoStack()->push(command.release());
                document->setSelection({id, kNoJoint});
                emit statusMessage(tr("Created %1").arg(document->part(id).name), 4000);
            };
        },
        [this](const QString& reason) {
            emit statusMessage(tr("Nothing created: %1").arg(reason), 8000);
        });
}

}  // namespace rigmesh::widgets
