// Put copied keys into a part's active clip (the timeline's paste):
// each key at its time, replacing a key within half a frame of it
// (Clip::setKey).
#pragma once

#include <QCoreApplication>
#include <map>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class PasteKeysCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(PasteKeysCommand)
  public:
    // Throws rigmesh::Error on an unknown id, no keys, a time out of range or
    // a pose that is not finite; a joint the part's skeleton lacks throws on
    // redo (Document::editClip), so check with fitsSkeleton first.
    PasteKeysCommand(Document& document, PartId id, std::map<double, rigmesh::Pose> keys,
                     QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;

    // True when every joint the keys rotate is a joint of the part.
    static bool fitsSkeleton(const PartNode& node, const std::map<double, rigmesh::Pose>& keys);

  private:
    std::map<double, rigmesh::Pose> keys_;
};

}  // namespace rigmesh::model
