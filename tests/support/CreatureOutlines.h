// A seeded family of creature outlines as people draw them, for the surface
// figures: the shapes the shared sketches leave out, each class with the
// feature that once creased or stepped the surface.
//
//  - legs: bipeds and quadrupeds whose legs stand close together, the gap
//    at the crotch down to 1.5 outline spacings (the cleaner's spacing,
//    1/60 of the bounding box's diagonal);
//  - stubs: big bodies with short stubby limbs 0.3 to 1.0 of the body's
//    thickness long (the ones the chordal axis prunes), and a tail or neck;
//  - fingers: a hand whose fingers have narrow gaps, with a thumb;
//  - tentacles: tapering, curling limbs fanning from one body;
//  - angles: limbs meeting an elongated body at 20 to 160 degrees.
//
// Each outline is drawn as a stroke in one of three manners: steadily
// (points a third of a spacing apart), fast (sparse points 1.2 to 3 spacings
// apart, the end short of or past the start) or slowly (dense points with a
// slow wobble and a tremor). Shapes are randomly turned, scaled and placed.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ImplicitOutline.h"

namespace rigmesh::testsupport {

enum class CreatureClass { Legs, Stubs, Fingers, Tentacles, Angles };
enum class StrokeManner { Steady, Fast, Slow };

inline constexpr std::array<CreatureClass, 5> kCreatureClasses{
    CreatureClass::Legs, CreatureClass::Stubs, CreatureClass::Fingers, CreatureClass::Tentacles,
    CreatureClass::Angles};

inline std::string creatureClassName(CreatureClass c) {
    switch (c) {
        case CreatureClass::Legs:
            return "legs";
        case CreatureClass::Stubs:
            return "stubs";
        case CreatureClass::Fingers:
            return "fingers";
        case CreatureClass::Tentacles:
            return "tentacles";
        case CreatureClass::Angles:
            return "angles";
    }
    return "?";
}

// The enumerator's name, as C++ spells it.
inline std::string creatureClassTypeName(CreatureClass c) {
    std::string name = creatureClassName(c);
    name[0] = static_cast<char>(name[0] - 'a' + 'A');
    return name;
}

inline std::string strokeMannerName(StrokeManner m) {
    return m == StrokeManner::Steady ? "steady" : m == StrokeManner::Fast ? "fast" : "slow";
}

// A short limb of the stubs class: where it leaves the body and its tip
// (in the outline's final coordinates), for checking what became of it.
struct Stub {
    Vec2 base, tip;
    double length = 0;     // beyond the body's outline
    double thickness = 0;  // of the body it sits on
};

struct CreatureOutline {
    CreatureClass shapeClass = CreatureClass::Legs;
    StrokeManner manner = StrokeManner::Steady;
    int seed = 0;
    std::vector<Vec2> stroke;  // as drawn
    std::vector<Stub> stubs;   // the stubs class only
};

namespace creature {

class Dice {
  public:
    explicit Dice(std::uint32_t seed) : random_(seed) {}
    double uniform(double low, double high) {
        return std::uniform_real_distribution<double>(low, high)(random_);
    }
    int integer(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(random_);
    }
    bool chance(double p) { return uniform(0, 1) < p; }
    double normal() { return std::normal_distribution<double>(0, 1)(random_); }

  private:
    std::mt19937 random_;
};

inline Vec2 direction(double angle) {
    return {std::cos(angle), std::sin(angle)};
}

// A tube from `base` heading `angle`, `length` long, turning `bend` radians
// in all (evenly along it), its radius running from r0 to r1.
inline TubeShape limb(const Vec2& base, double angle, double length, double r0, double r1,
                      double bend = 0.0) {
    TubeShape tube;
    constexpr int kPieces = 8;
    Vec2 p = base;
    tube.path.push_back(p);
    tube.radius.push_back(r0);
    for (int k = 1; k <= kPieces; ++k) {
        const double heading = angle + bend * (k - 0.5) / kPieces;
        p += (length / kPieces) * direction(heading);
        tube.path.push_back(p);
        tube.radius.push_back(r0 + (r1 - r0) * k / kPieces);
    }
    return tube;
}

// The outline's spacing as the cleaner will choose it (1/60 of the diagonal).
inline double spacingOf(const ShapeUnion& shape) {
    return shape.box().sizes().norm() / 60.0;
}

// Point of an ellipse at parameter t, and its outward normal's angle.
inline Vec2 ellipsePoint(const EllipseShape& e, double t) {
    const Vec2 local(e.a * std::cos(t), e.b * std::sin(t));
    const double c = std::cos(e.angle), s = std::sin(e.angle);
    return e.centre + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}
inline double ellipseNormalAngle(const EllipseShape& e, double t) {
    return e.angle + std::atan2(e.a * std::sin(t), e.b * std::cos(t));
}

// An ellipse parameter of either sign, |t| in [low, high], at least `apart`
// from every one in `used` if twenty tries find one; added to `used`.
inline double placeApart(Dice& dice, std::vector<double>& used, double low, double high,
                         double apart) {
    double t = 0;
    for (int attempt = 0; attempt < 20; ++attempt) {
        t = (dice.chance(0.5) ? 1 : -1) * dice.uniform(low, high);
        if (std::none_of(used.begin(), used.end(),
                         [&](double u) { return std::abs(u - t) < apart; }))
            break;
    }
    used.push_back(t);
    return t;
}

// Legs close together: one pair (a biped, with arms and a head sometimes)
// or two (a quadruped, with a neck and head, a tail sometimes). The gap
// between the legs of a pair is `gap` spacings where they leave the body.
inline ShapeUnion legs(Dice& dice) {
    const bool quadruped = dice.chance(0.5);
    EllipseShape body{Vec2::Zero(), dice.uniform(0.9, 1.6), dice.uniform(0.45, 0.8), 0.0};
    if (!quadruped)
        std::swap(body.a, body.b);
    const double gapSpacings = dice.uniform(1.5, 4.0);
    const double length = dice.uniform(0.7, 1.8);
    const double radius = dice.uniform(0.1, 0.22) * (quadruped ? 1.0 : 1.3);
    const double splay = dice.uniform(0.0, 0.15);
    std::vector<double> pairs =
        quadruped ? std::vector<double>{-0.6 * body.a, 0.6 * body.a} : std::vector<double>{0.0};
    ShapeUnion shape;
    shape.bodies.push_back(body);
    if (quadruped) {
        const double neck = dice.uniform(0.6, 1.4);
        shape.limbs.push_back(limb(ellipsePoint(body, 0.3), dice.uniform(0.4, 1.2), neck,
                                   dice.uniform(0.15, 0.3), dice.uniform(0.12, 0.2)));
        shape.bodies.push_back({shape.limbs.back().path.back(), dice.uniform(0.25, 0.45),
                                dice.uniform(0.18, 0.3), dice.uniform(-0.5, 0.5)});
        if (dice.chance(0.6))
            shape.limbs.push_back(limb(ellipsePoint(body, std::numbers::pi - 0.1),
                                       std::numbers::pi - dice.uniform(-0.6, 0.8),
                                       dice.uniform(0.5, 1.5), 0.08, 0.03, dice.uniform(-1, 1)));
    } else {
        shape.bodies.push_back({Vec2(0, body.b + dice.uniform(0.2, 0.4)), dice.uniform(0.3, 0.45),
                                dice.uniform(0.3, 0.5), 0.0});
        if (dice.chance(0.7))
            for (double side : {-1.0, 1.0}) {
                const double t = std::numbers::pi / 2 - side * dice.uniform(1.0, 1.3);
                shape.limbs.push_back(limb(ellipsePoint(body, t) - Vec2(side * 0.1, 0),
                                           std::numbers::pi / 2 - side * dice.uniform(1.8, 2.6),
                                           dice.uniform(0.8, 1.6), 0.12, 0.08));
            }
    }
    // The legs' positions depend on the spacing, which depends on the extent.
    const std::size_t fixedLimbs = shape.limbs.size();
    for (int pass = 0; pass < 3; ++pass) {
        shape.limbs.resize(fixedLimbs);
        const double gap = gapSpacings * spacingOf(shape);
        for (double x : pairs)
            for (double side : {-1.0, 1.0}) {
                const Vec2 base(x + side * (radius + 0.5 * gap), 0.0);
                shape.limbs.push_back(limb(base, -std::numbers::pi / 2 + side * splay,
                                           body.b + length, radius, radius * 0.85));
            }
    }
    return shape;
}

// A big body with stubs 0.3 to 1.0 of its thickness long, and often a tail
// or neck; `stubs` gets each stub's base and tip.
inline ShapeUnion stubs(Dice& dice, std::vector<Stub>& stubs) {
    EllipseShape body{Vec2::Zero(), dice.uniform(1.2, 2.0), dice.uniform(0.6, 1.0), 0.0};
    ShapeUnion shape;
    shape.bodies.push_back(body);
    if (dice.chance(0.6))
        shape.limbs.push_back(limb(ellipsePoint(body, std::numbers::pi), std::numbers::pi,
                                   dice.uniform(1.0, 2.5), dice.uniform(0.25, 0.45),
                                   dice.uniform(0.04, 0.12), dice.uniform(-0.8, 0.8)));
    if (dice.chance(0.4))
        shape.limbs.push_back(limb(ellipsePoint(body, 0.25), dice.uniform(0.3, 0.9),
                                   dice.uniform(0.8, 1.5), dice.uniform(0.2, 0.3),
                                   dice.uniform(0.15, 0.25)));
    const int count = dice.integer(1, 3);
    const double thickness = 2 * body.b;
    std::vector<double> used;
    for (int k = 0; k < count; ++k) {
        // Along the top or the bottom, away from the tail end and the other stubs.
        const double t = placeApart(dice, used, 0.7, 2.4, 0.6);
        const double length = dice.uniform(0.3, 1.0) * thickness;
        // As wide as long or so: the chordal axis prunes a limb whose outline
        // stays within the circle on its base (Teddy's test, paper 2.1).
        const double radius = std::min(0.5 * thickness, dice.uniform(0.6, 1.4) * length);
        const double angle = ellipseNormalAngle(body, t) + dice.uniform(-0.6, 0.6);
        const Vec2 edge = ellipsePoint(body, t);
        const Vec2 base = edge - radius * direction(angle);
        const double tipRadius = radius * dice.uniform(0.7, 1.0);
        // Reaching `length` beyond the body's outline, its round tip included.
        shape.limbs.push_back(limb(base, angle, radius + length - tipRadius, radius, tipRadius));
        stubs.push_back(
            {edge,
             shape.limbs.back().path.back() + shape.limbs.back().radius.back() * direction(angle),
             length, thickness});
    }
    return shape;
}

// A hand: a palm, a wrist, three to five fingers with gaps of 1.5 to 3
// spacings where they leave the palm, fanning a little, and a thumb.
inline ShapeUnion fingers(Dice& dice) {
    EllipseShape palm{Vec2::Zero(), dice.uniform(0.5, 0.7), dice.uniform(0.55, 0.8), 0.0};
    const int count = dice.integer(3, 5);
    const double radius = dice.uniform(0.04, 0.08) * (5.0 / (count + 1.0)) * 1.4;
    const double gapSpacings = dice.uniform(1.5, 3.0);
    const double fan = dice.uniform(0.0, 0.12);
    std::vector<double> lengths, bends;
    for (int k = 0; k < count; ++k) {
        lengths.push_back(dice.uniform(0.6, 1.2) * palm.b);
        bends.push_back(dice.uniform(-0.25, 0.25));
    }
    ShapeUnion shape;
    shape.bodies.push_back(palm);
    shape.limbs.push_back(limb(Vec2(0, -0.5 * palm.b), -std::numbers::pi / 2,
                               dice.uniform(0.8, 1.4), 0.7 * palm.a, 0.6 * palm.a));
    const double thumbSide = dice.chance(0.5) ? 1.0 : -1.0;
    shape.limbs.push_back(limb(Vec2(thumbSide * 0.5 * palm.a, -0.1 * palm.b),
                               std::numbers::pi / 2 - thumbSide * dice.uniform(0.5, 1.2),
                               dice.uniform(0.5, 0.8), 1.25 * radius, 1.1 * radius,
                               thumbSide * dice.uniform(0.0, 0.4)));
    const std::size_t fixedLimbs = shape.limbs.size();
    for (int pass = 0; pass < 3; ++pass) {
        shape.limbs.resize(fixedLimbs);
        const double gap = gapSpacings * spacingOf(shape);
        const double span = count * 2 * radius + (count - 1) * gap;
        for (int k = 0; k < count; ++k) {
            const double x = -0.5 * span + radius + k * (2 * radius + gap);
            const double y = palm.b * std::sqrt(std::max(0.0, 1.0 - std::pow(x / palm.a, 2)));
            const double lean = fan * (k - 0.5 * (count - 1));
            shape.limbs.push_back(limb(Vec2(x, y - 2 * radius), std::numbers::pi / 2 - lean,
                                       2 * radius + lengths[k], radius, 0.85 * radius,
                                       bends[k] * fan * 4));
        }
    }
    return shape;
}

// An octopus: five to eight tapering, curling tentacles fanning from the
// bottom of one body, close together where they leave it.
inline ShapeUnion tentacles(Dice& dice) {
    EllipseShape head{Vec2::Zero(), dice.uniform(0.6, 1.0), dice.uniform(0.7, 1.2), 0.0};
    const int count = dice.integer(5, 8);
    const double spread = dice.uniform(1.6, 3.4);  // radians over all tentacles
    const double curl = dice.uniform(-1.2, 1.2);
    ShapeUnion shape;
    shape.bodies.push_back(head);
    for (int k = 0; k < count; ++k) {
        const double f = count > 1 ? double(k) / (count - 1) - 0.5 : 0.0;
        const double angle = -std::numbers::pi / 2 + spread * f + dice.uniform(-0.05, 0.05);
        const double r0 = dice.uniform(0.08, 0.15);
        const Vec2 base = 0.6 * Vec2(head.a * std::cos(angle), head.b * std::sin(angle));
        shape.limbs.push_back(limb(base, angle, dice.uniform(1.2, 2.5), r0,
                                   dice.uniform(0.015, 0.05), curl + dice.uniform(-0.4, 0.4)));
    }
    return shape;
}

// An elongated body with two to four limbs meeting it at 20 to 160 degrees
// to its outline's tangent.
inline ShapeUnion angles(Dice& dice) {
    EllipseShape body{Vec2::Zero(), dice.uniform(1.0, 1.8), dice.uniform(0.3, 0.55), 0.0};
    ShapeUnion shape;
    shape.bodies.push_back(body);
    const int count = dice.integer(2, 4);
    std::vector<double> used;
    for (int k = 0; k < count; ++k) {
        const double t = placeApart(dice, used, 0.4, 2.7, 0.7);
        const double radius = dice.uniform(0.07, 0.18);
        const double meeting = dice.uniform(20.0, 160.0) * std::numbers::pi / 180.0;
        // The tangent turned by the meeting angle, away from the body.
        const double tangent = ellipseNormalAngle(body, t) - std::numbers::pi / 2;
        const double angle = tangent + meeting;
        // Starting a radius inside the body, so its round end does not show.
        const Vec2 base = ellipsePoint(body, t) - radius * direction(ellipseNormalAngle(body, t));
        shape.limbs.push_back(limb(base, angle, dice.uniform(0.8, 2.0), radius,
                                   radius * dice.uniform(0.6, 1.0), dice.uniform(-0.3, 0.3)));
    }
    return shape;
}

// Draws the closed `outline` (counter-clockwise, dense) as a stroke in the
// given manner, `spacing` being the cleaner's spacing.
inline std::vector<Vec2> drawn(const std::vector<Vec2>& outline, StrokeManner manner,
                               double spacing, Dice& dice) {
    const double length = polylineLength(outline, true);
    std::vector<Vec2> loop = outline;
    loop.push_back(outline.front());
    // Start anywhere, in either direction.
    std::rotate(loop.begin(), loop.begin() + dice.integer(0, int(outline.size()) - 1),
                loop.end() - 1);
    loop.back() = loop.front();
    if (dice.chance(0.5))
        std::reverse(loop.begin(), loop.end());
    std::vector<double> arc(loop.size(), 0.0);
    for (std::size_t i = 1; i < loop.size(); ++i)
        arc[i] = arc[i - 1] + (loop[i] - loop[i - 1]).norm();
    // Point and unit normal at arc length s (wrapping around).
    std::size_t cursor = 0;
    auto at = [&](double s, Vec2* normal) {
        s = std::fmod(s, length);
        if (s < arc[cursor])
            cursor = 0;
        while (cursor + 2 < loop.size() && arc[cursor + 1] < s)
            ++cursor;
        const Vec2 a = loop[cursor], b = loop[cursor + 1];
        const double span = arc[cursor + 1] - arc[cursor];
        const double f = span > 0 ? (s - arc[cursor]) / span : 0.0;
        const Vec2 d = (b - a).norm() > 0 ? Vec2((b - a).normalized()) : Vec2(1, 0);
        *normal = Vec2(d.y(), -d.x());
        return Vec2(a + f * (b - a));
    };
    std::vector<Vec2> stroke;
    Vec2 normal;
    if (manner == StrokeManner::Steady) {
        for (double s = 0; s < length; s += spacing / 3)
            stroke.push_back(at(s, &normal) + 0.02 * spacing * Vec2(dice.normal(), dice.normal()));
    } else if (manner == StrokeManner::Fast) {
        // Sparse points at a varying speed; the end short of or past the start.
        const double end = length + dice.uniform(-1.0, 1.5) * spacing;
        double speed = dice.uniform(1.2, 3.0);
        for (double s = 0; s < end; s += speed * spacing) {
            stroke.push_back(at(s, &normal) + 0.05 * spacing * Vec2(dice.normal(), dice.normal()));
            speed = std::clamp(speed + dice.uniform(-0.4, 0.4), 1.2, 3.0);
        }
    } else {
        // Dense points; a slow wobble across the outline plus a tremor.
        const double wobble = dice.uniform(0.1, 0.25) * spacing;
        const double wavelength = dice.uniform(3.0, 7.0) * spacing;
        const double phase = dice.uniform(0, 2 * std::numbers::pi);
        const double tremor = dice.uniform(0.05, 0.15) * spacing;
        for (double s = 0; s < length; s += spacing / 10) {
            const Vec2 p = at(s, &normal);
            const double offset = wobble * std::sin(2 * std::numbers::pi * s / wavelength + phase);
            stroke.push_back(p + offset * normal + tremor * Vec2(dice.normal(), dice.normal()));
        }
    }
    return stroke;
}

}  // namespace creature

// Outline `seed` of class `shapeClass`: the same for the same arguments.
inline CreatureOutline creatureOutline(CreatureClass shapeClass, int seed) {
    CreatureOutline result;
    result.shapeClass = shapeClass;
    result.seed = seed;
    result.manner = static_cast<StrokeManner>(seed % 3);
    creature::Dice dice(0x9E3779B9u * static_cast<std::uint32_t>(seed + 1) +
                        1013u * static_cast<std::uint32_t>(shapeClass));
    ShapeUnion shape;
    switch (shapeClass) {
        case CreatureClass::Legs:
            shape = creature::legs(dice);
            break;
        case CreatureClass::Stubs:
            shape = creature::stubs(dice, result.stubs);
            break;
        case CreatureClass::Fingers:
            shape = creature::fingers(dice);
            break;
        case CreatureClass::Tentacles:
            shape = creature::tentacles(dice);
            break;
        case CreatureClass::Angles:
            shape = creature::angles(dice);
            break;
    }
    const double spacing = creature::spacingOf(shape);
    const std::vector<Vec2> outline = traceOutline(shape, shape.box(), spacing / 8);
    std::vector<Vec2> stroke = creature::drawn(outline, result.manner, spacing, dice);
    // Turned, scaled and moved at random.
    const double angle = dice.uniform(0, 2 * std::numbers::pi);
    const double scale = std::pow(10.0, dice.uniform(-1.0, 2.0));
    const Vec2 offset(dice.uniform(-5, 5) * scale, dice.uniform(-5, 5) * scale);
    const Eigen::Rotation2Dd turn(angle);
    for (Vec2& p : stroke)
        p = scale * (turn * p) + offset;
    for (Stub& stub : result.stubs) {
        stub.base = scale * (turn * stub.base) + offset;
        stub.tip = scale * (turn * stub.tip) + offset;
        stub.length *= scale;
        stub.thickness *= scale;
    }
    result.stroke = std::move(stroke);
    return result;
}

}  // namespace rigmesh::testsupport
