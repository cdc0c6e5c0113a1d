// The one path in the studio from an exception to a message: everything the
// user starts on the GUI thread (a menu action, a click or drag that ends in
// an undo step, a finished background job's apply step, Undo and Redo) runs
// through runUserAction, and nothing thrown reaches Qt's event loop (an
// exception through an event handler ends the program).
//
// A rigmesh::Error is a refusal of the user's input: its message in the
// user's language (model::errorText), exactly as the caller showed it
// before. Anything else is a programming error or a library's failure
// (std::logic_error, std::bad_alloc, ...): "<action>: internal error
// (<what>)". Either way the document is left as it was: changes go through
// model/GuardedUndo, which puts it back when a command throws.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <exception>
#include <functional>
#include <utility>

namespace rigmesh::widgets {

// Where a failure's text goes: the status bar, a message box, a label.
using ReportFailure = std::function<void(const QString& text)>;

class UserAction {
    Q_DECLARE_TR_FUNCTIONS(rigmesh::widgets::UserAction)
  public:
    // The text for the user of `thrown`, raised while doing `action` (a
    // short translated name of what the user asked for, e.g. a menu item's
    // text; its '&' mnemonics are dropped). An empty `action` for a caller
    // whose message already says what failed ("Could not recover: %1"):
    // "Internal error: <what>".
    static QString failureText(const QString& action, const std::exception_ptr& thrown);

  private:
    static QString internalError(const QString& name, const QString& details);
};

// Runs `action`. True if it returned; false if it threw, after handing the
// failure's text to `report`.
template <typename Action>
bool runUserAction(const QString& actionName, const ReportFailure& report, Action&& action) {
    try {
        std::forward<Action>(action)();
        return true;
    } catch (...) {
        report(UserAction::failureText(actionName, std::current_exception()));
        return false;
    }
}

}  // namespace rigmesh::widgets
