// One weight paint stroke as one undoable step: its dabs
// (part/WeightPaint.h) painted in order on a copy in create(), so a refused
// dab (locked or unknown bone, bad brush) throws rigmesh::Error and changes
// nothing. The part's locked bones are kept as well as the dabs' own. Undo
// gives the weights back exactly; a stroke that changed weights marks them
// painted (Part::weightsPainted). The recipe step is "paint_weights": one
// dab's "center" and "radius", or a stroke's "dabs".
#pragma once

#include <QCoreApplication>
#include <memory>
#include <vector>

#include "model/commands/SkinningEditCommand.h"
#include "part/WeightPaint.h"

namespace rigmesh::model {

class PaintWeightsCommand : public SkinningEditCommand {
    Q_DECLARE_TR_FUNCTIONS(PaintWeightsCommand)
  public:
    // Dab centres and view directions (WeightDab::towardsViewer) are in
    // document coordinates. Every dab of a stroke shares everything but its
    // centre and radius (Error otherwise); a stroke has at least one dab.
    static std::unique_ptr<PaintWeightsCommand> create(Document& document, PartId part,
                                                       std::vector<WeightDab> dabs);
    static std::unique_ptr<PaintWeightsCommand> create(Document& document, PartId part,
                                                       const WeightDab& dab) {
        return create(document, part, std::vector<WeightDab>{dab});
    }

    // Vertex visits left as they were because every other bone is locked.
    int skippedVertices() const { return skipped_; }
    // Vertex visits left as they were because the part has only one bone.
    int skippedOnlyBone() const { return skippedOnlyBone_; }
    // X-mirror: vertex visits changed on one side only, the vertex having no
    // partner across the mirror plane (DabResult::unpaired).
    int unpairedVertices() const { return unpaired_; }

  private:
    PaintWeightsCommand(Document& document, PartId part)
        : SkinningEditCommand(document, part, MessageId::PaintNoSkeleton) {}
    nlohmann::json step(const std::vector<WeightDab>& dabs) const;

    int skipped_ = 0;
    int skippedOnlyBone_ = 0;
    int unpaired_ = 0;
};

// The recipe's names of brush modes and falloffs ("add", "smooth", ...), and
// back (std::nullopt for an unknown name).
const char* brushModeName(BrushMode mode);
const char* brushFalloffName(BrushFalloff falloff);
std::optional<BrushMode> brushModeNamed(const std::string& name);
std::optional<BrushFalloff> brushFalloffNamed(const std::string& name);

}  // namespace rigmesh::model
