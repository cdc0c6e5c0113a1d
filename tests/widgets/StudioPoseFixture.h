// The studio fixture with what the posing tests need: limbs of a skeleton,
// which vertices a pose moved, joint drags on screen, a sketched ellipse and
// the quadruped of tests/data/sketches.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "StudioFixture.h"
#include "pose/PoseHierarchy.h"
#include "pose/Skinning.h"

namespace rigmesh::test {

class StudioPose : public StudioFixture {
  protected:
    // A hand: the leaf joint farthest sideways.
    static JointId sidewaysHand(const Skeleton& skeleton) {
        JointId hand = kNoJoint;
        double side = -1;
        for (const Joint& joint : skeleton.joints())
            if (skeleton.degree(joint.id) == 1 && std::abs(joint.position.x()) > side) {
                side = std::abs(joint.position.x());
                hand = joint.id;
            }
        return hand;
    }
    // The quadruped kept with the tests (tests/data/sketches) as a part,
    // framed: its id.
    model::PartId addQuadruped() {
        const Sketch sketch =
            readSketchFile(std::string(RIGMESH_TEST_DATA) + "/sketches/quadruped.json");
        document()->undoStack()->push(
            model::CreatePartCommand::create(*document(), sketch.points, "quadruped").release());
        viewport()->frameAll();
        return document()->parts().front().id;
    }
    // The joint below the nearest junction (or the root) on the way up from
    // `joint`: the first joint a limb drag of `joint` moves.
    static JointId limbTop(const Skeleton& skeleton, JointId joint) {
        const PoseHierarchy h(skeleton);
        int top = h.indexOf(joint);
        while (h.parent(h.parent(top)) >= 0 && h.children(h.parent(top)).size() == 1)
            top = h.parent(top);
        return h.jointId(top);
    }
    // Bone ids of the subtree below `joint`, the bone ending at it
    // included: every bone a turn of that bone moves.
    static std::set<BoneId> bonesFrom(const Skeleton& skeleton, JointId joint) {
        const PoseHierarchy h(skeleton);
        std::vector<bool> below(h.jointCount(), false);
        for (int j : h.parentFirstOrder())
            below[j] = h.jointId(j) == joint || (h.parent(j) >= 0 && below[h.parent(j)]);
        std::set<BoneId> bones;
        for (int b = 0; b < h.boneCount(); ++b)
            if (below[h.boneTailJoint(b)])
                bones.insert(skeleton.bones()[b].id);
        return bones;
    }
    // How many of the vertices weighted only by bones outside `moving` moved
    // from the rest shape in the part's current pose; `checked` counts them.
    int movedOutside(model::PartId id, const std::set<BoneId>& moving, int& checked) const {
        const model::PartNode& node = document()->part(id);
        const std::vector<Vec3> posed = posePart(*node.part, node.pose).mesh.vertices;
        int moved = 0;
        checked = 0;
        for (std::size_t v = 0; v < posed.size(); ++v) {
            bool outside = true;
            for (const auto& [bone, w] : node.part->weights.perVertex[v])
                outside = outside && !moving.contains(bone);
            if (!outside)
                continue;
            ++checked;
            moved += (posed[v] - node.part->mesh.vertices[v]).norm() > 1e-9 ? 1 : 0;
        }
        return moved;
    }
    // A screen drag of `joint` by (dx, dy) pixels in ten steps.
    void dragJointBy(model::PartId id, JointId joint, double dx, double dy,
                     Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        const QVector3D at = viewport()->camera().project(viewport()->jointWorldPosition(id, joint),
                                                          QSizeF(viewport()->size()));
        std::vector<QPointF> path;
        for (int i = 0; i <= 10; ++i)
            path.emplace_back(at.x() + dx * i / 10, at.y() + dy * i / 10);
        drag(viewport(), path, modifiers);
    }
    // Sketches a long ellipse across the viewport: the new part's id.
    model::PartId sketchEllipse() {
        window->activateTool<widgets::SketchTool>();
        const QPointF centre(viewport()->width() / 2.0, viewport()->height() / 2.0);
        drag(viewport(), ellipseStroke(centre, 260, 50));
        EXPECT_EQ(document()->partCount(), 1);
        return document()->partCount() > 0 ? document()->parts().front().id : model::kNoPart;
    }
};

}  // namespace rigmesh::test
