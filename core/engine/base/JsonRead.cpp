#include "base/JsonRead.h"

#include <cmath>

namespace rigmesh::jsonread {

std::string quoted(const char* key) {
    return "\"" + std::string(key) + "\"";
}

const json& field(const json& object, const char* key) {
    if (!object.is_object())
        fail(MessageId::DataNotMap, quoted(key));
    const auto it = object.find(key);
    if (it == object.end())
        fail(MessageId::DataFieldMissing, quoted(key));
    return *it;
}

const json& array(const json& object, const char* key) {
    const json& value = field(object, key);
    if (!value.is_array())
        fail(MessageId::DataNotList, quoted(key));
    return value;
}

double rawNumber(const json& value, const char* what) {
    if (!value.is_number())
        fail(MessageId::DataNotNumber, what);
    return value.get<double>();
}

double number(const json& value, const char* what) {
    const double out = rawNumber(value, what);
    if (!std::isfinite(out))
        fail(MessageId::DataNotFinite, what);
    return out;
}

bool boolean(const json& value, const char* what) {
    if (!value.is_boolean())
        fail(MessageId::DataNotBoolean, what);
    return value.get<bool>();
}

std::string text(const json& value, const char* what) {
    if (!value.is_string())
        fail(MessageId::DataNotText, what);
    return value.get<std::string>();
}

std::vector<double> numbers(const json& list, std::size_t multiple, const char* what,
                            double (*read)(const json&, const char*)) {
    if (!list.is_array() || list.size() % multiple != 0)
        fail(MessageId::DataWrongLength, what);
    std::vector<double> out;
    out.reserve(list.size());
    for (const json& v : list)
        out.push_back(read(v, what));
    return out;
}

std::vector<Vec2> readVec2s(const json& list, const char* what) {
    const std::vector<double> flat = numbers(list, 2, what);
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < flat.size(); i += 2)
        out.emplace_back(flat[i], flat[i + 1]);
    return out;
}

Message parseErrorReason(const nlohmann::json::exception& error) {
    // nlohmann's ids: parse_error 101 (syntax), 110 (input ends early),
    // 112-115 (binary formats); out_of_range 406/407 (a number no double
    // or integer holds); type_error 3xx.
    if (const auto* parse = dynamic_cast<const nlohmann::json::parse_error*>(&error)) {
        const std::string byte = std::to_string(parse->byte);
        return {
            parse->id == 110 ? MessageId::DataEndsEarly : MessageId::DataMalformedAt, {byte}, {}};
    }
    if (error.id == 406 || error.id == 407)
        return {MessageId::DataNumberTooLarge, {}, {}};
    if (dynamic_cast<const nlohmann::json::type_error*>(&error))
        return {MessageId::DataWrongType, {}, {}};
    return {MessageId::DataMalformed, {}, {}};
}

}  // namespace rigmesh::jsonread
