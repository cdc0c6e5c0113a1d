// A small argument reader for the rigmesh CLI: positional arguments and
// "--name value" / "-o value" options, with a clear message on misuse.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rigmesh::cli {

class CommandLine {
  public:
    // `valueOptions` take a value, `flags` do not; anything else is an error.
    CommandLine(const std::vector<std::string>& arguments,
                const std::set<std::string>& valueOptions, const std::set<std::string>& flags);

    const std::vector<std::string>& positional() const { return positional_; }
    std::optional<std::string> value(const std::string& option) const;
    bool flag(const std::string& option) const { return flags_.count(option) > 0; }
    // The option's value as a number; throws rigmesh::Error when it is not one.
    std::optional<double> number(const std::string& option) const;

  private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> flags_;
};

}  // namespace rigmesh::cli
