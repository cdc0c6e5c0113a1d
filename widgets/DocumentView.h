// One open document in the studio: its viewport, and the wiring from tools
// to the document's commands (a finished stroke becomes a CreatePartCommand;
// a bad stroke becomes a status message and changes nothing). A stroke being
// drawn shows its part live (model/preview/SketchPreview.h, built by
// jobs/SketchPreviewBuilder.h); its release commits that same part.
#pragma once

#include <QWidget>
#include <memory>
#include <optional>

#include "jobs/SketchPreviewBuilder.h"
#include "model/Document.h"

namespace rigmesh::model {
class SketchPreview;
}

namespace rigmesh::widgets {

class Viewport;

class DocumentView : public QWidget {
    Q_OBJECT
  public:
    // Takes ownership of the document.
    explicit DocumentView(std::unique_ptr<model::Document> document, QWidget* parent = nullptr);
    ~DocumentView() override;

    model::Document* document() const { return document_.get(); }
    Viewport* viewport() const { return viewport_; }
    // The edge length new sketches ask for (Preferences; 0 = automatic).
    void setDefaultEdgeLength(double length) { defaultEdgeLength_ = length; }
    double defaultEdgeLength() const { return defaultEdgeLength_; }

    // Builds the live previews of strokes being drawn.
    SketchPreviewBuilder* sketchPreviewBuilder() const { return sketchBuilder_; }
    // The part the live preview shows (kNoPart: none).
    model::PartId sketchPreviewPart() const;

  public slots:
    // A finished stroke: its part is committed as one undo step, the
    // previewed one when it was built from this very stroke (or is being
    // built from it), else built now in the background.
    void createPartFromStroke(const std::vector<rigmesh::Vec2>& stroke,
                              const rigmesh::model::Placement& plane);
    // The stroke so far, while it is drawn: its part is shown when built.
    // A stroke that is open or that the engine refuses shows no part and
    // says nothing (its release says why).
    void previewStroke(const std::vector<rigmesh::Vec2>& stroke,
                       const rigmesh::model::Placement& plane);
    // The stroke ended without a part: its preview goes.
    void dropStrokePreview();

  signals:
    void statusMessage(const QString& message, int timeoutMs = 0);

  private:
    SketchPreviewBuilder::Request sketchRequest(const std::vector<Vec2>& stroke,
                                                const model::Placement& plane) const;
    void showSketchBuild(const SketchPreviewBuilder::Outcome& outcome);

    std::unique_ptr<model::Document> document_;
    Viewport* viewport_;
    double defaultEdgeLength_ = 0.0;
    SketchPreviewBuilder* sketchBuilder_;
    std::unique_ptr<model::SketchPreview> sketchPreview_;
    // The request whose part the preview shows.
    std::optional<SketchPreviewBuilder::Request> shown_;
};

}  // namespace rigmesh::widgets
