// The shape of every message (base/MessageText.h): one line of at most
// kMaxMessageCharacters, quoted names at most kMaxQuotedCharacters, enforced
// by Error and fillMessage whatever their callers pass.
#include <gtest/gtest.h>

#include <string>

#include "base/Error.h"
#include "base/Message.h"
#include "base/MessageText.h"

namespace rigmesh {
namespace {

// Characters (UTF-8 code points) of `text`; -1 when it is not valid UTF-8.
long characterCount(const std::string& text) {
    long count = 0;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80           ? 1
                                   : (lead >> 5) == 0x06 ? 2
                                   : (lead >> 4) == 0x0E ? 3
                                   : (lead >> 3) == 0x1E ? 4
                                                         : 0;
        if (length == 0 || i + length > text.size())
            return -1;
        for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
                return -1;
        i += length;
        ++count;
    }
    return count;
}

// The text between the first pair of `open` and `close`.
std::string quotedPart(const std::string& text, const std::string& open, const std::string& close) {
    const std::size_t begin = text.find(open);
    const std::size_t end = text.find(close, begin + open.size());
    if (begin == std::string::npos || end == std::string::npos)
        return {};
    return text.substr(begin + open.size(), end - begin - open.size());
}

TEST(MessageText, ALongNameIsElidedInsideItsQuotes) {
    const std::string name(5000, 'n');
    const Error error("step 2 (rename): no part named \"" + name + "\" in the document");
    const std::string text = error.what();
    const std::string shown = quotedPart(text, "\"", "\"");
    EXPECT_LE(characterCount(shown), static_cast<long>(kMaxQuotedCharacters)) << text;
    EXPECT_EQ(shown.substr(0, 20), name.substr(0, 20)) << "the name's beginning is kept";
    EXPECT_NE(shown.find("\xE2\x80\xA6"), std::string::npos) << "an ellipsis shows the cut";
    EXPECT_NE(text.find("\" in the document"), std::string::npos) << "the rest is kept";
}

TEST(MessageText, ALibraryDumpBecomesOneShortLine) {
    // Assimp quoted a whole float array into its error once: 64,389 characters.
    std::string dump = "cannot import x.dae: Expected 3 floats, got:";
    for (int i = 0; i < 10000; ++i)
        dump += " 0.125\n";
    const Error error(dump);
    const std::string text = error.what();
    EXPECT_LE(characterCount(text), static_cast<long>(kMaxMessageCharacters));
    EXPECT_EQ(text.find('\n'), std::string::npos);
    EXPECT_EQ(text.rfind("cannot import x.dae", 0), 0u) << "the beginning says what failed";
}

TEST(MessageText, ControlCharactersAndRunsOfSpaceBecomeOneSpace) {
    EXPECT_EQ(oneLine("  a\n\tb\r\n  c  ", 100), "a b c");
    EXPECT_EQ(messageText("line one\nline two"), "line one line two");
}

TEST(MessageText, ElisionNeverCutsACharacterInTwo) {
    std::string accented;
    for (int i = 0; i < 500; ++i)
        accented += "\xC3\xA9";  // é
    const std::string line = oneLine(accented, 41);
    EXPECT_EQ(characterCount(line), 41);
    const std::string quoted = messageText("the part \xE2\x80\x9E" + accented + "\xE2\x80\x9C");
    const std::string shown = quotedPart(quoted, "\xE2\x80\x9E", "\xE2\x80\x9C");
    EXPECT_GT(characterCount(shown), 0) << quoted;
    EXPECT_LE(characterCount(shown), static_cast<long>(kMaxQuotedCharacters));
}

TEST(MessageText, FilledTemplatesKeepTheRuleWhateverTheArguments) {
    // An argument the template quotes is a name; any argument is one line.
    const std::string name(300, 'x');
    const std::string filled = fillMessage("\"%1\" cannot be rebuilt: %2", {name, "a\nb"});
    EXPECT_LE(characterCount(quotedPart(filled, "\"", "\"")),
              static_cast<long>(kMaxQuotedCharacters));
    EXPECT_NE(filled.find("rebuilt: a b"), std::string::npos) << filled;
    const Error error(MessageId::PartHasNoSketch, name);
    EXPECT_LE(characterCount(error.what()), static_cast<long>(kMaxMessageCharacters));
    EXPECT_EQ(error.message().args.front(), name) << "the id's arguments stay whole";
}

TEST(MessageText, EveryTemplateFitsOnItsLine) {
    for (int i = static_cast<int>(MessageId::None) + 1; i < static_cast<int>(MessageId::Count);
         ++i) {
        const std::string text = messageTemplate(static_cast<MessageId>(i));
        EXPECT_EQ(text.find('\n'), std::string::npos) << text;
        // Room for its arguments as short numbers (8 characters each for
        // a 2-character marker): a message is elided only by long names.
        long room = 0;
        for (std::size_t at = text.find('%'); at != std::string::npos; at = text.find('%', at + 1))
            room += 6;
        EXPECT_LE(characterCount(text) + room, static_cast<long>(kMaxMessageCharacters)) << text;
    }
}

TEST(MessageText, ShortTextIsUnchanged) {
    EXPECT_EQ(messageText("The part has no bone 7."), "The part has no bone 7.");
    EXPECT_EQ(messageText("a \"quoted\" word and an unmatched \" quote"),
              "a \"quoted\" word and an unmatched \" quote");
}

}  // namespace
}  // namespace rigmesh
