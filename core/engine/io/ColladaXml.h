// The COLLADA text Assimp writes, edited as an XML tree (tinyxml2): the
// passes that add what Assimp leaves out (io/BoneTipHints,
// io/ColladaSkinsAndClips) share the parse, the refusal and the printing.
#pragma once

#include <functional>
#include <string>

namespace tinyxml2 {
class XMLElement;
}

namespace rigmesh {

// `dae` with `edit` applied to its root element. Throws Error when the text
// is not XML (the exporter's output is broken).
std::string editColladaXml(const std::string& dae,
                           const std::function<void(tinyxml2::XMLElement& root)>& edit);

// A number as COLLADA text: 9 significant digits.
std::string colladaNumber(double value);

}  // namespace rigmesh
