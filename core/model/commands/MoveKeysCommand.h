// Move several keys of a part's active clip by one time offset at once (a
// timeline drag). All move together, so a key moving onto the old
// place of another moving key does not replace it; a key that lands within
// half a frame of a key that stays replaces it (Clip::setKey).
#pragma once

#include <QCoreApplication>
#include <vector>

#include "model/commands/ClipCommand.h"

namespace rigmesh::model {

class MoveKeysCommand : public ClipCommand {
    Q_DECLARE_TR_FUNCTIONS(MoveKeysCommand)
  public:
    // Throws rigmesh::Error on an unknown id, no keys, a time without a key,
    // a non-finite offset or a target time out of range.
    MoveKeysCommand(Document& document, PartId id, std::vector<double> times, double offset,
                    QUndoCommand* parent = nullptr);

    nlohmann::json recipeStep() const override;

  private:
    std::vector<double> times_;
    double offset_;
};

// The edit moving the keys at `times` of `clip` by `offset` seconds (what
// MoveKeysCommand does). Throws rigmesh::Error as the command does.
ClipEdit movedKeysEdit(const rigmesh::Clip& clip, const std::vector<double>& times, double offset);

}  // namespace rigmesh::model
