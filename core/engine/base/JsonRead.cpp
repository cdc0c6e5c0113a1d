#include "base/JsonRead.h"

#include <cmath>

namespace rigmesh::jsonread {

const json& field(const json& object, const char* key) {
    if (!object.is_object())
        fail("expected a map holding \"" + std::string(key) + "\"");
    const auto it = object.find(key);
    if (it == object.end())
        fail("missing \"" + std::string(key) + "\"");
    return *it;
}

const json& array(const json& object, const char* key) {
    const json& value = field(object, key);
    if (!value.is_array())
        fail("\"" + std::string(key) + "\" is not a list");
    return value;
}

double rawNumber(const json& value, const char* what) {
    if (!value.is_number())
        fail(std::string(what) + " is not a number");
    return value.get<double>();
}

double number(const json& value, const char* what) {
    const double out = rawNumber(value, what);
    if (!std::isfinite(out))
        fail(std::string(what) + " holds a value that is not finite");
    return out;
}

bool boolean(const json& value, const char* what) {
    if (!value.is_boolean())
        fail(std::string(what) + " is not true or false");
    return value.get<bool>();
}

std::string text(const json& value, const char* what) {
    if (!value.is_string())
        fail(std::string(what) + " is not text");
    return value.get<std::string>();
}

std::vector<double> numbers(const json& list, std::size_t multiple, const char* what,
                            double (*read)(const json&, const char*)) {
    if (!list.is_array() || list.size() % multiple != 0)
        fail(std::string(what) + " has the wrong length");
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

std::string parseErrorReason(const nlohmann::json::exception& error) {
    // nlohmann's ids: parse_error 101 (syntax), 110 (input ends early),
    // 112-115 (binary formats); out_of_range 406/407 (a number no double
    // or integer holds); type_error 3xx.
    if (const auto* parse = dynamic_cast<const nlohmann::json::parse_error*>(&error)) {
        const std::string at = "at byte " + std::to_string(parse->byte);
        if (parse->id == 110)
            return "it ends too early, " + at;
        return "it is malformed " + at;
    }
    if (error.id == 406 || error.id == 407)
        return "it holds a number too large to read";
    if (dynamic_cast<const nlohmann::json::type_error*>(&error))
        return "a value has the wrong type";
    return "it is malformed";
}

}  // namespace rigmesh::jsonread
