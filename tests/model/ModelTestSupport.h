// Helpers of the model tests: a QCoreApplication for the whole run, small
// strokes that build quickly, and documents built through commands.
#pragma once

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QTemporaryDir>
#include <cmath>
#include <memory>
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

}  // namespace rigmesh::model::test
