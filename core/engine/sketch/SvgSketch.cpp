// parseSketchSvg: finds the first drawable outline element of an SVG document.
#include <tinyxml2.h>
#include <filesystem>
#include <string_view>

#include "base/Error.h"
#include "sketch/Sketch.h"
#include "sketch/SvgNumberScanner.h"
#include "sketch/SvgPathData.h"
#include "sketch/SvgTransform.h"

namespace rigmesh {

namespace {

// The element name without a namespace prefix ("svg:path" -> "path").
std::string_view localName(const tinyxml2::XMLElement& element) {
    std::string_view name = element.Name();
    const auto colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// Containers whose content is never drawn directly.
bool isNonRendering(std::string_view name) {
    return name == "defs" || name == "clipPath" || name == "mask" || name == "marker" ||
           name == "pattern" || name == "symbol" || name == "metadata";
}

Polyline2 pointList(const char* attribute) {
    SvgNumberScanner scan(attribute == nullptr ? "" : attribute, "points");
    Polyline2 points;
    while (!scan.atEnd()) {
        const double x = scan.number();
        if (scan.atEnd()) {
            scan.fail(MessageId::SvgOddCoordinateCount);
        }
        points.emplace_back(x, scan.number());
    }
    return points;
}

// The outline of `element` in its own coordinates, empty for other elements.
Polyline2 outlineOf(const tinyxml2::XMLElement& element) {
    const std::string_view name = localName(element);
    if (name == "path") {
        const char* data = element.Attribute("d");
        return data == nullptr ? Polyline2{} : flattenSvgPathData(data);
    }
    if (name == "polyline" || name == "polygon") {
        return pointList(element.Attribute("points"));
    }
    return {};
}

Affine2 transformOf(const tinyxml2::XMLElement& element) {
    const char* attribute = element.Attribute("transform");
    return attribute == nullptr ? Affine2::Identity() : parseSvgTransform(attribute);
}

// Depth-first search in document order; `parent` maps the element's parent
// coordinates to the document's. Returns true and fills `out` on success.
bool findOutline(const tinyxml2::XMLElement& element, const Affine2& parent, Polyline2& out) {
    if (isNonRendering(localName(element))) {
        return false;
    }
    const Affine2 transform = parent * transformOf(element);
    Polyline2 outline = outlineOf(element);
    if (!outline.empty()) {
        out.clear();
        for (const Vec2& p : outline) {
            out.push_back(applyAffine(transform, p));
        }
        return true;
    }
    for (const tinyxml2::XMLElement* child = element.FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
        if (findOutline(*child, transform, out)) {
            return true;
        }
    }
    return false;
}

}  // namespace

Sketch parseSketchSvg(const std::string& text, const std::string& sourceName) {
    tinyxml2::XMLDocument document;
    if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
        throw Error(MessageId::SketchNotSvg, sourceName, std::string(document.ErrorStr()));
    }
    const tinyxml2::XMLElement* root = document.RootElement();
    if (root == nullptr || localName(*root) != "svg") {
        throw Error(MessageId::SketchNoSvgRoot, sourceName);
    }
    Polyline2 outline;
    bool found = false;
    try {
        found = findOutline(*root, Affine2::Identity(), outline);
    } catch (const SvgSyntaxError& error) {
        Message message{
            error.problem,
            {sourceName, error.attribute, messageArgument(error.character), error.excerpt}};
        message.args.insert(message.args.end(), error.details.begin(), error.details.end());
        throw Error(std::move(message));
    }
    if (!found) {
        throw Error(MessageId::SketchSvgNoStroke, sourceName);
    }
    Sketch sketch;
    sketch.name = std::filesystem::path(sourceName).stem().string();
    // SVG's y axis points down; sketches are y-up.
    for (const Vec2& p : outline) {
        sketch.points.emplace_back(p.x(), -p.y());
    }
    return sketch;
}

}  // namespace rigmesh
