// Every refusal the engine and the model throw is an Error built from a
// MessageId, so the studio can show it translated (docs/ARCHITECTURE.md,
// "Translations"): a `throw Error(` whose arguments hold a string literal,
// an id's argument included, is English only. None is left; a new one fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace {

// The text from `at` (an opening parenthesis) to its closing one, string
// and character literals skipped whole.
std::string parenthesised(const std::string& text, std::size_t at) {
    int depth = 0;
    for (std::size_t i = at; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"' || c == '\'') {
            for (++i; i < text.size() && text[i] != c; ++i)
                if (text[i] == '\\')
                    ++i;
        } else if (c == '(') {
            ++depth;
        } else if (c == ')' && --depth == 0) {
            return text.substr(at, i + 1 - at);
        }
    }
    return text.substr(at);
}

// How many `throw Error(...)` in `text` hold a string literal.
int literalThrows(const std::string& text) {
    const std::string opening = "throw Error(";
    int count = 0;
    for (std::size_t at = text.find(opening); at != std::string::npos;
         at = text.find(opening, at + 1)) {
        const std::string arguments = parenthesised(text, at + opening.size() - 1);
        if (arguments.find('"') != std::string::npos)
            ++count;
    }
    return count;
}

TEST(ErrorLiterals, EngineAndModelThrowNoNewEnglishLiterals) {
    const std::map<std::string, int> remaining = {};
    const std::filesystem::path root(RIGMESH_SOURCE_DIR);
    std::map<std::string, int> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "core")) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".h"))
            continue;
        std::ifstream file(entry.path());
        std::ostringstream text;
        text << file.rdbuf();
        if (const int count = literalThrows(text.str()); count > 0)
            found[std::filesystem::relative(entry.path(), root).generic_string()] = count;
    }
    EXPECT_EQ(found, remaining)
        << "throw Error(MessageId::..., arguments) with an English template in "
           "core/engine/base/MessageCatalog*.cpp and its translations in translations/*.ts; "
           "a programming error is a std::logic_error";
}

TEST(ErrorLiterals, TheScanSeesLiteralsAndNotIds) {
    EXPECT_EQ(literalThrows("throw Error(\"no\");"), 1);
    EXPECT_EQ(literalThrows("throw Error(std::string(\"a\") + b);"), 1);
    EXPECT_EQ(literalThrows("throw Error(MessageId::NoSuchPart);"), 0);
    // An argument in English is English too.
    EXPECT_EQ(literalThrows("throw Error(MessageId::X, \"the flow gave no curve.\");"), 1);
    // A parenthesis in a literal does not end the arguments.
    EXPECT_EQ(literalThrows("throw Error(MessageId::X, f(')'), g(1));\nthrow Error(\"y\");"), 1);
    EXPECT_EQ(literalThrows("throw std::logic_error(\"internal\");"), 0);
}

}  // namespace
