#include "whitted/lab_table.hpp"

namespace whitted {

std::string stage_list() {
    std::string list;
    for (const LabInfo& row : kLabs) {
        if (!list.empty()) list += ", ";
        list += std::to_string(row.number) + " " + std::string(row.title);
    }
    return list;
}

std::vector<std::string_view> lab_functions(const LabInfo& lab) {
    std::vector<std::string_view> names;
    std::string_view rest = lab.functions;
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (space != 0) names.push_back(rest.substr(0, space));
        rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
    }
    return names;
}

} // namespace whitted
