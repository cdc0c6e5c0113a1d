#include "io/ColladaXml.h"

#include <tinyxml2.h>

#include <cstdio>

#include "base/Error.h"

namespace rigmesh {

std::string editColladaXml(const std::string& dae,
                           const std::function<void(tinyxml2::XMLElement& root)>& edit) {
    tinyxml2::XMLDocument document;
    if (document.Parse(dae.data(), dae.size()) != tinyxml2::XML_SUCCESS ||
        document.RootElement() == nullptr)
        throw Error(MessageId::ExportColladaInvalidXml);
    edit(*document.RootElement());
    tinyxml2::XMLPrinter printer;
    document.Print(&printer);
    return std::string(printer.CStr(), static_cast<std::size_t>(printer.CStrSize() - 1));
}

std::string colladaNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

}  // namespace rigmesh
