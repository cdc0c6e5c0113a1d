#include "model/ErrorText.h"

#include <QCoreApplication>

#include "base/Error.h"

namespace rigmesh::model {

QString messageText(const Message& message) {
    // The same template the engine wrote its English from: lupdate listed it
    // under "EngineMessage" (base/MessageCatalog.cpp).
    const QString translated =
        QCoreApplication::translate("EngineMessage", messageTemplate(message.id));
    return QString::fromStdString(fillMessage(translated.toStdString(), message.args));
}

QString errorText(const std::exception& error) {
    if (const auto* engineError = dynamic_cast<const Error*>(&error))
        if (engineError->message().id != MessageId::None)
            return messageText(engineError->message());
    return QString::fromUtf8(error.what());
}

}  // namespace rigmesh::model
