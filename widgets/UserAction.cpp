#include "UserAction.h"

#include <new>

#include "base/Error.h"
#include "model/ErrorText.h"

namespace rigmesh::widgets {

QString UserAction::internalError(const QString& name, const QString& details) {
    return name.isEmpty() ? tr("Internal error: %1").arg(details)
                          : tr("%1: internal error (%2)").arg(name, details);
}

QString UserAction::failureText(const QString& action, const std::exception_ptr& thrown) {
    // A menu item's text without its mnemonic ("&&" is a literal '&').
    QString name;
    for (qsizetype i = 0; i < action.size(); ++i) {
        if (action[i] == QLatin1Char('&') && i + 1 < action.size())
            ++i;
        name += action[i];
    }
    try {
        std::rethrow_exception(thrown);
    } catch (const Error& error) {
        return model::errorText(error);
    } catch (const std::bad_alloc&) {
        return name.isEmpty() ? tr("Out of memory.") : tr("%1: out of memory").arg(name);
    } catch (const std::exception& error) {
        return internalError(name, QString::fromUtf8(error.what()));
    } catch (...) {
        return internalError(name, QStringLiteral("an exception of unknown type"));
    }
}

}  // namespace rigmesh::widgets
