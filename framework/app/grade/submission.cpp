#include "grade/submission.hpp"

#include <algorithm>
#include <cctype>

namespace whitted::grade {
namespace fs = std::filesystem;

fs::path find_lab_folder(const fs::path& submission, const std::vector<std::string>& labs) {
    const fs::path nested = submission / "labs";
    for (const std::string& lab : labs)
        if (fs::is_regular_file(nested / (lab + ".cpp"))) return nested;
    return submission;
}

std::vector<std::string> copy_lab_files(const fs::path& from, const fs::path& stubs, const fs::path& to,
                                        const std::vector<std::string>& labs) {
    fs::remove_all(to);
    fs::create_directories(to);
    std::vector<std::string> missing;
    for (const std::string& lab : labs) {
        const fs::path file = from / (lab + ".cpp");
        const bool present = fs::is_regular_file(file);
        if (!present) missing.push_back(lab);
        // Copy the content, not the file's attributes: a fresh time stamp makes the build recompile it.
        fs::copy_file(present ? file : stubs / (lab + ".cpp"), to / (lab + ".cpp"), fs::copy_options::overwrite_existing);
        fs::last_write_time(to / (lab + ".cpp"), fs::file_time_type::clock::now());
    }
    return missing;
}

std::vector<std::string> lab_names(const fs::path& instructor_tree) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(instructor_tree / "labs")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".cpp" && stem.size() > 3 && std::isdigit(static_cast<unsigned char>(stem[0])) &&
            std::isdigit(static_cast<unsigned char>(stem[1])) && stem[2] == '_')
            names.push_back(stem);
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace whitted::grade
