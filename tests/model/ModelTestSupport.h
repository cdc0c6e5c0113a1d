// Helpers of the model tests: a QCoreApplication for the whole run, small
// strokes that build quickly, and documents built through commands.
#pragma once

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <cmath>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "base/Types.h"
#include "model/Document.h"
#include "model/DocumentFile.h"
#include "model/commands/CreatePartCommand.h"
#include "sketch/Sketch.h"

namespace rigmesh::model::test {

// Counter-clockwise ellipse stroke.
inline std::vector<Vec2> ellipseStroke(double a, double b, int count = 48,
                                       const Vec2& centre = Vec2::Zero()) {
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        const double t = 2.0 * std::numbers::pi * i / count;
        points.push_back(centre + Vec2(a * std::cos(t), b * std::sin(t)));
    }
    return points;
}

inline std::vector<Vec2> sharedStroke(const std::string& name) {
    return readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json").points;
}

// The strokes random sequences draw from: two ellipses and shared sketches.
inline const std::vector<std::vector<Vec2>>& testStrokes() {
    static const std::vector<std::vector<Vec2>> strokes = {
        ellipseStroke(1.0, 0.35),
        ellipseStroke(0.6, 0.25, 40, Vec2(0.3, -0.2)),
        sharedStroke("tube"),
        sharedStroke("y_branch"),
    };
    return strokes;
}

// A stroke the engine rejects (too few points).
inline std::vector<Vec2> badStroke() {
    return {Vec2(0, 0), Vec2(1, 0)};
}

inline PartId addPart(Document& document, const std::vector<Vec2>& stroke,
                      const QString& name = {}) {
    auto command = CreatePartCommand::create(document, stroke, name);
    const PartId id = command->partId();
    document.undoStack()->push(command.release());
    return id;
}

inline QByteArray bytesOf(const Document& document) {
    return DocumentFile::toBytes(document);
}

// A .rigmesh file's JSON tree: CBOR after the 3-byte self-describe tag.
inline nlohmann::json documentJson(const QByteArray& bytes) {
    return nlohmann::json::from_cbor(std::vector<std::uint8_t>(bytes.begin() + 3, bytes.end()));
}

// The file of a JSON tree: the self-describe tag, then CBOR.
inline QByteArray documentBytes(const nlohmann::json& root) {
    std::vector<std::uint8_t> out = {0xD9, 0xD9, 0xF7};
    nlohmann::json::to_cbor(root, out);
    return QByteArray(reinterpret_cast<const char*>(out.data()),
                      static_cast<qsizetype>(out.size()));
}

// Loading `bytes` fails with a DocumentFileError mentioning `fragment`.
inline void expectRejected(const QByteArray& bytes, const std::string& fragment) {
    try {
        DocumentFile::fromBytes(bytes);
        ADD_FAILURE() << "accepted a file that should fail with \"" << fragment << "\"";
    } catch (const DocumentFileError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

}  // namespace rigmesh::model::test
