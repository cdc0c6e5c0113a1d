// The shape of every message a user reads, enforced in one place: one line
// of about 200 characters (at most kMaxMessageCharacters), with every quoted
// name at most kMaxQuotedCharacters. rigmesh::Error applies it to each text
// it is given and fillMessage to each filled template (English or
// translated), so no call site has to: a 5,000-character part name or a
// library's 64 KB error string cannot make a message unreadable.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rigmesh {

inline constexpr std::size_t kMaxMessageCharacters = 200;
inline constexpr std::size_t kMaxQuotedCharacters = 60;

// `text` as one line: line breaks, tabs and other control characters become
// spaces and runs of spaces one space, trimmed; longer than `maxCharacters`
// characters (UTF-8 code points), its middle gives way to " … ". Invalid
// UTF-8 bytes are kept as they are, each counted as one character.
std::string oneLine(std::string_view text, std::size_t maxCharacters);

// `text` as a message: one line of at most kMaxMessageCharacters, and each
// span in double quotes ("...", “...”, „...“, «...») at most
// kMaxQuotedCharacters inside its quotes.
std::string messageText(std::string_view text);

}  // namespace rigmesh
