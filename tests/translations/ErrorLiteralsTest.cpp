// Every refusal the engine and the model throw is an Error built from a
// MessageId, so the studio can show it translated (docs/ARCHITECTURE.md,
// "Translations"): a `throw Error(` whose arguments hold a string literal,
// an id's argument included, is English only. The same holds for the
// readers' own ways to throw (`fail(`, the document reader's `corrupt(`,
// `throw RecipeError(`), where a literal is allowed only as a field's path
// (a raw string, R"("mesh" "faces")") or inside QT_TRANSLATE_NOOP or
// translate(). None is left; a new one fails.
#include <gtest/gtest.h>

#include <cctype>
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

// `arguments` without what may hold literals: raw strings (a field's path)
// and the arguments of QT_TRANSLATE_NOOP( and translate( (lupdate's).
std::string withoutPathsAndTranslations(std::string arguments) {
    for (std::size_t at = arguments.find("R\"("); at != std::string::npos;
         at = arguments.find("R\"(", at)) {
        const std::size_t end = arguments.find(")\"", at + 3);
        arguments.erase(at, end == std::string::npos ? std::string::npos : end + 2 - at);
    }
    for (const std::string call : {"QT_TRANSLATE_NOOP(", "translate("}) {
        for (std::size_t at = arguments.find(call); at != std::string::npos;
             at = arguments.find(call, at + 1))
            arguments.erase(at + call.size() - 1,
                            parenthesised(arguments, at + call.size() - 1).size());
    }
    return arguments;
}

// How many throws of an English literal `text` holds: `throw Error(...)`
// with a string literal among its arguments, or a reader's `fail(`,
// `corrupt(` or `throw RecipeError(` with one outside paths and translations.
int literalThrows(const std::string& text) {
    int count = 0;
    for (const std::string opening : {"throw Error(", "throw RecipeError(", "fail(", "corrupt("}) {
        const bool pathsAllowed = opening != "throw Error(";
        for (std::size_t at = text.find(opening); at != std::string::npos;
             at = text.find(opening, at + 1)) {
            // "fail(" inside a longer name (failure(, mustFail() is not a throw.
            if (at > 0 &&
                (std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_'))
                continue;
            std::string arguments = parenthesised(text, at + opening.size() - 1);
            if (pathsAllowed)
                arguments = withoutPathsAndTranslations(arguments);
            if (arguments.find('"') != std::string::npos)
                ++count;
        }
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
    // A reader's own throws: a path or a translated text is no English literal.
    EXPECT_EQ(literalThrows("fail(\"missing \\\"\" + key);"), 1);
    EXPECT_EQ(literalThrows("fail(MessageId::DataWrongLength, R\"(\"mesh\" \"faces\")\");"), 0);
    EXPECT_EQ(literalThrows("corrupt(QT_TRANSLATE_NOOP(\"C\", \"a part has no id\"));"), 0);
    EXPECT_EQ(literalThrows("corrupt(\"a part has no id\");"), 1);
    EXPECT_EQ(literalThrows("fail(translate(\"C\", \"x %1\").arg(\"y\"));"), 1);
    EXPECT_EQ(literalThrows("throw RecipeError(n, \"?\", reason);"), 1);
    EXPECT_EQ(literalThrows("mustFail(\"x\"); failure(\"y\");"), 0);
}

}  // namespace
