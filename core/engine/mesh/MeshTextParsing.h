// Small strict parsing helpers shared by the mesh file readers, which throw
// an Error saying where a token failed to parse.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rigmesh::meshtext {

// The whitespace-separated tokens of one line.
inline std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> result;
    std::size_t i = 0;
    while (true) {
        i = line.find_first_not_of(" \t\r\f\v", i);
        if (i == std::string_view::npos)
            return result;
        const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", i), line.size());
        result.push_back(line.substr(i, end - i));
        i = end;
    }
}

// Splits text into lines at '\n' (a trailing '\r' is left to tokens()).
class LineReader {
  public:
    explicit LineReader(std::string_view text) : text_(text) {}
    bool next(std::string_view& line) {
        if (pos_ >= text_.size())
            return false;
        const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
        line = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++number_;
        return true;
    }
    int lineNumber() const { return number_; }
    std::size_t position() const { return std::min(pos_, text_.size()); }  // start of the next line

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int number_ = 0;
};

// A finite double; a leading '+' is accepted, as C's strtod does. Nothing
// for any other token: the reader says where it was, in its own message.
inline std::optional<double> toDouble(std::string_view token) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

inline std::optional<long long> toInteger(std::string_view token) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    long long value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
        return std::nullopt;
    return value;
}

}  // namespace rigmesh::meshtext
