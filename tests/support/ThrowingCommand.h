// An undo command for the tests of the studio's failure paths
// (core/model/GuardedUndo.h, widgets/UserAction.h): it renames a part, or,
// when told to fail, changes the document half-way (renames the part, adds
// a copy of it under a fresh id, removes the others, lengthens the timeline,
// selects the copy) and then throws a std::logic_error, as a programming
// error in a command would.
#pragma once

#include <QUndoCommand>
#include <stdexcept>
#include <vector>

#include "model/Document.h"

namespace rigmesh::test {

inline constexpr const char* kBrokenOnPurpose = "a command broken on purpose";

class ThrowingCommand : public QUndoCommand {
  public:
    enum class Throws {
        Never,
        OnRedo,       // the first redo() (the push) already
        OnLaterRedo,  // every redo() after the first (a Redo, a History click)
        OnUndo,
    };

    ThrowingCommand(model::Document& document, model::PartId id, const QString& name, Throws throws)
        : QUndoCommand(QStringLiteral("Rename to %1").arg(name)),
          document_(document),
          id_(id),
          oldName_(document.part(id).name),
          name_(name),
          throws_(throws) {}

    void redo() override {
        ++redos_;
        if (throws_ == Throws::OnRedo || (throws_ == Throws::OnLaterRedo && redos_ > 1))
            failHalfWay();
        document_.setName(id_, name_);
    }

    void undo() override {
        if (throws_ == Throws::OnUndo)
            failHalfWay();
        document_.setName(id_, oldName_);
    }

  private:
    [[noreturn]] void failHalfWay() {
        document_.setName(id_, QStringLiteral("half-changed"));
        model::PartNode copy = document_.part(id_);
        copy.id = document_.allocatePartId();
        const model::PartId copyId = copy.id;
        document_.insertPart(0, std::move(copy));
        std::vector<model::PartId> others;
        for (const model::PartNode& node : document_.parts())
            if (node.id != id_ && node.id != copyId)
                others.push_back(node.id);
        for (const model::PartId other : others)
            document_.removePart(other);
        model::TimelineSettings longer = document_.timeline();
        longer.endFrame += 24;
        document_.setTimeline(longer);
        document_.setSelection({copyId, kNoJoint});
        throw std::logic_error(kBrokenOnPurpose);
    }

    model::Document& document_;
    model::PartId id_;
    QString oldName_;
    QString name_;
    Throws throws_;
    int redos_ = 0;
};

}  // namespace rigmesh::test
