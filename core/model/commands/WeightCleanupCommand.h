// A whole-part weight clean-up (Normalize All, Clean, Limit Total, Smooth
// All) or a recomputation of the weights by bone heat, as
// one undoable step, keeping the part's locked bones; the recipe steps
// normalize_weights, clean_weights, limit_weights, smooth_weights and
// recompute_weights. A clean-up that changes weights marks them painted
// (Part::weightsPainted), so a rebuild asks before discarding them.
#pragma once

#include <QCoreApplication>
#include <memory>

#include "model/commands/SkinningEditCommand.h"
#include "part/WeightCleanup.h"

namespace rigmesh::model {

class WeightCleanupCommand : public SkinningEditCommand {
    Q_DECLARE_TR_FUNCTIONS(WeightCleanupCommand)
  public:
    static std::unique_ptr<WeightCleanupCommand> normalizeAll(Document& document, PartId part);
    static std::unique_ptr<WeightCleanupCommand> clean(Document& document, PartId part,
                                                       double threshold);
    static std::unique_ptr<WeightCleanupCommand> limitTotal(Document& document, PartId part,
                                                            int influences);
    static std::unique_ptr<WeightCleanupCommand> smoothAll(Document& document, PartId part,
                                                           const SmoothAllOptions& options);
    // Bone heat over the whole part again, keeping locked bones (recipe step
    // recompute_weights). The weights are automatic again: not painted.
    static std::unique_ptr<WeightCleanupCommand> recompute(Document& document, PartId part);
    // The same in two halves, for a background job (widgets/jobs): the
    // solve on the part as it is (touches no document), then the command on
    // the GUI thread. Throws Error if the part changed in between.
    struct Recomputed {
        std::shared_ptr<const Part> from;
        std::shared_ptr<const Part> to;
        int changed = 0;
    };
    static Recomputed recomputed(std::shared_ptr<const Part> part);
    static std::unique_ptr<WeightCleanupCommand> fromRecomputed(Document& document, PartId part,
                                                                const Recomputed& result);

  private:
    WeightCleanupCommand(Document& document, PartId part)
        : SkinningEditCommand(document, part, MessageId::CleanupNoSkeleton) {}
    // Runs `edit` on a copy and records the result with its recipe step.
    template <typename Edit>
    void apply(Edit&& edit, nlohmann::json step, const QString& text);
};

}  // namespace rigmesh::model
