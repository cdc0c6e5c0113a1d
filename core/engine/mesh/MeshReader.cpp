// readMesh (declared in MeshWriter.h): OBJ and OFF parsing and the dispatch by
// extension; PLY lives in PlyReader.cpp.
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include "base/Error.h"
#include "mesh/MeshFileFormat.h"
#include "mesh/MeshTextParsing.h"
#include "mesh/MeshWriter.h"
#include "mesh/PlyReader.h"

namespace rigmesh {

namespace {

using meshtext::LineReader;
using meshtext::toDouble;
using meshtext::toInteger;
using meshtext::tokens;

std::string loadFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("Cannot open '" + path + "': the file does not exist or is not readable.");
    std::ostringstream content;
    content << in.rdbuf();
    if (in.bad())
        throw Error("Cannot read '" + path + "': reading the file failed.");
    return std::move(content).str();
}

// Adds the polygon `corners` as a fan of triangles around its first corner.
void addFan(TriMesh& mesh, const std::vector<int>& corners) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
        mesh.faces.push_back({corners[0], corners[i], corners[i + 1]});
}

std::string atLine(int line) {
    return "line " + std::to_string(line);
}

TriMesh readObj(std::string_view text) {
    TriMesh mesh;
    LineReader lines(text);
    std::string_view line;
    std::vector<int> corners;
    while (lines.next(line)) {
        const auto parts = tokens(line);
        if (parts.empty())
            continue;
        const std::string where = atLine(lines.lineNumber());
        if (parts[0] == "v") {
            // "v x y z [w or colour]": extra values are ignored.
            if (parts.size() < 4)
                throw Error(where + ": a vertex needs three coordinates.");
            mesh.vertices.emplace_back(toDouble(parts[1], where), toDouble(parts[2], where),
                                       toDouble(parts[3], where));
        } else if (parts[0] == "f") {
            if (parts.size() < 4)
                throw Error(where + ": a face needs at least three vertices.");
            corners.clear();
            for (std::size_t i = 1; i < parts.size(); ++i) {
                // "a", "a/t", "a//n" or "a/t/n": only the position index matters.
                const std::string_view corner = parts[i].substr(0, parts[i].find('/'));
                const long long index = toInteger(corner, where);
                // Positive indices count from 1; negative ones back from the last vertex.
                const long long resolved = index > 0 ? index - 1 : mesh.vertexCount() + index;
                if (index == 0 || resolved < 0 || resolved >= mesh.vertexCount())
                    throw Error(where + ": face refers to vertex " + std::string(corner) +
                                " but only " + std::to_string(mesh.vertexCount()) +
                                " vertices are defined before it.");
                corners.push_back(static_cast<int>(resolved));
            }
            addFan(mesh, corners);
        }
        // Normals, texture coordinates, groups, materials and comments are not needed.
    }
    return mesh;
}

// The tokens of the next line that is neither blank nor a comment.
std::vector<std::string_view> nextDataLine(LineReader& lines, const std::string& expected) {
    std::string_view line;
    while (lines.next(line)) {
        line = line.substr(0, line.find('#'));
        auto parts = tokens(line);
        if (!parts.empty())
            return parts;
    }
    throw Error("the file ends early, while expecting " + expected + ".");
}

int toCount(std::string_view token, const std::string& where) {
    const long long value = toInteger(token, where);
    if (value < 0 || value > std::numeric_limits<int>::max())
        throw Error(where + ": invalid count '" + std::string(token) + "'.");
    return static_cast<int>(value);
}

TriMesh readOff(std::string_view text) {
    LineReader lines(text);
    auto header = nextDataLine(lines, "the OFF header");
    if (header[0] != "OFF")
        throw Error("the file does not start with 'OFF'.");
    // The counts may share the header line or follow on the next one.
    header.erase(header.begin());
    if (header.empty())
        header = nextDataLine(lines, "the vertex and face counts");
    const std::string countsWhere = atLine(lines.lineNumber());
    if (header.size() < 2)
        throw Error(countsWhere + ": expected the vertex and face counts.");
    const int vertexCount = toCount(header[0], countsWhere);
    const int faceCount = toCount(header[1], countsWhere);

    TriMesh mesh;
    // Each vertex takes at least 6 bytes of text; never trust the count to reserve more.
    mesh.vertices.reserve(std::min<std::size_t>(vertexCount, text.size() / 6));
    for (int i = 0; i < vertexCount; ++i) {
        const auto parts = nextDataLine(
            lines, "vertex " + std::to_string(i + 1) + " of " + std::to_string(vertexCount));
        const std::string where = atLine(lines.lineNumber());
        if (parts.size() < 3)
            throw Error(where + ": a vertex needs three coordinates.");
        mesh.vertices.emplace_back(toDouble(parts[0], where), toDouble(parts[1], where),
                                   toDouble(parts[2], where));
    }
    std::vector<int> corners;
    for (int i = 0; i < faceCount; ++i) {
        const auto parts = nextDataLine(
            lines, "face " + std::to_string(i + 1) + " of " + std::to_string(faceCount));
        const std::string where = atLine(lines.lineNumber());
        const long long n = toInteger(parts[0], where);
        if (n < 3 || static_cast<long long>(parts.size()) < n + 1)
            throw Error(where +
                        ": a face needs a corner count of at least 3 and that many "
                        "vertex indices.");
        corners.clear();
        for (long long k = 1; k <= n; ++k) {
            const long long index = toInteger(parts[k], where);
            if (index < 0 || index >= vertexCount)
                throw Error(where + ": face refers to vertex " + std::to_string(index) +
                            " but there are " + std::to_string(vertexCount) + " vertices.");
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
    try {
        switch (format) {
            case MeshFileFormat::Obj:
                return readObj(bytes);
            case MeshFileFormat::Off:
                return readOff(bytes);
            case MeshFileFormat::Ply:
                return readPly(bytes, vertexColors);
        }
    } catch (const Error& error) {
        throw Error("Cannot read '" + path + "': " + error.what());
    }
    throw Error("Cannot read '" + path + "': unknown format.");
}

}  // namespace rigmesh
