#include "debug/DebugSvg.h"

#include <Eigen/Geometry>
#include <sstream>

namespace rigmesh {
namespace {

// Maps sketch coordinates (y up) to SVG pixels (y down) with a margin.
class Canvas {
  public:
    explicit Canvas(const std::vector<Vec2>& points) {
        for (const Vec2& p : points)
            box_.extend(p);
        double extent = std::max(box_.sizes().maxCoeff(), 1e-300);
        scale_ = 900.0 / extent;
        width_ = box_.sizes().x() * scale_ + 2 * kMargin;
        height_ = box_.sizes().y() * scale_ + 2 * kMargin;
    }
    double x(const Vec2& p) const { return kMargin + (p.x() - box_.min().x()) * scale_; }
    double y(const Vec2& p) const { return kMargin + (box_.max().y() - p.y()) * scale_; }
    double width() const { return width_; }
    double height() const { return height_; }

  private:
    static constexpr double kMargin = 20.0;
    Eigen::AlignedBox2d box_;
    double scale_ = 1, width_ = 0, height_ = 0;
};

const char* fillFor(TriangleKind kind, bool pruned) {
    if (pruned)
        return "#dddddd";
    switch (kind) {
        case TriangleKind::Junction:
            return "#8fd18f";
        case TriangleKind::Terminal:
            return "#f5e29b";
        default:
            return "#ffffff";
    }
}

}  // namespace

std::string debugSvg(const SketchToSurfaceResult& result,
                     const std::vector<DebugOverlay>& overlays) {
    // The regions and sections the surface was built on; the rig's skeleton
    // comes as an overlay.
    const Decomposition& d = result.surfaceRegions ? *result.surfaceRegions : result.decomposition;
    const std::vector<CylinderSections>& cylinders =
        result.surfaceCylinders.empty() ? result.cylinders : result.surfaceCylinders;
    const auto& cdt = d.axis.cdt;
    Canvas canvas(cdt.points);
    std::ostringstream svg;
    auto point = [&](const Vec2& p) { svg << canvas.x(p) << ',' << canvas.y(p) << ' '; };
    auto line = [&](const Vec2& a, const Vec2& b, const char* colour, double width) {
        svg << "<line x1='" << canvas.x(a) << "' y1='" << canvas.y(a) << "' x2='" << canvas.x(b)
            << "' y2='" << canvas.y(b) << "' stroke='" << colour << "' stroke-width='" << width
            << "'/>\n";
    };
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << canvas.width() << "' height='"
        << canvas.height() << "'>\n<rect width='100%' height='100%' fill='white'/>\n";

    svg << "<g id='triangles' stroke='#bbbbbb' stroke-width='0.5'>\n";
    std::vector<int> connectingOf(cdt.triangles.size(), -1);
    for (std::size_t r = 0; r < d.connecting.size(); ++r)
        for (int t : d.connecting[r].triangles)
            connectingOf[t] = static_cast<int>(r);
    for (std::size_t t = 0; t < cdt.triangles.size(); ++t) {
        const char* fill =
            connectingOf[t] >= 0 ? "#8fd18f" : fillFor(d.axis.kind[t], d.axis.pruned[t]);
        svg << "<polygon fill='" << fill << "' points='";
        for (int v : cdt.triangles[t])
            point(cdt.points[v]);
        svg << "'/>\n";
    }
    svg << "</g>\n<g id='cross-sections'>\n";
    for (const auto& cylinder : cylinders)
        for (const auto& s : cylinder.sections)
            line(s.left, s.right, s.inCap ? "#e69500" : "#6fa8dc", 0.8);
    svg << "</g>\n<g id='outline'><polygon fill='none' stroke='black' stroke-width='1.5' points='";
    for (const Vec2& p : cdt.points)
        point(p);
    svg << "'/></g>\n<g id='axis-before-pruning'>\n";
    for (const auto& s : chordalAxisSegments(d.axis, false))
        line(s[0], s[1], "#999999", 1.0);
    svg << "</g>\n<g id='axis-after-pruning'>\n";
    for (const auto& s : chordalAxisSegments(d.axis, true))
        line(s[0], s[1], "#000000", 2.0);
    svg << "</g>\n";
    for (const auto& overlay : overlays) {
        svg << "<g class='overlay'>\n";
        for (const auto& s : overlay.segments)
            line(s[0], s[1], overlay.colour.c_str(), 3.0);
        for (const Vec2& p : overlay.points)
            svg << "<circle cx='" << canvas.x(p) << "' cy='" << canvas.y(p) << "' r='5' fill='"
                << overlay.colour << "'/>\n";
        svg << "</g>\n";
    }
    svg << "<text x='10' y='16' font-family='sans-serif' font-size='13'>green: connecting regions, "
           "yellow: terminal triangles, grey: pruned; black: chordal axis after pruning, grey "
           "lines: "
           "before; blue: cross sections, orange: cap slices</text>\n</svg>\n";
    return svg.str();
}

}  // namespace rigmesh
