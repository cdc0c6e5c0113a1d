#include "mesh/MeshWriter.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <stdexcept>

#include "base/Error.h"
#include "base/StagedFile.h"
#include "mesh/MeshFileFormat.h"

namespace rigmesh {

namespace {

// Shortest decimal form that reads back as exactly the same double (never
// more than max_digits10 significant digits).
void appendNumber(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void appendNumber(std::string& out, int value) {
    char buffer[16];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

// "x y z" followed by a newline.
void appendCoordinateLine(std::string& out, const Vec3& v) {
    appendNumber(out, v.x());
    out += ' ';
    appendNumber(out, v.y());
    out += ' ';
    appendNumber(out, v.z());
    out += '\n';
}

std::string objText(const TriMesh& mesh) {
    std::string out = "# RigMesh Studio\n";
    for (const Vec3& v : mesh.vertices) {
        out += "v ";
        appendCoordinateLine(out, v);
    }
    for (const auto& face : mesh.faces) {
        out += 'f';
        for (const int index : face) {
            out += ' ';
            appendNumber(out, index + 1);  // OBJ counts from 1
        }
        out += '\n';
    }
    return out;
}

std::string offText(const TriMesh& mesh) {
    std::string out = "OFF\n";
    appendNumber(out, mesh.vertexCount());
    out += ' ';
    appendNumber(out, mesh.faceCount());
    out += " 0\n";
    for (const Vec3& v : mesh.vertices) {
        appendCoordinateLine(out, v);
    }
    for (const auto& face : mesh.faces) {
        out += '3';
        for (const int index : face) {
            out += ' ';
            appendNumber(out, index);
        }
        out += '\n';
    }
    return out;
}

// Appends the little-endian bytes of a number.
template <class T>
void appendLittleEndian(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
        std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string plyBytes(const TriMesh& mesh, const std::vector<VertexColor>& colors) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment RigMesh Studio\n";
    out += "element vertex " + std::to_string(mesh.vertexCount()) + "\n";
    out += "property double x\nproperty double y\nproperty double z\n";
    if (!colors.empty())
        out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out += "element face " + std::to_string(mesh.faceCount()) + "\n";
    out += "property list uchar int vertex_indices\nend_header\n";

    const std::size_t vertexBytes = 3 * sizeof(double) + (colors.empty() ? 0 : 3);
    out.reserve(out.size() + mesh.vertices.size() * vertexBytes + mesh.faces.size() * 13);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k)
            appendLittleEndian(out, mesh.vertices[i][k]);
        if (!colors.empty())
            out.append(reinterpret_cast<const char*>(colors[i].data()), 3);
    }
    for (const auto& face : mesh.faces) {
        out += static_cast<char>(3);
        for (const int index : face)
            appendLittleEndian(out, static_cast<std::int32_t>(index));
    }
    return out;
}

void validate(const TriMesh& mesh, const MeshWriteOptions& options) {
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!mesh.vertices[v].allFinite())
            throw Error(MessageId::MeshWriteVertexNotFinite, v);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (const int index : mesh.faces[f])
            if (index < 0 || index >= mesh.vertexCount())
                throw Error(MessageId::MeshWriteFaceMissingVertex, f, index, mesh.vertexCount());
    if (!options.vertexColors.empty() && options.vertexColors.size() != mesh.vertices.size())
        throw std::logic_error(
            "Cannot write the mesh: " + std::to_string(options.vertexColors.size()) +
            " vertex colours given for " + std::to_string(mesh.vertexCount()) + " vertices.");
}

}  // namespace

void writeMesh(const TriMesh& mesh, const std::string& path, const MeshWriteOptions& options) {
    const MeshFileFormat format = meshFileFormatFromPath(path);
    validate(mesh, options);
    switch (format) {
        case MeshFileFormat::Obj:
            writeFileAtomically(path, objText(mesh));
            break;
        case MeshFileFormat::Off:
            writeFileAtomically(path, offText(mesh));
            break;
        case MeshFileFormat::Ply:
            writeFileAtomically(path, plyBytes(mesh, options.vertexColors));
            break;
    }
}

}  // namespace rigmesh
