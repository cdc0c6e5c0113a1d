// readMesh (declared in MeshWriter.h): OBJ and OFF parsing and the dispatch by
// extension; PLY lives in PlyReader.cpp.
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "base/Error.h"
#include "mesh/MeshFileFormat.h"
#include "mesh/MeshTextParsing.h"
#include "mesh/MeshWriter.h"
#include "mesh/PlyReader.h"

namespace rigmesh {

namespace {

using meshtext::LineReader;
using meshtext::tokens;

std::string loadFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(MessageId::MeshFileCannotOpen, path);
    std::ostringstream content;
    content << in.rdbuf();
    if (in.bad())
        throw Error(MessageId::MeshFileReadFailed, path);
    return std::move(content).str();
}

// Adds the polygon `corners` as a fan of triangles around its first corner.
void addFan(TriMesh& mesh, const std::vector<int>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
        mesh.faces.push_back({corners[0], corners[i], corners[i + 1]});
}

// A line of an OBJ or OFF file, to read numbers from and to name in messages.
struct TextLine {
    const std::string& path;
    int number = 0;

    double toDouble(std::string_view token) const {
        if (const auto value = meshtext::toDouble(token))
            return *value;
        throw Error(MessageId::MeshLineNotANumber, path, number, std::string(token));
    }
    long long toInteger(std::string_view token) const {
        if (const auto value = meshtext::toInteger(token))
            return *value;
        throw Error(MessageId::MeshLineNotAnInteger, path, number, std::string(token));
    }
    Vec3 toPoint(const std::vector<std::string_view>& parts, std::size_t first) const {
        return {toDouble(parts[first]), toDouble(parts[first + 1]), toDouble(parts[first + 2])};
    }
};

TriMesh readObj(std::string_view text, const std::string& path) {
    TriMesh mesh;
    LineReader lines(text);
    std::string_view line;
    std::vector<int> corners;
    while (lines.next(line)) {
        const auto parts = tokens(line);
        if (parts.empty())
            continue;
        const TextLine at{path, lines.lineNumber()};
        if (parts[0] == "v") {
            // "v x y z [w or colour]": extra values are ignored.
            if (parts.size() < 4)
                throw Error(MessageId::MeshLineVertexCoordinates, path, at.number);
            mesh.vertices.push_back(at.toPoint(parts, 1));
        } else if (parts[0] == "f") {
            if (parts.size() < 4)
                throw Error(MessageId::MeshLineFaceCorners, path, at.number);
            corners.clear();
            for (std::size_t i = 1; i < parts.size(); ++i) {
                // "a", "a/t", "a//n" or "a/t/n": only the position index matters.
                const std::string_view corner = parts[i].substr(0, parts[i].find('/'));
                const long long index = at.toInteger(corner);
                // Positive indices count from 1; negative ones back from the last vertex.
                const long long resolved = index > 0 ? index - 1 : mesh.vertexCount() + index;
                if (index == 0 || resolved < 0 || resolved >= mesh.vertexCount())
                    throw Error(MessageId::ObjFaceVertexUndefined, path, at.number,
                                std::string(corner), mesh.vertexCount());
                corners.push_back(static_cast<int>(resolved));
            }
            addFan(mesh, corners);
        }
        // Normals, texture coordinates, groups, materials and comments are not needed.
    }
    return mesh;
}

// The tokens of the next line that is neither blank nor a comment; at the
// end of the file, the Error `endsEarly()` makes is thrown (made only then:
// this runs once per vertex).
template <class EndsEarly>
std::vector<std::string_view> nextDataLine(LineReader& lines, const EndsEarly& endsEarly) {
    std::string_view line;
    while (lines.next(line)) {
        line = line.substr(0, line.find('#'));
        auto parts = tokens(line);
        if (!parts.empty())
            return parts;
    }
    throw endsEarly();
}

int toCount(std::string_view token, const TextLine& at) {
    const long long value = at.toInteger(token);
    if (value < 0 || value > std::numeric_limits<int>::max())
        throw Error(MessageId::MeshLineInvalidCount, at.path, at.number, std::string(token));
    return static_cast<int>(value);
}

TriMesh readOff(std::string_view text, const std::string& path) {
    LineReader lines(text);
    auto header = nextDataLine(lines, [&] { return Error(MessageId::OffEndsBeforeHeader, path); });
    if (header[0] != "OFF")
        throw Error(MessageId::OffNoHeader, path);
    // The counts may share the header line or follow on the next one.
    header.erase(header.begin());
    if (header.empty())
        header = nextDataLine(lines, [&] { return Error(MessageId::OffEndsBeforeCounts, path); });
    const TextLine countsAt{path, lines.lineNumber()};
    if (header.size() < 2)
        throw Error(MessageId::OffNoCounts, path, countsAt.number);
    const int vertexCount = toCount(header[0], countsAt);
    const int faceCount = toCount(header[1], countsAt);

    TriMesh mesh;
    // Each vertex takes at least 6 bytes of text; never trust the count to reserve more.
    mesh.vertices.reserve(std::min<std::size_t>(vertexCount, text.size() / 6));
    for (int i = 0; i < vertexCount; ++i) {
        const auto parts = nextDataLine(
            lines, [&] { return Error(MessageId::OffEndsBeforeVertex, path, i + 1, vertexCount); });
        const TextLine at{path, lines.lineNumber()};
        if (parts.size() < 3)
            throw Error(MessageId::MeshLineVertexCoordinates, path, at.number);
        mesh.vertices.push_back(at.toPoint(parts, 0));
    }
    std::vector<int> corners;
    for (int i = 0; i < faceCount; ++i) {
        const auto parts = nextDataLine(
            lines, [&] { return Error(MessageId::OffEndsBeforeFace, path, i + 1, faceCount); });
        const TextLine at{path, lines.lineNumber()};
        const long long n = at.toInteger(parts[0]);
        if (n < 3 || static_cast<long long>(parts.size()) < n + 1)
            throw Error(MessageId::OffFaceCornerCount, path, at.number);
        corners.clear();
        for (long long k = 1; k <= n; ++k) {
            const long long index = at.toInteger(parts[k]);
            if (index < 0 || index >= vertexCount)
                throw Error(MessageId::OffFaceVertexOutOfRange, path, at.number, index,
                            vertexCount);
            corners.push_back(static_cast<int>(index));
        }
        addFan(mesh, corners);  // any colour after the indices is ignored
    }
    return mesh;
}

}  // namespace

TriMesh readMesh(const std::string& path, std::vector<VertexColor>* vertexColors) {
    const MeshFileFormat format = meshFileFormatFromPath(path);
    const std::string bytes = loadFile(path);
    if (vertexColors)
        vertexColors->clear();
    switch (format) {
        case MeshFileFormat::Obj:
            return readObj(bytes, path);
        case MeshFileFormat::Off:
            return readOff(bytes, path);
        case MeshFileFormat::Ply:
            return readPly(bytes, path, vertexColors);
    }
    throw std::logic_error("readMesh: a mesh file format without a reader");
}

}  // namespace rigmesh
