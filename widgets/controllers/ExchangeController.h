// File > Import, File > Export and File > Save History as Recipe. Imports are
// read by a child process and exports written off the GUI thread, both as
// background jobs; what arrives is one undoable command, and an exported
// file is in place only when its job is applied (model::stageParts).
#pragma once

#include <QObject>
#include <functional>
#include <memory>

#include "io/SceneExport.h"

namespace rigmesh::model {
class Document;
class ImportPartsCommand;
}  // namespace rigmesh::model

namespace rigmesh::widgets {

class RigController;
class StudioHost;

class ExchangeController : public QObject {
    Q_OBJECT
  public:
    // `skinning` tells how the view skins a pose (View > Dual Quaternion
    // Skinning), which the export takes for posed shapes and FBX records.
    ExchangeController(StudioHost& host, RigController& rig,
                       std::function<SkinningMethod()> skinning, QObject* parent);

    // File > Import: a file dialog, then importPath.
    void importFile();
    // Imports `path` into the current document, as a background job.
    void importPath(const QString& path);
    // File > Export: the dialog, then exportTo.
    void exportDocument();
    // Exports the current document's visible parts to `path`, as a
    // background job.
    void exportTo(const QString& path, const ExportOptions& options);
    void saveHistoryAsRecipe();

  private:
    void finishImport(model::Document& document, const QString& file,
                      std::unique_ptr<model::ImportPartsCommand> command);

    StudioHost& host_;
    RigController& rig_;
    std::function<SkinningMethod()> skinning_;
};

}  // namespace rigmesh::widgets
