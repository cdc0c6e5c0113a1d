// One open document in the studio: its viewport, and the wiring from tools
// to the document's commands (a finished stroke becomes a CreatePartCommand;
// a bad stroke becomes a status message and changes nothing).
#pragma once

#include <QWidget>
#include <memory>

#include "model/Document.h"

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

  public slots:
    void createPartFromStroke(const std::vector<rigmesh::Vec2>& stroke,
                              const rigmesh::model::Placement& plane);

  signals:
    void statusMessage(const QString& message, int timeoutMs = 0);

  private:
    std::unique_ptr<model::Document> document_;
    Viewport* viewport_;
    double defaultEdgeLength_ = 0.0;
};

}  // namespace rigmesh::widgets
