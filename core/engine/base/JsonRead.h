// Reading untrusted JSON (documents, parts): every access checked, every
// failure a rigmesh::Error from a MessageId naming what is wrong ("missing
// \"mesh\"", "\"weights\" \"byBoneId\" holds a negative value"). A value is
// named by `what`, its path in the file, which reads the same in every
// language. The model's document reader adds "The document is corrupt: ..."
// around it.
#pragma once

#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/Error.h"
#include "base/Types.h"

namespace rigmesh::jsonread {

using nlohmann::json;

template <class... Args>
[[noreturn]] void fail(MessageId id, const Args&... args) {
    throw Error(id, args...);
}

// `key` as a path in messages: "mesh".
std::string quoted(const char* key);

const json& field(const json& object, const char* key);
const json& array(const json& object, const char* key);
// Any number, finite or not: for readers that name the part in their own
// finiteness message.
double rawNumber(const json& value, const char* what);
// Every number in a document is finite: NaN or infinity anywhere is damage.
double number(const json& value, const char* what);
bool boolean(const json& value, const char* what);
std::string text(const json& value, const char* what);
std::vector<double> numbers(const json& list, std::size_t multiple, const char* what,
                            double (*read)(const json&, const char*) = &number);
std::vector<Vec2> readVec2s(const json& list, const char* what);

template <typename Int>
Int integer(const json& value, const char* what) {
    if (!value.is_number_integer())
        fail(MessageId::DataNotInteger, what);
    if (value.is_number_unsigned()) {
        const auto v = value.get<std::uint64_t>();
        if (v > static_cast<std::uint64_t>(std::numeric_limits<Int>::max()))
            fail(MessageId::DataOutOfRange, what);
        return static_cast<Int>(v);
    }
    const auto v = value.get<std::int64_t>();
    if (v < static_cast<std::int64_t>(std::numeric_limits<Int>::min()) ||
        (v > 0 && static_cast<std::uint64_t>(v) >
                      static_cast<std::uint64_t>(std::numeric_limits<Int>::max())))
        fail(MessageId::DataOutOfRange, what);
    return static_cast<Int>(v);
}

// What a user can be told about a JSON or CBOR parsing error: where it
// stopped and why in plain words ("it ends too early, at byte 12"), never
// the library's own ids and wording ("[json.exception.parse_error.110]").
// A message to nest in the one that names the file.
Message parseErrorReason(const nlohmann::json::exception& error);

}  // namespace rigmesh::jsonread
