#include "model/ErrorText.h"

#include <QCoreApplication>

#include "base/Error.h"

namespace rigmesh::model {

QString messageText(const Message& message) {
    // The same template the engine wrote its English from: lupdate listed it
    // under "EngineMessage" (base/MessageCatalog.cpp).
    const QString translated =
        QCoreApplication::translate("EngineMessage", messageTemplate(message.id));
    std::vector<std::string> args = message.args;
    for (const Message& nested : message.nested)
        args.push_back(messageText(nested).toStdString());
    return QString::fromStdString(fillMessage(translated.toStdString(), args));
}

QString errorText(const std::exception& error) {
    if (const auto* engineError = dynamic_cast<const Error*>(&error))
        if (engineError->message().id != MessageId::None)
            return messageText(engineError->message());
    return QString::fromUtf8(error.what());
}

}  // namespace rigmesh::model
