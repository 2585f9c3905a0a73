#include "grader/submission.hpp"

#include "whitted/lab_table.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace whitted::grade {
namespace fs = std::filesystem;

std::string read_regular_file(const fs::path& file, std::size_t max_bytes) {
    const int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        if (errno == ELOOP) throw std::runtime_error("is a symbolic link; only regular files are read");
        throw std::runtime_error(std::string("cannot be opened: ") + std::strerror(errno));
    }
    struct stat info {};
    std::string content;
    try {
        if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) throw std::runtime_error("is not a regular file (a folder, FIFO or device?)");
        if (static_cast<std::size_t>(info.st_size) > max_bytes)
            throw std::runtime_error("is larger than " + std::to_string(max_bytes) + " bytes");
        content.resize(static_cast<std::size_t>(info.st_size));
        std::size_t done = 0;
        while (done < content.size()) {
            const ssize_t n = read(fd, content.data() + done, content.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            done += static_cast<std::size_t>(n);
        }
        content.resize(done);
    } catch (...) {
        close(fd);
        throw;
    }
    close(fd);
    return content;
}

namespace {

// How many of the lab files `folder` holds (links count: they are refused, with the reason, when copied).
int lab_files_in(const fs::path& folder, const std::vector<std::string>& labs) {
    std::error_code error;
    if (!fs::is_directory(fs::symlink_status(folder, error))) return 0;
    int count = 0;
    for (const std::string& lab : labs)
        if (fs::exists(fs::symlink_status(folder / (lab + ".cpp"), error))) ++count;
    return count;
}

// Folders a zip tool or the system adds, never the student's work.
bool searched(const fs::directory_entry& entry) {
    const std::string name = entry.path().filename().string();
    std::error_code error;
    return entry.is_directory(error) && !entry.is_symlink(error) && !name.empty() && name[0] != '.' && name != "__MACOSX";
}

// Lower case, for comparing names as a person reads them.
std::string lowered(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The names in `folder` that look like `name` (NN_lab.cpp) but are not it: a browser's "NN_lab (1).cpp", another
// case, a copy ("NN_lab copy.cpp", "NN_lab-2.cpp"), another extension ("NN_lab.cc", "NN_lab.cpp.txt"). Sorted.
std::vector<std::string> near_misses(const fs::path& folder, const std::string& name) {
    const std::string stem = lowered(name.substr(0, name.size() - 4)); // without ".cpp"
    std::vector<std::string> found;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string other = it->path().filename().string();
        if (other != name && other.size() <= 255 && lowered(other).starts_with(stem)) found.push_back(other);
    }
    std::sort(found.begin(), found.end());
    return found;
}

std::string describe(const LabFolder& place) {
    return (place.shown.empty() ? std::string("the top folder") : place.shown) + " (" + std::to_string(place.files) +
           (place.files == 1 ? " file)" : " files)");
}

} // namespace

LabFolder find_lab_folder(const fs::path& submission, const std::vector<std::string>& labs) {
    std::vector<LabFolder> places;
    auto look = [&](const fs::path& folder, const std::string& shown) {
        if (const int files = lab_files_in(folder, labs)) places.push_back({folder, shown, files});
    };
    look(submission, "");
    look(submission / "labs", "labs/");
    std::vector<fs::path> subfolders;
    std::error_code error;
    for (fs::directory_iterator it(submission, error), end; !error && it != end; it.increment(error))
        if (searched(*it) && it->path().filename() != "labs") subfolders.push_back(it->path());
    std::sort(subfolders.begin(), subfolders.end()); // the message lists places in the same order every time
    for (const fs::path& folder : subfolders) {
        const std::string name = folder.filename().string();
        look(folder, name + "/");
        look(folder / "labs", name + "/labs/");
    }
    if (places.empty()) return LabFolder{submission, "", 0};
    if (places.size() == 1) return places.front();
    std::string found;
    for (std::size_t i = 0; i < places.size(); ++i)
        found += (i == 0 ? "" : i + 1 == places.size() ? " and " : ", ") + describe(places[i]);
    throw AmbiguousSubmission("lab files were found in " + std::to_string(places.size()) + " places: " + found +
                              ". Keep one copy of each file, all in one folder, and submit again.");
}

std::optional<std::string> linked_submission(const fs::path& argument) {
    std::string path = argument.lexically_normal().string(); // "link/." is "link/"
    while (path.size() > 1 && path.back() == '/') path.pop_back(); // "link/" would be the folder it leads to
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(path, error))) return std::nullopt;
    return fs::path(path).filename().string() +
           " is a symbolic link, which the grader does not follow (it could lead to any folder of the grading machine): "
           "grade the folder itself";
}

std::map<std::string, std::string> copy_lab_files(const LabFolder& from, const fs::path& stubs, const fs::path& to,
                                                  const std::vector<std::string>& labs) {
    fs::remove_all(to);
    fs::create_directories(to);
    std::map<std::string, std::string> refused;
    for (const std::string& lab : labs) {
        const std::string name = lab + ".cpp";
        const std::string shown = from.shown + name;
        std::string content;
        std::error_code error;
        const bool absent = !fs::exists(fs::symlink_status(from.folder / name, error));
        if (from.files == 0) {
            refused[lab] = "no lab file was found: the grader looks for " + name +
                           " and the other lab files at the top of the submission, in labs/, or one folder down (my-project/labs/)";
        } else if (absent) {
            refused[lab] = "the submission has no " + shown;
        } else {
            try {
                content = read_regular_file(from.folder / name, kMaxLabFileBytes);
            } catch (const std::exception& why) {
                refused[lab] = shown + " " + why.what() + ": it is graded as missing";
            }
        }
        // A near miss is named, not taken: the grader grades the exact names only, so that no file is graded by a guess.
        if (absent)
            if (const std::vector<std::string> misses = near_misses(from.folder, name); !misses.empty()) {
                std::string listed;
                for (std::size_t i = 0; i < misses.size() && i < 3; ++i) listed += (i ? ", " : "") + from.shown + misses[i];
                refused[lab] += "; " + listed + (misses.size() == 1 ? " looks like it: rename it " : " look like it: keep one, named ") +
                                name + " exactly, and submit again";
            }
        if (refused.count(lab)) content = read_regular_file(stubs / name, kMaxLabFileBytes);
        std::ofstream out(to / name, std::ios::binary | std::ios::trunc);
        out << content;
        if (!out.flush()) throw std::runtime_error("cannot write " + (to / name).string());
    }
    return refused;
}

std::vector<std::string> lab_names() {
    std::vector<std::string> names;
    for (const LabInfo& lab : kLabs) names.emplace_back(lab.stem);
    return names;
}

} // namespace whitted::grade
