#include "sketch/SvgTransform.h"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sketch/SvgNumberScanner.h"

namespace rigmesh {

namespace {

Affine2 fromMatrix(double a, double b, double c, double d, double e, double f) {
    Affine2 m;
    m << a, c, e, b, d, f, 0.0, 0.0, 1.0;
    return m;
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

// The function `name` applied to its `args`; checks how many there are.
Affine2 transformFunction(const std::string& name, const std::vector<double>& args,
                          SvgNumberScanner& scan) {
    const auto count = args.size();
    if (name == "matrix" && count == 6) {
        return fromMatrix(args[0], args[1], args[2], args[3], args[4], args[5]);
    }
    if (name == "translate" && (count == 1 || count == 2)) {
        return fromMatrix(1.0, 0.0, 0.0, 1.0, args[0], count == 2 ? args[1] : 0.0);
    }
    if (name == "scale" && (count == 1 || count == 2)) {
        return fromMatrix(args[0], 0.0, 0.0, count == 2 ? args[1] : args[0], 0.0, 0.0);
    }
    if (name == "rotate" && (count == 1 || count == 3)) {
        const double c = std::cos(radians(args[0]));
        const double s = std::sin(radians(args[0]));
        const Affine2 rotation = fromMatrix(c, s, -s, c, 0.0, 0.0);
        if (count == 1) {
            return rotation;
        }
        // rotate(a, cx, cy) turns about (cx, cy) instead of the origin.
        return fromMatrix(1.0, 0.0, 0.0, 1.0, args[1], args[2]) * rotation *
               fromMatrix(1.0, 0.0, 0.0, 1.0, -args[1], -args[2]);
    }
    if (name == "skewX" && count == 1) {
        return fromMatrix(1.0, 0.0, std::tan(radians(args[0])), 1.0, 0.0, 0.0);
    }
    if (name == "skewY" && count == 1) {
        return fromMatrix(1.0, std::tan(radians(args[0])), 0.0, 1.0, 0.0, 0.0);
    }
    scan.fail(MessageId::SvgUnknownTransform, {name, std::to_string(count)});
}

}  // namespace

Affine2 parseSvgTransform(std::string_view attribute) {
    SvgNumberScanner scan(attribute, "transform");
    Affine2 result = Affine2::Identity();
    while (!scan.atEnd()) {
        const std::string name = scan.word();
        if (!scan.accept('(')) {
            scan.fail(MessageId::SvgTransformWithoutOpening, {name});
        }
        std::vector<double> args;
        while (!scan.accept(')')) {
            if (scan.atEnd()) {
                scan.fail(MessageId::SvgTransformWithoutClosing, {name});
            }
            args.push_back(scan.number());
        }
        // Listed transforms nest: the first one is the outermost.
        result = result * transformFunction(name, args, scan);
    }
    return result;
}

Vec2 applyAffine(const Affine2& transform, const Vec2& p) {
    return transform.topLeftCorner<2, 2>() * p + transform.topRightCorner<2, 1>();
}

}  // namespace rigmesh
