#include "viewport/GlobalDifferences.h"

#include <QCoreApplication>
#include <QPointer>
#include <thread>

#include "base/Error.h"
#include "merge/MergeParts.h"
#include "rig/LocalBoneHeat.h"

namespace rigmesh::widgets {

std::vector<float> GlobalDifferences::compute(const Part& part) {
    std::vector<float> out(part.mesh.vertices.size(), 0.0f);
    if (part.skeleton.boneCount() == 0)
        return out;
    try {
        const WeightsById global = recomputeWeightsGlobally(part.mesh, part.skeleton);
        const std::vector<double> d = weightDifferences(part.weights.perVertex, global);
        for (std::size_t v = 0; v < d.size() && v < out.size(); ++v)
            out[v] = static_cast<float>(d[v]);
    } catch (const Error&) {
        // No global solution to compare with: the view shows no difference.
    }
    return out;
}

GlobalDifferences::Values GlobalDifferences::of(const std::shared_ptr<const Part>& part) {
    if (!part)
        return nullptr;
    // Forget parts nobody holds any more (their address may come back).
    std::erase_if(entries_, [](const auto& entry) { return entry.second.part.expired(); });
    const auto found = entries_.find(part.get());
    if (found != entries_.end() && found->second.part.lock() == part)
        return found->second.values;
    if (computing_.contains(part.get()))
        return nullptr;
    computing_.insert(part.get());
    QPointer<GlobalDifferences> self(this);
    std::thread([self, part] {
        auto values = std::make_shared<const std::vector<float>>(compute(*part));
        const std::weak_ptr<const Part> weak = part;
        const Part* key = part.get();
        QCoreApplication* app = QCoreApplication::instance();
        if (!app)
            return;
        // Back on the GUI thread (the application object lives there).
        QMetaObject::invokeMethod(
            app,
            [self, weak, key, values] {
                if (!self)
                    return;
                self->computing_.erase(key);
                if (!weak.expired())
                    self->entries_[key] = Entry{weak, values};
                emit self->ready();
            },
            Qt::QueuedConnection);
    }).detach();
    return nullptr;
}

}  // namespace rigmesh::widgets
