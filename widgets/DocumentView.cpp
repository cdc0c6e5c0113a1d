#include "DocumentView.h"

#include <QPointer>
#include <QVBoxLayout>
#include <exception>
#include <optional>

#include "UserAction.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/ErrorText.h"
#include "model/PartBuilder.h"
#include "model/preview/SketchPreview.h"
#include "sketch/StrokeCrossingError.h"
#include "viewport/ViewMath.h"
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
    sketchBuilder_ = new SketchPreviewBuilder(this);
    sketchPreview_ = std::make_unique<model::SketchPreview>(*document_);
    connect(sketchBuilder_, &SketchPreviewBuilder::built, this, &DocumentView::showSketchBuild);
}

DocumentView::~DocumentView() {
    // The viewport reads the document until it is gone.
    delete viewport_;
}

model::PartId DocumentView::sketchPreviewPart() const {
    return sketchPreview_->previewing() ? sketchPreview_->partId() : model::kNoPart;
}

SketchPreviewBuilder::Request DocumentView::sketchRequest(const std::vector<Vec2>& stroke,
                                                          const model::Placement& plane) const {
    SketchPreviewBuilder::Request request;
    request.stroke = stroke;
    // Named after the id it gets: the one the preview holds, else the next.
    request.name = tr("Part %1").arg(sketchPreview_->upcomingId());
    // The preview is not one of the document's parts yet: its own edge
    // length does not count.
    request.documentLength = model::documentEdgeLength(*document_, sketchPreviewPart());
    // The preferred edge length (Preferences; 0 = the document's).
    request.options.targetEdgeLength = defaultEdgeLength_;
    request.plane = plane;
    return request;
}

void DocumentView::previewStroke(const std::vector<Vec2>& stroke, const model::Placement& plane) {
    // The studio is read-only while a job runs (jobs/JobRunner.h).
    if (viewport_->jobRunner() && viewport_->jobRunner()->busy())
        return;
    sketchBuilder_->request(sketchRequest(stroke, plane));
}

void DocumentView::dropStrokePreview() {
    sketchBuilder_->cancel();
    sketchPreview_->revert();
    shown_.reset();
}

void DocumentView::showSketchBuild(const SketchPreviewBuilder::Outcome& outcome) {
    if (!outcome.built) {
        // Open or refused: nothing to show, nothing to say until release.
        sketchPreview_->revert();
        shown_.reset();
        return;
    }
    const SketchPreviewBuilder::Request& request = outcome.request;
    // A refused preview says nothing until release (the build says why); a
    // failure of any other kind is said now.
    const auto report = [this](const QString& failure) {
        sketchPreview_->revert();
        shown_.reset();
        emit statusMessage(failure, 8000);
    };
    runUserAction(tr("Building %1").arg(request.name), report, [&] {
        try {
            sketchPreview_->preview(std::make_shared<const model::SketchedPart>(
                model::SketchedPart{request.stroke, request.name, *outcome.built, request.plane}));
            shown_ = request;
        } catch (const Error&) {
            sketchPreview_->revert();
            shown_.reset();
        }
    });
}

void DocumentView::createPartFromStroke(const std::vector<Vec2>& stroke,
                                        const model::Placement& plane) {
    const SketchPreviewBuilder::Request request = sketchRequest(stroke, plane);
    // Built while it was drawn and nothing changed since: that part, now.
    if (shown_ && *shown_ == request && sketchPreview_->previewing()) {
        sketchBuilder_->cancel();
        shown_.reset();
        const model::PartId id = sketchPreview_->commit();
        document_->setSelection({id, kNoJoint});
        emit statusMessage(tr("Created %1").arg(document_->part(id).name), 4000);
        return;
    }
    // Else the build of this stroke the preview started, or a new one; the
    // engine builds off the GUI thread from copies (a fine edge length can
    // take seconds). What the preview shows stays until the part replaces it.
    const std::optional<SketchPreviewBuilder::Result> started = sketchBuilder_->started(request);
    sketchBuilder_->cancel();
    shown_.reset();
    const QPointer<DocumentView> self(this);
    auto dropPreview = [self] {
        if (self)
            self->sketchPreview_->revert();
    };
    JobRunner::runOn(
        viewport_->jobRunner(), tr("Building %1").arg(request.name),
        [=, this]() -> JobRunner::Apply {
            model::BuiltPart built;
            try {
                std::shared_ptr<const SketchPreviewBuilder::Outcome> outcome;
                if (started)
                    outcome = started->get();  // on this worker thread, never the GUI's
                if (outcome && outcome->error)
                    std::rethrow_exception(outcome->error);
                built = outcome && outcome->built
                            ? *outcome->built
                            : model::buildPartAtDocumentLength(request.documentLength, stroke,
                                                               request.name, request.options);
            } catch (const StrokeCrossingError& error) {
                // Where a stroke crosses itself is shown, not told in
                // coordinates (the engine's message names the point for the
                // command line).
                const Vec2 at = error.crossing();
                return [=, this]() {
                    dropPreview();
                    viewport_->setProblemMark(toQt(plane.toWorld(Vec3(at.x(), at.y(), 0.0))));
                    emit statusMessage(tr("Nothing created: the stroke crosses itself where "
                                          "the red cross is; draw a silhouette that does not "
                                          "cross itself"),
                                       8000);
                };
            }
            return [=, this]() mutable {
                if (!self)
                    return;
                const model::PartId id = sketchPreview_->commit(
                    model::SketchedPart{stroke, request.name, std::move(built), plane});
                document_->setSelection({id, kNoJoint});
                emit statusMessage(tr("Created %1").arg(document_->part(id).name), 4000);
            };
        },
        [this, dropPreview](const QString& reason) {
            dropPreview();
            emit statusMessage(tr("Nothing created: %1").arg(reason), 8000);
        },
        dropPreview);
}

}  // namespace rigmesh::widgets
