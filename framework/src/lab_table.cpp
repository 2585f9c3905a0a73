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

} // namespace whitted
