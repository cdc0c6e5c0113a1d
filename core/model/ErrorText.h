// The one place where the studio turns an exception into text for the user:
// an engine Error with a message id is shown in the current language (its
// English template translated in the context "EngineMessage" and filled with
// its arguments); any other exception shows its what() as it is.
#pragma once

#include <QString>
#include <exception>

#include "base/Message.h"

namespace rigmesh::model {

// The translated text of `message` (English where no translation is loaded).
QString messageText(const Message& message);

// The text of `error` for the user.
QString errorText(const std::exception& error);

}  // namespace rigmesh::model
