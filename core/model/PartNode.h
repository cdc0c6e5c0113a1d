// One part of a document: the immutable engine value plus what the document
// adds around it (stable id, user name, placement, visibility, and the raw
// stroke and options it was built from, so it can be rebuilt).
#pragma once

#include <Eigen/Geometry>
#include <QString>
#include <cstdint>
#include <memory>
#include <vector>

#include "base/Types.h"
#include "part/Part.h"

namespace rigmesh::model {

// Stable part id: assigned once, never changed. Ids start at 1.
using PartId = std::uint32_t;
inline constexpr PartId kNoPart = 0;

// The user-facing build options of a part (what the properties panel edits).
struct BuildOptions {
    double targetEdgeLength = 0.0;  // 0 = automatic (the cleaned outline's spacing)
    bool smoothing = true;          // Least-Squares Meshes smoothing of the surface

    friend bool operator==(const BuildOptions&, const BuildOptions&) = default;
};

// Where a part sits in the scene: p_world = rotation * p_part + translation.
struct Placement {
    Vec3 translation = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();

    friend bool operator==(const Placement& a, const Placement& b) {
        return a.translation == b.translation && a.rotation.coeffs() == b.rotation.coeffs();
    }
};

struct PartNode {
    PartId id = kNoPart;
    QString name;
    // Never mutated once shared: edits build a new Part and swap the pointer.
    std::shared_ptr<const Part> part;
    std::vector<Vec2> stroke;  // the raw sketch, as drawn
    BuildOptions options;
    Placement placement;
    bool visible = true;
};

}  // namespace rigmesh::model
