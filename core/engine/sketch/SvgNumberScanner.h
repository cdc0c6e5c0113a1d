// Reads the numbers, flags and letters of SVG attribute micro-syntaxes (path
// data, transform lists, point lists), where separators are optional:
// "M10-5.5.5e1" is the three numbers 10, -5.5 and 0.5e1 after the letter M.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/Message.h"

namespace rigmesh {

// A malformed attribute, as the scanner found it. parseSketchSvg
// (sketch/SvgSketch.cpp) turns it into an Error that also names the file.
struct SvgSyntaxError {
    MessageId problem;                 // one of the Svg* ids
    std::string attribute;             // the attribute's name, e.g. "d"
    std::size_t character = 0;         // from 1
    std::string excerpt;               // the attribute's first 80 characters
    std::vector<std::string> details;  // the problem's own arguments (%5, %6)
};

class SvgNumberScanner {
  public:
    // `attribute` names the attribute in error messages, e.g. "d".
    SvgNumberScanner(std::string_view text, std::string attribute);

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
    // Reads one number; throws SvgSyntaxError when there is none.
    double number();
    // Reads an arc flag, a single '0' or '1' that needs no separator.
    bool flag();
    // Reads `expected` when it comes next (after separators); false otherwise.
    bool accept(char expected);

    // Throws SvgSyntaxError: `problem` at the current position.
    [[noreturn]] void fail(MessageId problem, std::vector<std::string> details = {}) const;

  private:
    void skipSeparators();

    std::string_view text_;
    std::string attribute_;
    std::size_t pos_ = 0;
};

}  // namespace rigmesh
