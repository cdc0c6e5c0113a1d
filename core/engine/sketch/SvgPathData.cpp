#include "sketch/SvgPathData.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "sketch/PolygonGeometry.h"
#include "sketch/SvgNumberScanner.h"

namespace rigmesh {

namespace {

class PathFlattener {
  public:
    PathFlattener(std::string_view pathData, int curveSamples)
        : scan_(pathData, "d"), samples_(std::max(1, curveSamples)) {}

    Polyline2 run() {
        char command = 0;
        while (!scan_.atEnd()) {
            if (scan_.nextIsLetter()) {
                command = scan_.letter();
            } else if (command == 0) {
                scan_.fail(MessageId::SvgPathWithoutMoveto);
            }
            // Numbers without a letter repeat the previous command; after a
            // moveto they are implicit lineto commands.
            if (points_.empty() && command != 'M' && command != 'm') {
                scan_.fail(MessageId::SvgPathWithoutMoveto);
            }
            if (!step(command)) {
                break;
            }
            if (command == 'M') {
                command = 'L';
            } else if (command == 'm') {
                command = 'l';
            }
        }
        return points_;
    }

  private:
    // Executes one argument set of `command`; false when the first subpath ended.
    bool step(char command) {
        const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
        const Vec2 origin = relative ? current_ : Vec2(0.0, 0.0);
        const char kind = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
        char previousKind = lastKind_;
        lastKind_ = kind;
        switch (kind) {
            case 'M': {
                if (!points_.empty()) {
                    return false;  // a second subpath: only the first one counts
                }
                current_ = origin + point();
                points_.push_back(current_);
                return true;
            }
            case 'Z':
                return false;
            case 'L':
                lineTo(origin + point());
                return true;
            case 'H':
                lineTo(Vec2(scan_.number() + origin.x(), current_.y()));
                return true;
            case 'V':
                lineTo(Vec2(current_.x(), scan_.number() + origin.y()));
                return true;
            case 'C': {
                const Vec2 c1 = origin + point();
                const Vec2 c2 = origin + point();
                cubicTo(c1, c2, origin + point());
                return true;
            }
            case 'S': {
                // The first control point mirrors the previous cubic's second one.
                const Vec2 c1 = (previousKind == 'C' || previousKind == 'S')
                                    ? Vec2(2.0 * current_ - lastControl_)
                                    : current_;
                const Vec2 c2 = origin + point();
                cubicTo(c1, c2, origin + point());
                return true;
            }
            case 'Q': {
                const Vec2 c = origin + point();
                quadTo(c, origin + point());
                return true;
            }
            case 'T': {
                const Vec2 c = (previousKind == 'Q' || previousKind == 'T')
                                   ? Vec2(2.0 * current_ - lastControl_)
                                   : current_;
                quadTo(c, origin + point());
                return true;
            }
            case 'A': {
                const double rx = scan_.number();
                const double ry = scan_.number();
                const double rotation = scan_.number();
                const bool largeArc = scan_.flag();
                const bool sweep = scan_.flag();
                arcTo(rx, ry, rotation, largeArc, sweep, origin + point());
                return true;
            }
            default:
                scan_.fail(MessageId::SvgUnknownPathCommand, {std::string(1, command)});
        }
    }

    Vec2 point() {
        const double x = scan_.number();
        const double y = scan_.number();
        return {x, y};
    }

    void lineTo(const Vec2& end) {
        points_.push_back(end);
        current_ = end;
    }

    void cubicTo(const Vec2& c1, const Vec2& c2, const Vec2& end) {
        const Vec2 start = current_;
        for (int i = 1; i <= samples_; ++i) {
            const double t = static_cast<double>(i) / samples_;
            const double s = 1.0 - t;
            points_.push_back(s * s * s * start + 3.0 * s * s * t * c1 + 3.0 * s * t * t * c2 +
                              t * t * t * end);
        }
        points_.back() = end;
        lastControl_ = c2;
        current_ = end;
    }

    void quadTo(const Vec2& c, const Vec2& end) {
        const Vec2 start = current_;
        for (int i = 1; i <= samples_; ++i) {
            const double t = static_cast<double>(i) / samples_;
            const double s = 1.0 - t;
            points_.push_back(s * s * start + 2.0 * s * t * c + t * t * end);
        }
        points_.back() = end;
        lastControl_ = c;
        current_ = end;
    }

    // Endpoint-to-centre conversion of SVG 1.1 appendix F.6.5, then sampling.
    void arcTo(double rx, double ry, double rotationDegrees, bool largeArc, bool sweep,
               const Vec2& end) {
        const Vec2 start = current_;
        if (start == end) {
            return;  // the spec omits an arc whose ends coincide
        }
        rx = std::abs(rx);
        ry = std::abs(ry);
        if (rx == 0.0 || ry == 0.0) {
            lineTo(end);
            return;
        }
        const double phi = rotationDegrees * std::numbers::pi / 180.0;
        const double cosPhi = std::cos(phi);
        const double sinPhi = std::sin(phi);
        const Vec2 half = (start - end) / 2.0;
        const Vec2 p(cosPhi * half.x() + sinPhi * half.y(), -sinPhi * half.x() + cosPhi * half.y());
        // Radii too small to reach the end point are scaled up uniformly.
        const double lambda = (p.x() * p.x()) / (rx * rx) + (p.y() * p.y()) / (ry * ry);
        if (lambda > 1.0) {
            rx *= std::sqrt(lambda);
            ry *= std::sqrt(lambda);
        }
        const double numerator =
            rx * rx * ry * ry - rx * rx * p.y() * p.y() - ry * ry * p.x() * p.x();
        const double denominator = rx * rx * p.y() * p.y() + ry * ry * p.x() * p.x();
        double coefficient = std::sqrt(std::max(0.0, numerator / denominator));
        if (largeArc == sweep) {
            coefficient = -coefficient;
        }
        const Vec2 centreP(coefficient * rx * p.y() / ry, -coefficient * ry * p.x() / rx);
        const Vec2 centre = Vec2(cosPhi * centreP.x() - sinPhi * centreP.y(),
                                 sinPhi * centreP.x() + cosPhi * centreP.y()) +
                            (start + end) / 2.0;
        const Vec2 u((p.x() - centreP.x()) / rx, (p.y() - centreP.y()) / ry);
        const Vec2 v((-p.x() - centreP.x()) / rx, (-p.y() - centreP.y()) / ry);
        const double theta1 = turnAngle(Vec2(1.0, 0.0), u);
        double delta = turnAngle(u, v);
        if (!sweep && delta > 0.0) {
            delta -= 2.0 * std::numbers::pi;
        } else if (sweep && delta < 0.0) {
            delta += 2.0 * std::numbers::pi;
        }
        const int count = std::max(
            2, static_cast<int>(std::ceil(samples_ * std::abs(delta) / (std::numbers::pi / 2.0))));
        for (int i = 1; i <= count; ++i) {
            const double angle = theta1 + delta * i / count;
            const Vec2 local(rx * std::cos(angle), ry * std::sin(angle));
            points_.push_back(centre + Vec2(cosPhi * local.x() - sinPhi * local.y(),
                                            sinPhi * local.x() + cosPhi * local.y()));
        }
        points_.back() = end;
        current_ = end;
    }

    SvgNumberScanner scan_;
    int samples_;
    Polyline2 points_;
    Vec2 current_ = Vec2::Zero();
    Vec2 lastControl_ = Vec2::Zero();
    char lastKind_ = 0;
};

}  // namespace

Polyline2 flattenSvgPathData(std::string_view pathData, int curveSamples) {
    return PathFlattener(pathData, curveSamples).run();
}

}  // namespace rigmesh
