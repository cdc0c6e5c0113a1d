#include "Mutator.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "model/BoundedCbor.h"

namespace rigmesh::fuzz {
namespace {

using nlohmann::json;

constexpr unsigned char kCborMagic[] = {0xD9, 0xD9, 0xF7};

// Text that breaks numbers and structure where it lands.
const char* const kTokens[] = {"NaN",
                               "nan",
                               "Infinity",
                               "-Infinity",
                               "inf",
                               "1e308",
                               "-1e308",
                               "1e-308",
                               "-1",
                               "-0",
                               "0",
                               "1e999",
                               "99999999999999999999",
                               "4294967295",
                               "2147483648",
                               "-2147483649",
                               "\"",
                               "[",
                               "]",
                               "{",
                               "}",
                               ",",
                               ":",
                               "<",
                               ">",
                               "/>",
                               "\\u0000",
                               "e",
                               "0x10",
                               ".",
                               "--",
                               "&amp;",
                               "<!--",
                               "M"};

const double kNumbers[] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           1e308,
                           -1e308,
                           1e-308,
                           -1.0,
                           0.0,
                           -0.0,
                           1e9,
                           -1e9,
                           1e-12,
                           0.5};

}  // namespace

Mutator::Mutator(InputKind kind, std::vector<std::string> seeds, std::uint64_t seed)
    : kind_(kind), seeds_(std::move(seeds)), random_(seed) {}

std::size_t Mutator::position(const std::string& input) {
    return std::uniform_int_distribution<std::size_t>(0, input.size())(random_);
}

std::string Mutator::token() {
    return kTokens[std::uniform_int_distribution<std::size_t>(0, std::size(kTokens) - 1)(random_)];
}

std::string Mutator::next() {
    std::string input =
        seeds_[std::uniform_int_distribution<std::size_t>(0, seeds_.size() - 1)(random_)];
    const int count = std::uniform_int_distribution<int>(1, 3)(random_);
    for (int i = 0; i < count; ++i) {
        switch (std::uniform_int_distribution<int>(0, 9)(random_)) {
            case 0:
            case 1:
            case 2:
                mutateBytes(input);
                break;
            case 3:
            case 4:
            case 5:
                mutateText(input);
                break;
            case 6:
            case 7:
            case 8:
                mutateTree(input);
                break;
            default:
                nest(input);
                break;
        }
    }
    return input;
}

void Mutator::mutateBytes(std::string& input) {
    if (input.empty())
        return;
    std::uniform_int_distribution<int> byte(0, 255);
    const std::size_t at = position(input) % input.size();
    switch (std::uniform_int_distribution<int>(0, 5)(random_)) {
        case 0:  // flip a few bits
            for (int i = 0; i < 4; ++i)
                input[position(input) % input.size()] ^=
                    static_cast<char>(1 << (byte(random_) % 8));
            break;
        case 1:
            input[at] = static_cast<char>(byte(random_));
            break;
        case 2:
            input.resize(at);
            break;  // truncate
        case 3:
            input.erase(at, std::min<std::size_t>(input.size() - at, 1 + byte(random_)));
            break;
        case 4: {  // duplicate a range in place
            const std::string range = input.substr(at, 1 + byte(random_) * 4);
            input.insert(position(input), range);
            break;
        }
        default: {  // splice in a range of another seed
            const std::string& other =
                seeds_[std::uniform_int_distribution<std::size_t>(0, seeds_.size() - 1)(random_)];
            if (!other.empty()) {
                const std::size_t from = position(other) % other.size();
                input.insert(position(input), other.substr(from, 1 + byte(random_) * 8));
            }
            break;
        }
    }
}

// Replaces a run of number characters with a token, or inserts one.
void Mutator::mutateText(std::string& input) {
    const std::size_t at = position(input);
    std::size_t begin = at;
    while (begin < input.size() && !std::isdigit(static_cast<unsigned char>(input[begin])))
        ++begin;
    if (begin >= input.size() || std::uniform_int_distribution<int>(0, 3)(random_) == 0) {
        input.insert(at, token());
        return;
    }
    std::size_t end = begin;
    while (end < input.size() && (std::isdigit(static_cast<unsigned char>(input[end])) ||
                                  input[end] == '.' || input[end] == 'e' || input[end] == '-'))
        ++end;
    input.replace(begin, end - begin, token());
}

void Mutator::nest(std::string& input) {
    const int depth = std::uniform_int_distribution<int>(1, 100000)(random_);
    if (kind_ == InputKind::Cbor) {
        // Arrays of one element (0x81) after the magic.
        const std::size_t at = input.size() >= 3 ? 3 : 0;
        input.insert(at, std::string(static_cast<std::size_t>(depth), '\x81'));
    } else if (kind_ == InputKind::SvgText) {
        std::string open, close;
        for (int i = 0; i < std::min(depth, 20000); ++i) {
            open += "<g>";
            close += "</g>";
        }
        const std::size_t at = input.find("<path");
        input.insert(at == std::string::npos ? position(input) : at, open);
        const std::size_t end = input.find("</svg>");
        input.insert(end == std::string::npos ? input.size() : end, close);
    } else {
        const std::size_t at = position(input);
        input.insert(at, std::string(static_cast<std::size_t>(depth), '['));
        input.insert(position(input), std::string(static_cast<std::size_t>(depth), ']'));
    }
}

// Parses the input as a tree, changes one node, writes it back. Inputs that
// no longer parse are mutated as bytes instead.
void Mutator::mutateTree(std::string& input) {
    if (kind_ == InputKind::SvgText || kind_ == InputKind::Bytes) {
        mutateText(input);
        return;
    }
    json root;
    const bool cbor = kind_ == InputKind::Cbor;
    // Deeply nested inputs stay bytes: writing a tree back recurses per level.
    constexpr int kMaxTreeDepth = 64;
    try {
        if (cbor) {
            if (input.size() < 3)
                return mutateBytes(input);
            const auto* bytes = reinterpret_cast<const std::uint8_t*>(input.data());
            root = model::parseBoundedCbor(bytes + 3, bytes + input.size(), kMaxTreeDepth);
        } else {
            bool tooDeep = false;
            root = json::parse(input, [&](int depth, json::parse_event_t, json&) {
                tooDeep = tooDeep || depth > kMaxTreeDepth;
                return !tooDeep;
            });
            if (tooDeep)
                return mutateBytes(input);
        }
    } catch (const std::exception&) {  // not parseable (json::exception) or too deep (Error)
        return mutateBytes(input);
    }
    // A random walk down from the root.
    json* node = &root;
    while ((node->is_array() || node->is_object()) && !node->empty() &&
           std::uniform_int_distribution<int>(0, 5)(random_) != 0) {
        auto it = node->begin();
        std::advance(it, std::uniform_int_distribution<std::size_t>(0, node->size() - 1)(random_));
        node = &*it;
    }
    std::uniform_int_distribution<int> choice(0, 4);
    if (node->is_number()) {
        const double value = kNumbers[std::uniform_int_distribution<std::size_t>(
            0, std::size(kNumbers) - 1)(random_)];
        if (choice(random_) == 0 && std::isfinite(value))
            *node = static_cast<std::int64_t>(value > 9e18 ? 9e18 : value < -9e18 ? -9e18 : value);
        else if (choice(random_) == 0)
            *node = node->get<double>() * 1e6;
        else
            *node = value;
    } else if (node->is_array()) {
        switch (choice(random_)) {
            case 0:
                node->clear();
                break;
            case 1:
                if (!node->empty())
                    node->erase(node->begin() + static_cast<long>(position(input) % node->size()));
                break;
            case 2: {  // duplicate the whole list's contents (or grow a lot)
                const json copy = *node;
                for (int i = 0; i < 3; ++i)
                    for (const json& item : copy)
                        node->push_back(item);
                break;
            }
            case 3:
                *node = json::array({*node});
                break;
            default:
                node->push_back(json::object());
                break;
        }
    } else if (node->is_object()) {
        switch (choice(random_)) {
            case 0:
                if (!node->empty())
                    node->erase(node->begin());
                break;
            case 1:  // a field copied under a neighbour's name
                if (node->size() > 1) {
                    auto a = node->begin(), b = std::next(node->begin());
                    (*node)[b.key()] = a.value();
                }
                break;
            default:
                (*node)["unexpected"] = 1;
                break;
        }
    } else if (node->is_string()) {
        *node = choice(random_) == 0 ? std::string() : std::string(5000, 'x');
    } else if (node->is_boolean()) {
        *node = 3;
    } else {
        *node = json::array();
    }
    if (cbor) {
        std::vector<std::uint8_t> bytes(std::begin(kCborMagic), std::end(kCborMagic));
        json::to_cbor(root, bytes);
        input.assign(bytes.begin(), bytes.end());
    } else {
        input = root.dump();
    }
}

}  // namespace rigmesh::fuzz
