#include "CommandLine.h"

#include <cmath>
#include <cstdlib>

#include "base/Error.h"

namespace rigmesh::cli {

CommandLine::CommandLine(const std::vector<std::string>& arguments,
                         const std::set<std::string>& valueOptions,
                         const std::set<std::string>& flags) {
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument.size() < 2 || argument[0] != '-') {
            positional_.push_back(argument);
        } else if (valueOptions.count(argument)) {
            if (i + 1 >= arguments.size())
                throw Error("option " + argument + " needs a value");
            values_[argument] = arguments[++i];
        } else if (flags.count(argument)) {
            flags_.insert(argument);
        } else {
            throw Error("unknown option " + argument + " (see rigmesh --help)");
        }
    }
}

std::optional<std::string> CommandLine::value(const std::string& option) const {
    auto it = values_.find(option);
    if (it == values_.end())
        return std::nullopt;
    return it->second;
}

std::optional<double> CommandLine::number(const std::string& option) const {
    auto text = value(option);
    if (!text)
        return std::nullopt;
    char* end = nullptr;
    double result = std::strtod(text->c_str(), &end);
    if (end == text->c_str() || *end != '\0' || !std::isfinite(result))
        throw Error("option " + option + " needs a number, not '" + *text + "'");
    return result;
}

}  // namespace rigmesh::cli
