// The one exception type the engine throws at its boundary. Its message is
// written for the user: it says what is wrong with their input and, where it
// helps, what to do instead. An Error made from a MessageId also carries the
// id and its arguments, so the studio can show it translated; what() is
// always the English text (the CLI prints it). Every text is put in the
// shape messages keep (base/MessageText.h: one line, at most about 200
// characters, quoted names at most 60).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "base/Message.h"
#include "base/MessageText.h"

namespace rigmesh {

class Error : public std::runtime_error {
  public:
    // A message without an id: shown as it is, in English.
    explicit Error(const std::string& text) : std::runtime_error(messageText(text)) {}

    explicit Error(Message message)
        : std::runtime_error(englishText(message)), message_(std::move(message)) {}

    // E.g. Error(MessageId::PartHasNoBone, bone); messages nest (makeMessage).
    template <class... Args>
    explicit Error(MessageId id, const Args&... args) : Error(makeMessage(id, args...)) {}

    // The id (None for a message without one) and the arguments.
    const Message& message() const { return message_; }

  private:
    Message message_;
};

// What `error` says, as a message that can fill another one's marker: an
// Error's own message, or any other exception's text as it is (a library's
// English, which no catalogue translates).
inline Message messageOf(const std::exception& error) {
    if (const auto* engineError = dynamic_cast<const Error*>(&error))
        if (engineError->message().id != MessageId::None)
            return engineError->message();
    return Message{MessageId::UntranslatedText, {error.what()}, {}};
}

}  // namespace rigmesh
