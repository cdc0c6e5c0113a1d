#include "sketch/SvgNumberScanner.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>

namespace rigmesh {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

bool isSeparator(char c) {
    return c == ',' || std::isspace(static_cast<unsigned char>(c)) != 0;
}

}  // namespace

SvgNumberScanner::SvgNumberScanner(std::string_view text, std::string attribute)
    : text_(text), attribute_(std::move(attribute)) {}

void SvgNumberScanner::skipSeparators() {
    while (pos_ < text_.size() && isSeparator(text_[pos_])) {
        ++pos_;
    }
}

bool SvgNumberScanner::atEnd() {
    skipSeparators();
    return pos_ >= text_.size();
}

bool SvgNumberScanner::nextIsNumber() {
    skipSeparators();
    if (pos_ >= text_.size()) {
        return false;
    }
    const char c = text_[pos_];
    return isDigit(c) || c == '-' || c == '+' || c == '.';
}

bool SvgNumberScanner::nextIsLetter() {
    skipSeparators();
    return pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])) != 0;
}

char SvgNumberScanner::letter() {
    if (!nextIsLetter()) {
        fail(MessageId::SvgExpectedLetter);
    }
    return text_[pos_++];
}

std::string SvgNumberScanner::word() {
    if (!nextIsLetter()) {
        fail(MessageId::SvgExpectedName);
    }
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])) != 0) {
        ++pos_;
    }
    return std::string(text_.substr(begin, pos_ - begin));
}

double SvgNumberScanner::number() {
    skipSeparators();
    // Find the extent of the number by hand: SVG numbers end where the next
    // one can start, so "-.5.5" is two numbers and "1e" is 1 followed by 'e'.
    std::size_t end = pos_;
    if (end < text_.size() && (text_[end] == '-' || text_[end] == '+')) {
        ++end;
    }
    std::size_t digits = 0;
    while (end < text_.size() && isDigit(text_[end])) {
        ++end;
        ++digits;
    }
    if (end < text_.size() && text_[end] == '.') {
        ++end;
        while (end < text_.size() && isDigit(text_[end])) {
            ++end;
            ++digits;
        }
    }
    if (digits == 0) {
        fail(MessageId::SvgExpectedNumber);
    }
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
        std::size_t exponent = end + 1;
        if (exponent < text_.size() && (text_[exponent] == '-' || text_[exponent] == '+')) {
            ++exponent;
        }
        if (exponent < text_.size() && isDigit(text_[exponent])) {
            while (exponent < text_.size() && isDigit(text_[exponent])) {
                ++exponent;
            }
            end = exponent;
        }
    }
    // std::from_chars rejects a leading '+', so skip it.
    const std::size_t begin = text_[pos_] == '+' ? pos_ + 1 : pos_;
    double value = 0.0;
    const auto result = std::from_chars(text_.data() + begin, text_.data() + end, value);
    if (result.ec != std::errc() || !std::isfinite(value)) {
        fail(MessageId::SvgNumberOutOfRange);
    }
    pos_ = end;
    return value;
}

bool SvgNumberScanner::flag() {
    skipSeparators();
    if (pos_ < text_.size() && (text_[pos_] == '0' || text_[pos_] == '1')) {
        return text_[pos_++] == '1';
    }
    fail(MessageId::SvgExpectedArcFlag);
}

bool SvgNumberScanner::accept(char expected) {
    skipSeparators();
    if (pos_ < text_.size() && text_[pos_] == expected) {
        ++pos_;
        return true;
    }
    return false;
}

void SvgNumberScanner::fail(MessageId problem, std::vector<std::string> details) const {
    std::string excerpt(text_.substr(0, 80));
    if (text_.size() > 80)
        excerpt += "...";
    throw SvgSyntaxError{problem, attribute_, pos_ + 1, std::move(excerpt), std::move(details)};
}

}  // namespace rigmesh
