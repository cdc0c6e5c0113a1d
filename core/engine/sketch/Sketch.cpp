#include "sketch/Sketch.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/Error.h"
#include "base/JsonRead.h"

namespace rigmesh {

namespace {

// Strings standing in for the bare NaN / Infinity tokens nlohmann_json cannot
// read; the leading control character keeps them apart from real strings.
constexpr const char* kNanMarker = "\x01NaN";
constexpr const char* kInfinityMarker = "\x01Infinity";
constexpr const char* kNegativeInfinityMarker = "\x01-Infinity";

bool startsWithWord(const std::string& text, std::size_t pos, const std::string& word) {
    if (text.compare(pos, word.size(), word) != 0) {
        return false;
    }
    const std::size_t after = pos + word.size();
    return after >= text.size() || std::isalnum(static_cast<unsigned char>(text[after])) == 0;
}

// Replaces NaN, Infinity and -Infinity tokens outside strings by marker strings.
std::string quoteNonFiniteTokens(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            out += c;
            if (c == '\\' && i + 1 < text.size()) {
                out += text[++i];
            } else if (c == '"') {
                inString = false;
            }
            continue;
        }
        if (c == '"') {
            inString = true;
            out += c;
        } else if (startsWithWord(text, i, "NaN")) {
            out += "\"\\u0001NaN\"";
            i += 2;
        } else if (startsWithWord(text, i, "Infinity")) {
            out += "\"\\u0001Infinity\"";
            i += 7;
        } else if (startsWithWord(text, i, "-Infinity")) {
            out += "\"\\u0001-Infinity\"";
            i += 8;
        } else {
            out += c;
        }
    }
    return out;
}

std::string stemOf(const std::string& sourceName) {
    return std::filesystem::path(sourceName).stem().string();
}

double coordinate(const nlohmann::json& value, std::size_t pointIndex, const char* axis,
                  const std::string& sourceName) {
    if (value.is_number()) {
        return value.get<double>();
    }
    if (value.is_string()) {
        const auto& text = value.get_ref<const std::string&>();
        if (text == kNanMarker) {
            return std::numeric_limits<double>::quiet_NaN();
        }
        if (text == kInfinityMarker) {
            return std::numeric_limits<double>::infinity();
        }
        if (text == kNegativeInfinityMarker) {
            return -std::numeric_limits<double>::infinity();
        }
    }
    // Only a primitive value is printed: dump() recurses once per level, and a
    // list nested 70,000 deep overflowed the stack (tests/data/fuzz).
    std::string shown = value.is_array()    ? "[...]"
                        : value.is_object() ? "{...}"
                        : value.is_null()   ? "null"
                                            : value.dump();
    if (shown.size() > 40)
        shown = shown.substr(0, 37) + "...";
    throw Error(MessageId::SketchCoordinateNotNumber, sourceName, pointIndex, shown, axis);
}

}  // namespace

Sketch parseSketchJson(const std::string& text, const std::string& sourceName) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(quoteNonFiniteTokens(text));
    } catch (const nlohmann::json::parse_error& error) {
        throw Error(
            Message{MessageId::SketchNotJson, {sourceName}, {jsonread::parseErrorReason(error)}});
    } catch (const nlohmann::json::exception& error) {
        // E.g. out_of_range 406: a number like 1e999 that no double can hold.
        throw Error(Message{
            MessageId::SketchNumberOutOfRange, {sourceName}, {jsonread::parseErrorReason(error)}});
    }
    if (!document.is_object()) {
        throw Error(MessageId::SketchNotObject, sourceName);
    }
    Sketch sketch;
    const auto name = document.find("name");
    sketch.name = (name != document.end() && name->is_string()) ? name->get<std::string>()
                                                                : stemOf(sourceName);
    const auto points = document.find("points");
    if (points == document.end() || !points->is_array()) {
        throw Error(MessageId::SketchNoPoints, sourceName);
    }
    sketch.points.reserve(points->size());
    for (std::size_t i = 0; i < points->size(); ++i) {
        const nlohmann::json& point = (*points)[i];
        if (!point.is_array() || point.size() != 2) {
            throw Error(MessageId::SketchPointNotPair, sourceName, i);
        }
        sketch.points.emplace_back(coordinate(point[0], i, "x", sourceName),
                                   coordinate(point[1], i, "y", sourceName));
    }
    return sketch;
}

Sketch readSketchFile(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".json" && extension != ".svg") {
        throw Error(MessageId::SketchFileTypeUnknown, path, extension);
    }
    std::error_code ignored;
    std::ifstream file(path, std::ios::binary);
    if (!file.is_open() || std::filesystem::is_directory(path, ignored)) {
        throw Error(MessageId::SketchFileUnreadable, path);
    }
    std::ostringstream contents;
    contents << file.rdbuf();
    if (file.bad()) {
        throw Error(MessageId::SketchFileReadFailed, path);
    }
    return extension == ".json" ? parseSketchJson(contents.str(), path)
                                : parseSketchSvg(contents.str(), path);
}

}  // namespace rigmesh
