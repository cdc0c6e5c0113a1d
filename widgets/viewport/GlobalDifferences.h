// The "Difference from Global Weights" view's data (the paper's Fig. 9a /
// 15): per vertex, the L1 distance between a part's weights and what
// section 2.4 would give on the whole part now. That is a whole-part bone
// heat solve, seconds on a large part, so it runs on a worker thread the
// first time a part is shown this way (the GUI never freezes); until
// it is ready the view shows no difference and `ready` repaints it.
#pragma once

#include <QObject>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "part/Part.h"

namespace rigmesh::widgets {

class GlobalDifferences : public QObject {
    Q_OBJECT
  public:
    using Values = std::shared_ptr<const std::vector<float>>;
    explicit GlobalDifferences(QObject* parent = nullptr) : QObject(parent) {}

    // The part's differences, or null while they are computed (the first
    // ask starts the computation). A part is an immutable value: a new
    // shared part (any edit) gets new differences.
    Values of(const std::shared_ptr<const Part>& part);
    // True while any computation runs (tests wait on it).
    bool pending() const { return !computing_.empty(); }

    // Per vertex: the L1 distance from a fresh global computation (0 where
    // there is none, e.g. a part without a skeleton).
    static std::vector<float> compute(const Part& part);

  signals:
    void ready();

  private:
    struct Entry {
        std::weak_ptr<const Part> part;
        Values values;
    };
    std::map<const Part*, Entry> entries_;
    std::set<const Part*> computing_;
};

}  // namespace rigmesh::widgets
