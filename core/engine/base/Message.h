// User-facing engine messages by id, so that the studio can show them in the
// user's language while the engine stays Qt-free and the CLI prints English.
// Each id has an English template with %1, %2, ... for its arguments
// (MessageCatalog.cpp); the studio translates the template, found by the
// same id, and fills in the same arguments (model/ErrorText).
#pragma once

#include <concepts>
#include <iosfwd>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "base/MessageId.h"

namespace rigmesh {

// A message: its id and its arguments, already text, and the messages that
// fill the template's markers after the arguments' own, each put in the
// reader's language first ("The document is corrupt: %1." with what is wrong
// as a message of its own).
struct Message {
    MessageId id = MessageId::None;
    std::vector<std::string> args;
    std::vector<Message> nested = {};

    friend bool operator==(const Message&, const Message&) = default;
};

// The English template of `id`, e.g. "The part has no bone %1." (empty for None).
const char* messageTemplate(MessageId id);

// `text` with %1 .. %9 replaced by `args` in one pass, so an argument that
// itself holds "%2" stays as it is; a missing argument leaves its marker.
// The result has the shape of every message (base/MessageText.h: one line,
// quoted names elided), whatever the arguments hold.
std::string fillMessage(std::string_view text, const std::vector<std::string>& args);

// The English text of `message`, nested messages included.
std::string englishText(const Message& message);
// The English texts of `messages` on one line, separated by spaces.
std::string englishText(const std::vector<Message>& messages);

// Its English text, e.g. in a test's failure output.
std::ostream& operator<<(std::ostream& out, const Message& message);

// A number for a message: three significant digits ("0.000215", "1.5e+06").
std::string shortNumber(double value);

// Message arguments are text: integers are written in full, strings as they
// are. Other numbers are formatted by the caller, so the engine decides
// their precision; most use shortNumber.
inline std::string messageArgument(std::string text) {
    return text;
}
inline std::string messageArgument(const char* text) {
    return text;
}
template <std::integral Integer>
std::string messageArgument(Integer value) {
    return std::to_string(value);
}

// A message from its id and arguments, in the template's order: text and
// integers become arguments; a Message (e.g. a part's first problem inside
// the refusal it caused) fills a marker after them, in the reader's
// language, so messages come last.
template <class... Args>
constexpr bool messagesComeLast() {
    bool seenMessage = false, inOrder = true;
    ((std::is_same_v<Args, Message> ? void(seenMessage = true)
                                    : void(inOrder = inOrder && !seenMessage)),
     ...);
    return inOrder;
}

template <class... Args>
Message makeMessage(MessageId id, const Args&... args) {
    static_assert(messagesComeLast<Args...>(), "nested messages fill the last markers");
    Message message{id, {}};
    [[maybe_unused]] const auto add = [&message](const auto& argument) {
        if constexpr (std::is_same_v<std::decay_t<decltype(argument)>, Message>)
            message.nested.push_back(argument);
        else
            message.args.push_back(messageArgument(argument));
    };
    (add(args), ...);
    return message;
}

}  // namespace rigmesh
