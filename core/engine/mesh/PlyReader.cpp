#include "mesh/PlyReader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>

#include "base/Error.h"
#include "mesh/MeshTextParsing.h"

namespace rigmesh {

namespace {

using meshtext::LineReader;
using meshtext::tokens;

enum class Encoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct ScalarType {
    int size = 0;  // bytes in binary files
    bool isFloat = false;
    bool isSigned = false;
};

struct Property {
    std::string name;
    ScalarType type;
    bool isList = false;
    ScalarType countType;  // lists only
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    std::size_t bodyOffset = 0;
};

// `path` and `line` name the header line in a message.
ScalarType scalarType(std::string_view name, const std::string& path, int line) {
    if (name == "char" || name == "int8")
        return {1, false, true};
    if (name == "uchar" || name == "uint8")
        return {1, false, false};
    if (name == "short" || name == "int16")
        return {2, false, true};
    if (name == "ushort" || name == "uint16")
        return {2, false, false};
    if (name == "int" || name == "int32")
        return {4, false, true};
    if (name == "uint" || name == "uint32")
        return {4, false, false};
    if (name == "float" || name == "float32")
        return {4, true, true};
    if (name == "double" || name == "float64")
        return {8, true, true};
    throw Error(MessageId::PlyHeaderUnknownType, path, line, std::string(name));
}

Header parseHeader(std::string_view bytes, const std::string& path) {
    LineReader lines(bytes);
    std::string_view line;
    if (!lines.next(line) || tokens(line) != std::vector<std::string_view>{"ply"})
        throw Error(MessageId::PlyNoMagic, path);
    Header header;
    bool sawFormat = false;
    while (true) {
        if (!lines.next(line))
            throw Error(MessageId::PlyNoEndHeader, path);
        const auto parts = tokens(line);
        const int at = lines.lineNumber();
        if (parts.empty() || parts[0] == "comment" || parts[0] == "obj_info")
            continue;
        if (parts[0] == "end_header")
            break;
        if (parts[0] == "format" && parts.size() >= 2) {
            if (parts[1] == "ascii")
                header.encoding = Encoding::Ascii;
            else if (parts[1] == "binary_little_endian")
                header.encoding = Encoding::BinaryLittleEndian;
            else if (parts[1] == "binary_big_endian")
                header.encoding = Encoding::BinaryBigEndian;
            else
                throw Error(MessageId::PlyHeaderUnknownFormat, path, at, std::string(parts[1]));
            sawFormat = true;
        } else if (parts[0] == "element" && parts.size() == 3) {
            const std::optional<long long> count = meshtext::toInteger(parts[2]);
            if (!count)
                throw Error(MessageId::PlyHeaderNotAnInteger, path, at, std::string(parts[2]));
            if (*count < 0 || *count > std::numeric_limits<int>::max())
                throw Error(MessageId::PlyHeaderInvalidCount, path, at, std::string(parts[2]));
            header.elements.push_back(
                {std::string(parts[1]), static_cast<std::size_t>(*count), {}});
        } else if (parts[0] == "property" && !header.elements.empty()) {
            Property property;
            if (parts.size() == 5 && parts[1] == "list") {
                property = {std::string(parts[4]), scalarType(parts[3], path, at), true,
                            scalarType(parts[2], path, at)};
                if (property.countType.isFloat)
                    throw Error(MessageId::PlyHeaderListCountType, path, at);
            } else if (parts.size() == 3) {
                property = {std::string(parts[2]), scalarType(parts[1], path, at), false, {}};
            } else {
                throw Error(MessageId::PlyHeaderMalformedProperty, path, at);
            }
            header.elements.back().properties.push_back(property);
        } else {
            throw Error(MessageId::PlyHeaderUnexpected, path, at, std::string(line));
        }
    }
    if (!sawFormat)
        throw Error(MessageId::PlyNoFormat, path);
    header.bodyOffset = lines.position();
    return header;
}

// Where the body is being read, for messages: file, element, entry (from 1).
struct BodyPlace {
    const std::string& path;
    const std::string& element;
    std::size_t entry = 0;
    std::size_t count = 0;

    // E.g. Error(MessageId::PlyCoordinateNotFinite, path, "vertex", 3, 8).
    template <class... Args>
    Error error(MessageId id, const Args&... more) const {
        return Error(id, path, element, entry, count, more...);
    }
};

// Reads the values of the body one at a time, in the file's encoding.
class BodyReader {
  public:
    BodyReader(std::string_view body, Encoding encoding) : body_(body), encoding_(encoding) {}

    // Throws Error (naming `at`) if the body ends or the value is malformed.
    double read(const ScalarType& type, const BodyPlace& at) {
        return encoding_ == Encoding::Ascii ? readText(at) : readBinary(type, at);
    }
    std::size_t remaining() const { return body_.size() - pos_; }
    bool isBinary() const { return encoding_ != Encoding::Ascii; }

  private:
    double readText(const BodyPlace& at) {
        const std::size_t begin = body_.find_first_not_of(" \t\r\n\f\v", pos_);
        if (begin == std::string_view::npos)
            throw at.error(MessageId::PlyTruncatedIn);
        pos_ = std::min(body_.find_first_of(" \t\r\n\f\v", begin), body_.size());
        const std::string_view token = body_.substr(begin, pos_ - begin);
        if (const auto value = meshtext::toDouble(token))
            return *value;
        throw at.error(MessageId::PlyNotANumber, std::string(token));
    }

    double readBinary(const ScalarType& type, const BodyPlace& at) {
        if (remaining() < static_cast<std::size_t>(type.size))
            throw at.error(MessageId::PlyTruncatedIn);
        unsigned char raw[8];
        std::memcpy(raw, body_.data() + pos_, type.size);
        pos_ += type.size;
        const bool fileIsLittle = encoding_ == Encoding::BinaryLittleEndian;
        if (fileIsLittle != (std::endian::native == std::endian::little))
            std::reverse(raw, raw + type.size);
        return decode(raw, type);
    }

    template <class T>
    static double as(const unsigned char* raw) {
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return static_cast<double>(value);
    }

    static double decode(const unsigned char* raw, const ScalarType& type) {
        if (type.isFloat)
            return type.size == 4 ? as<float>(raw) : as<double>(raw);
        switch (type.size) {
            case 1:
                return type.isSigned ? as<std::int8_t>(raw) : as<std::uint8_t>(raw);
            case 2:
                return type.isSigned ? as<std::int16_t>(raw) : as<std::uint16_t>(raw);
            default:
                return type.isSigned ? as<std::int32_t>(raw) : as<std::uint32_t>(raw);
        }
    }

    std::string_view body_;
    Encoding encoding_;
    std::size_t pos_ = 0;
};

int findProperty(const Element& element, std::string_view name) {
    for (std::size_t i = 0; i < element.properties.size(); ++i)
        if (element.properties[i].name == name)
            return static_cast<int>(i);
    return -1;
}

std::uint8_t toColorChannel(double value, const ScalarType& type) {
    // Float colours are in [0, 1]; integer ones in [0, 255].
    const double scaled = type.isFloat ? std::round(value * 255) : value;
    return static_cast<std::uint8_t>(std::clamp(scaled, 0.0, 255.0));
}

// A list length or vertex index (`what`, a message with the value and
// `limit` after the place): a non-negative integer below `limit`.
long long toIndex(double value, long long limit, const BodyPlace& at, MessageId what) {
    if (!(value >= 0 && value < static_cast<double>(limit)) || value != std::floor(value))
        throw at.error(what, std::to_string(value), limit);
    return static_cast<long long>(value);
}

}  // namespace

TriMesh readPly(std::string_view bytes, const std::string& path,
                std::vector<VertexColor>* vertexColors) {
    const Header header = parseHeader(bytes, path);
    BodyReader body(bytes.substr(header.bodyOffset), header.encoding);
    TriMesh mesh;
    std::vector<VertexColor> colors;
    std::vector<std::vector<int>> polygons;  // checked once the vertex count is known
    bool sawVertices = false;

    for (const Element& element : header.elements) {
        const bool isVertex = element.name == "vertex";
        const bool isFace = element.name == "face";
        std::array<int, 3> xyz{}, rgb{};
        bool hasColor = false;
        int indicesProperty = -1;
        if (isVertex) {
            xyz = {findProperty(element, "x"), findProperty(element, "y"),
                   findProperty(element, "z")};
            if (std::min({xyz[0], xyz[1], xyz[2]}) < 0)
                throw Error(MessageId::PlyNoXyz, path);
            rgb = {findProperty(element, "red"), findProperty(element, "green"),
                   findProperty(element, "blue")};
            hasColor = std::min({rgb[0], rgb[1], rgb[2]}) >= 0;
            if (sawVertices)
                throw Error(MessageId::PlyTwoVertexElements, path);
            sawVertices = true;
        } else if (isFace) {
            indicesProperty = findProperty(element, "vertex_indices");
            if (indicesProperty < 0)
                indicesProperty = findProperty(element, "vertex_index");
            if (indicesProperty < 0 || !element.properties[indicesProperty].isList)
                throw Error(MessageId::PlyNoVertexIndices, path);
        }
        // Each instance takes a minimum size (in ASCII at least a digit and a
        // separator per value); reject impossible counts before allocating for them.
        std::size_t minimumSize = 0;
        for (const Property& p : element.properties)
            minimumSize += !body.isBinary() ? 2 : p.isList ? p.countType.size : p.type.size;
        if (minimumSize > 0 && element.count > (body.remaining() + 1) / minimumSize)
            throw Error(MessageId::PlyElementTooLarge, path, element.name, element.count);
        if (isVertex) {
            mesh.vertices.resize(element.count);
            colors.resize(hasColor ? element.count : 0);
        }
        std::vector<double> values(element.properties.size());
        for (std::size_t i = 0; i < element.count; ++i) {
            const BodyPlace where{path, element.name, i + 1, element.count};
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const Property& p = element.properties[k];
                if (!p.isList) {
                    values[k] = body.read(p.type, where);
                    continue;
                }
                const long long n =
                    toIndex(body.read(p.countType, where), std::numeric_limits<int>::max(), where,
                            MessageId::PlyListLengthOutOfRange);
                if (static_cast<int>(k) != indicesProperty) {
                    for (long long j = 0; j < n; ++j)
                        body.read(p.type, where);
                    continue;
                }
                if (n < 3)
                    throw where.error(MessageId::PlyFaceCorners);
                std::vector<int>& polygon = polygons.emplace_back();
                for (long long j = 0; j < n; ++j)
                    polygon.push_back(static_cast<int>(
                        toIndex(body.read(p.type, where), std::numeric_limits<int>::max(), where,
                                MessageId::PlyVertexIndexOutOfRange)));
            }
            if (isVertex) {
                if (!std::isfinite(values[xyz[0]]) || !std::isfinite(values[xyz[1]]) ||
                    !std::isfinite(values[xyz[2]]))
                    throw where.error(MessageId::PlyCoordinateNotFinite);
                mesh.vertices[i] = Vec3(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
                if (hasColor)
                    for (int c = 0; c < 3; ++c)
                        colors[i][c] =
                            toColorChannel(values[rgb[c]], element.properties[rgb[c]].type);
            }
        }
    }
    if (!sawVertices)
        throw Error(MessageId::PlyNoVertexElement, path);

    for (std::size_t f = 0; f < polygons.size(); ++f) {
        const auto& polygon = polygons[f];
        for (const int index : polygon)
            if (index >= mesh.vertexCount())
                throw Error(MessageId::PlyFaceVertexOutOfRange, path, f + 1, index,
                            mesh.vertexCount());
        // Fan-triangulate around the first corner.
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
            mesh.faces.push_back({polygon[0], polygon[i], polygon[i + 1]});
    }
    if (vertexColors)
        *vertexColors = std::move(colors);
    return mesh;
}

}  // namespace rigmesh
