// Reads the numbers, flags and letters of SVG attribute micro-syntaxes (path
// data, transform lists, point lists), where separators are optional:
// "M10-5.5.5e1" is the three numbers 10, -5.5 and 0.5e1 after the letter M.
#pragma once

#include <string>
#include <string_view>

namespace rigmesh {

class SvgNumberScanner {
  public:
    // `what` names the attribute in error messages, e.g. "path data".
    SvgNumberScanner(std::string_view text, std::string what);

    // Skips whitespace and commas; true when nothing but separators remains.
    bool atEnd();
    // True when the next token starts a number (sign, digit or dot).
    bool nextIsNumber();
    // True when the next token is a letter (a command or function name).
    bool nextIsLetter();
    // Reads one letter; the caller checked nextIsLetter().
    char letter();
    // Reads a run of letters, e.g. "translate".
    std::string word();
    // Reads one number; throws rigmesh::Error when there is none.
    double number();
    // Reads an arc flag, a single '0' or '1' that needs no separator.
    bool flag();
    // Reads `expected` when it comes next (after separators); false otherwise.
    bool accept(char expected);

    // Throws rigmesh::Error describing `problem` at the current position.
    [[noreturn]] void fail(const std::string& problem) const;

  private:
    void skipSeparators();

    std::string_view text_;
    std::string what_;
    std::size_t pos_ = 0;
};

}  // namespace rigmesh
