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

fs::path find_lab_folder(const fs::path& submission, const std::vector<std::string>& labs) {
    const fs::path nested = submission / "labs";
    std::error_code error;
    if (fs::is_symlink(nested, error) || !fs::is_directory(nested, error)) return submission;
    for (const std::string& lab : labs)
        if (fs::exists(fs::symlink_status(nested / (lab + ".cpp"), error))) return nested;
    return submission;
}

std::map<std::string, std::string> copy_lab_files(const fs::path& from, const fs::path& stubs, const fs::path& to,
                                                  const std::vector<std::string>& labs) {
    fs::remove_all(to);
    fs::create_directories(to);
    std::map<std::string, std::string> refused;
    for (const std::string& lab : labs) {
        const std::string name = lab + ".cpp";
        std::string content;
        std::error_code error;
        if (!fs::exists(fs::symlink_status(from / name, error))) {
            refused[lab] = "the submission has no labs/" + name;
        } else {
            try {
                content = read_regular_file(from / name, kMaxLabFileBytes);
            } catch (const std::exception& why) {
                refused[lab] = "labs/" + name + " " + why.what() + ": it is graded as missing";
            }
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
