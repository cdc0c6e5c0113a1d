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
            throw Error(
                count == 1 ? MessageId::RecipeNoPartAtIndexOfOne : MessageId::RecipeNoPartAtIndex,
                index, count);
        return document.parts()[static_cast<std::size_t>(index)].id;
    }
    if (!reference.is_string())
        throw Error(MessageId::RecipePartReference);
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
        throw Error(MessageId::RecipeNoPartNamed, name.toStdString());
    if (matches > 1)
        throw Error(MessageId::RecipePartNameAmbiguous, matches, name.toStdString());
    return found;
}

}  // namespace rigmesh::model::recipe
