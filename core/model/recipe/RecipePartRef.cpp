#include "model/recipe/RecipePartRef.h"

#include "base/Error.h"

namespace rigmesh::model::recipe {

std::string partLabel(const PartNode& node) {
    return "part \"" + node.name.toStdString() + "\"";
}

PartId resolvePart(const Document& document, const nlohmann::json& reference) {
    const int count = document.partCount();
    if (reference.is_number_integer()) {
        const auto index = reference.get<std::int64_t>();
        if (index < 0 || index >= count)
            throw Error("there is no part at index " + std::to_string(index) +
                        " (the document has " + std::to_string(count) +
                        (count == 1 ? " part)" : " parts)"));
        return document.parts()[static_cast<std::size_t>(index)].id;
    }
    if (!reference.is_string())
        throw Error("\"part\" must be a part's name or its index (from 0)");
    const QString name = QString::fromStdString(reference.get<std::string>());
    PartId found = kNoPart;
    int matches = 0;
    for (const PartNode& node : document.parts()) {
        if (node.name == name) {
            found = node.id;
            ++matches;
        }
    }
    if (matches == 0)
        throw Error("there is no part \"" + name.toStdString() + "\"");
    if (matches > 1)
        throw Error(std::to_string(matches) + " parts are named \"" + name.toStdString() +
                    "\"; refer to the part by its index");
    return found;
}

}  // namespace rigmesh::model::recipe
