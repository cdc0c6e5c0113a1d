// What the viewport draws, gathered from the document each frame: plain data,
// so the renderer knows nothing of documents, tools or selection rules.
#pragma once

#include <QMatrix4x4>
#include <QVector3D>
#include <QVector4D>
#include <memory>
#include <vector>

#include "part/Part.h"

namespace rigmesh::widgets {

// How parts are coloured: by their own colour, or by skin
// weights computed on the GPU from the vertex attributes.
enum class WeightView {
    Off,
    SelectedBone,  // the selected bone's weight, Blender's blue-green-red ramp
    DominantBone,  // each vertex in its largest bone's colour
    Influences,    // how many bones weigh the vertex (over 4 flagged)
    // The L1 distance to a fresh global computation (paper Fig. 9a, 15):
    // where merges and cuts left weights the whole part would not have.
    GlobalDifference,
};

struct RenderPart {
    std::shared_ptr<const Part> part;
    QMatrix4x4 model;  // the part's placement in the world
    QVector3D colour{0.72f, 0.75f, 0.82f};
    bool selected = false;
    // The bone whose weights the SelectedBone view shows (its index in
    // part->skeleton.bones()), -1 for none.
    int weightBone = -1;
    // Skinning per bone (order of part->skeleton.bones()): unit dual
    // quaternions (x, y, z, w) and 3x4 matrix rows; empty = the rest pose.
    std::vector<QVector4D> boneReal, boneDual, boneRows;
    // Below 1: drawn translucent, after the opaque parts (onion-skin ghosts).
    float opacity = 1.0f;
    // The GlobalDifference view's per-vertex values (GlobalDifferences);
    // null while they are computed: no difference is shown.
    std::shared_ptr<const std::vector<float>> globalDifference;
};

// Coloured vertices: pairs for GL_LINES, or single points.
struct ColouredVertices {
    std::vector<QVector3D> positions;
    std::vector<QVector3D> colours;
    void add(const QVector3D& p, const QVector3D& c) {
        positions.push_back(p);
        colours.push_back(c);
    }
};

struct RenderScene {
    std::vector<RenderPart> parts;
    // Onion skin: parts in their previous and next keyed poses,
    // translucent, not selectable.
    std::vector<RenderPart> ghosts;
    // Parts drawn see-through over everything else (ViewportTool::
    // partsInFront): translucent, their own nearest faces only.
    std::vector<RenderPart> inFront;
    ColouredVertices lines;   // skeleton bones and other overlays, in pairs
    ColouredVertices points;  // joints
    ColouredVertices stroke;  // the stroke being drawn, as a strip
    bool wireframe = false;
    bool dualQuaternionSkinning = true;
    bool showGrid = true;
    WeightView weightView = WeightView::Off;
    // The grid lies in the plane through gridCentre normal to the world axis
    // gridNormal (1: the ground, y up; an axis view's own plane otherwise),
    // lines gridSpacing apart on world multiples of it, gridLines each side.
    QVector3D gridCentre{0.0f, 0.0f, 0.0f};
    int gridNormal = 1;
    float gridSpacing = 0.1f;
    int gridLines = 20;
};

}  // namespace rigmesh::widgets
