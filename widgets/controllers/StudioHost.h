// What the studio's feature controllers (files, exchange, rig, weights, pose) need
// of the window that assembles them, after Krita's KisViewManager, which its
// managers reach the current view through: the current document and view,
// the background jobs, a parent for dialogs, the status bar, and the tabs'
// documents. MainWindow implements it; a controller never includes it.
#pragma once

#include <QString>
#include <memory>
#include <vector>

class QWidget;

namespace rigmesh::model {
class Document;
}

namespace rigmesh::widgets {

class DocumentView;
class JobRunner;

class StudioHost {
  public:
    virtual ~StudioHost() = default;

    virtual model::Document* currentDocument() const = 0;
    virtual DocumentView* currentView() const = 0;
    virtual JobRunner* jobs() const = 0;
    // The window, as the parent of dialogs and message boxes.
    virtual QWidget* dialogParent() = 0;
    virtual void showStatus(const QString& message, int timeoutMs = 0) = 0;

    // The open documents' views, in tab order.
    virtual std::vector<DocumentView*> views() const = 0;
    // A new empty document ("Untitled N") as the current one.
    virtual DocumentView* newDocument() = 0;
    // Adds a document as a new tab and makes it current.
    virtual DocumentView* addDocument(std::unique_ptr<model::Document> document) = 0;
    virtual void setCurrentView(DocumentView* view) = 0;
    // Takes the view's tab away and deletes the view with its document.
    virtual void removeView(DocumentView* view) = 0;
};

}  // namespace rigmesh::widgets
