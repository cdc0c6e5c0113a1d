// The camel of the shipped recipe (resources/recipes/camel.json, the paper's
// Fig. 10 session) at its last step: the body after the legs and the neck,
// the head in the body's frame and the recipe's merge of the two, run once
// per program with the model's recipe runner; and the finished camel that
// merge gives (what bench_merge cuts and edits). For targets that link
// rigmesh_model and define RIGMESH_RESOURCES.
#pragma once

#include <QString>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "merge/MergeParts.h"
#include "model/Document.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeRunner.h"

namespace rigmesh::testsupport {

struct CamelLastMerge {
    Part body;  // after the legs and the neck
    Part head;  // in the body's frame
    MergeRequest request;
};

inline const CamelLastMerge& lastCamelMerge() {
    static const CamelLastMerge merge = [] {
        const std::string path = std::string(RIGMESH_RESOURCES) + "/recipes/camel.json";
        const nlohmann::json recipe = model::readRecipeFile(path);
        model::Document document;
        model::RecipeRunner runner(document, std::string(RIGMESH_RESOURCES) + "/recipes");
        const nlohmann::json& steps = model::recipeSteps(recipe);
        int number = 0;
        nlohmann::json lastStep;
        for (const nlohmann::json& step : steps) {
            if (step["command"] == "merge" && step["part"] == "head") {
                lastStep = step;
                break;
            }
            runner.apply(step, ++number);
        }
        CamelLastMerge m;
        const model::PartNode& body = document.parts()[0];
        m.body = *body.part;
        const model::PartNode* head = nullptr;
        for (const model::PartNode& node : document.parts())
            if (node.name == QStringLiteral("head"))
                head = &node;
        m.head = *head->part;
        const Vec3 offset = head->placement.translation - body.placement.translation;
        for (Vec3& p : m.head.mesh.vertices)
            p += offset;
        for (const Joint& joint : std::vector<Joint>(m.head.skeleton.joints()))
            m.head.skeleton.setJointPosition(joint.id, joint.position + offset);
        // The recipe's joints: the head's back joint onto the neck's top one.
        m.request.join.mode = MergeMode::Snap;
        m.request.join.draggedJoint =
            lastStep["joint"].is_number() ? lastStep["joint"].get<JointId>() : 1;
        m.request.join.targetJoint =
            lastStep["target"].is_number() ? lastStep["target"].get<JointId>() : 11;
        m.request.edgeLength = body.options.targetEdgeLength;
        return m;
    }();
    return merge;
}

// The finished camel (about 11k vertices): the last merge's part.
inline const Part& finishedCamel() {
    static const Part camel =
        mergeParts(lastCamelMerge().body, lastCamelMerge().head, lastCamelMerge().request).part;
    return camel;
}

}  // namespace rigmesh::testsupport
