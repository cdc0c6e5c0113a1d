#include "surface/SectionGaps.h"

#include <algorithm>

namespace rigmesh {

std::vector<SectionGap> sectionGaps(const CylinderSections& cylinder, double targetEdgeLength,
                                    double ratio) {
    std::vector<SectionGap> gaps;
    const auto& sections = cylinder.sections;
    for (std::size_t i = 1; i < sections.size(); ++i) {
        const CrossSection &a = sections[i - 1], &b = sections[i];
        if (!a.inCap && !b.inCap)
            continue;  // body sections are resampled one spacing apart
        auto spacingOf = [&](const CrossSection& s) {
            return s.spacing > 0 ? s.spacing : targetEdgeLength;
        };
        const double spacing = std::max(spacingOf(a), spacingOf(b));
        const double length = std::max((a.left - b.left).norm(), (a.right - b.right).norm());
        if (!(length > ratio * spacing))
            continue;
        const double from = cylinder.axisPosition[i - 1], to = cylinder.axisPosition[i];
        gaps.push_back({0.5 * (from + to), 0.5 * std::abs(to - from), length});
    }
    return gaps;
}

}  // namespace rigmesh
