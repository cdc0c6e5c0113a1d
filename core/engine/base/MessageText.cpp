#include "base/MessageText.h"

#include <array>
#include <vector>

namespace rigmesh {
namespace {

constexpr std::string_view kEllipsis = "\xE2\x80\xA6";  // U+2026

// The byte length of the UTF-8 character at `at`, 1 for a byte that does
// not start a valid sequence.
std::size_t characterLength(std::string_view text, std::size_t at) {
    const auto lead = static_cast<unsigned char>(text[at]);
    const std::size_t length = lead < 0x80           ? 1
                               : (lead >> 5) == 0x06 ? 2
                               : (lead >> 4) == 0x0E ? 3
                               : (lead >> 3) == 0x1E ? 4
                                                     : 1;
    if (at + length > text.size())
        return 1;
    for (std::size_t k = 1; k < length; ++k)
        if ((static_cast<unsigned char>(text[at + k]) & 0xC0) != 0x80)
            return 1;
    return length;
}

// The text split into characters.
std::vector<std::string_view> characters(std::string_view text) {
    std::vector<std::string_view> out;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = characterLength(text, at);
        out.push_back(text.substr(at, length));
        at += length;
    }
    return out;
}

bool isControl(std::string_view character) {
    if (character.size() != 1)
        return false;
    const auto c = static_cast<unsigned char>(character[0]);
    return c < 0x20 || c == 0x7F;
}

// At most `maxCharacters`: the beginning and the end around " … ".
std::string elided(const std::vector<std::string_view>& chars, std::size_t maxCharacters) {
    std::string out;
    if (chars.size() <= maxCharacters) {
        for (std::string_view c : chars)
            out += c;
        return out;
    }
    const std::size_t kept = maxCharacters > 3 ? maxCharacters - 3 : 0;
    const std::size_t head = (kept + 1) / 2;
    const std::size_t tail = kept - head;
    for (std::size_t i = 0; i < head; ++i)
        out += chars[i];
    out += ' ';
    out += kEllipsis;
    out += ' ';
    for (std::size_t i = chars.size() - tail; i < chars.size(); ++i)
        out += chars[i];
    return out;
}

// Opening quotes and the quote that closes each.
struct QuotePair {
    std::string_view open, close;
};
constexpr std::array<QuotePair, 4> kQuotes{{
    {"\"", "\""},
    {"\xE2\x80\x9C", "\xE2\x80\x9D"},  // “ ”
    {"\xE2\x80\x9E", "\xE2\x80\x9C"},  // „ “
    {"\xC2\xAB", "\xC2\xBB"},          // « »
}};

}  // namespace

std::string oneLine(std::string_view text, std::size_t maxCharacters) {
    std::vector<std::string_view> chars;
    for (std::string_view c : characters(text)) {
        const bool space = c == " " || isControl(c);
        if (space && (chars.empty() || chars.back() == " "))
            continue;
        chars.push_back(space ? std::string_view(" ") : c);
    }
    if (!chars.empty() && chars.back() == " ")
        chars.pop_back();
    return elided(chars, maxCharacters);
}

std::string messageText(std::string_view text) {
    const std::string line = oneLine(text, std::string_view::npos);
    const std::vector<std::string_view> chars = characters(line);
    std::string out;
    for (std::size_t i = 0; i < chars.size(); ++i) {
        out += chars[i];
        const QuotePair* quote = nullptr;
        for (const QuotePair& pair : kQuotes)
            if (chars[i] == pair.open)
                quote = &pair;
        if (!quote)
            continue;
        std::size_t close = i + 1;
        while (close < chars.size() && chars[close] != quote->close)
            ++close;
        if (close == chars.size())
            continue;  // unmatched: left as it is
        const std::vector<std::string_view> inside(chars.begin() + static_cast<long>(i) + 1,
                                                   chars.begin() + static_cast<long>(close));
        out += elided(inside, kMaxQuotedCharacters);
        out += chars[close];
        i = close;
    }
    return oneLine(out, kMaxMessageCharacters);
}

}  // namespace rigmesh
