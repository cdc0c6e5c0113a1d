// Tools > Auto-Rig Part, for an unrigged part (an imported mesh): a
// background job with a filling progress bar and Cancel that stops the
// skeleton's flow at its next step; the result arrives as one undoable
// command (model/commands/RigPartCommand). After an import of meshes without
// a rig the studio offers to rig them at once, as one figure. Edit > Connect
// Bone connects the selected joint's disconnected bone to its parent
// (part/BoneConnection.h), one undoable BoneEditCommand.
#pragma once

#include <QObject>
#include <vector>

#include "model/PartNode.h"

namespace rigmesh::model {
class Document;
}

namespace rigmesh::widgets {

class StudioHost;

class RigController : public QObject {
    Q_OBJECT
  public:
    RigController(StudioHost& host, QObject* parent);

    // Tools > Auto-Rig Part on the selected part.
    void rigSelectedPart();
    // Edit > Connect Bone on the selected joint's bone.
    void connectSelectedBone();
    // Rigs the parts together as one figure (an import's body, eyes and
    // clothes): one background job and one undo step.
    void rigParts(model::Document* document, std::vector<model::PartId> ids);
    // After an import: asks whether to rig the parts without a skeleton now
    // (a message box named "offerToRig"); true if the user said yes.
    bool offerToRig(model::Document& document, const std::vector<model::PartId>& ids,
                    const QString& message);

  private:
    StudioHost& host_;
};

}  // namespace rigmesh::widgets
