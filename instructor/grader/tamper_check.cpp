#include "grader/tamper_check.hpp"

#include <algorithm>

namespace whitted::grade {

namespace fs = std::filesystem;

FileRecord FileRecord::of(const std::vector<fs::path>& paths, const std::vector<std::string>& extensions) {
    FileRecord record;
    auto add = [&](const fs::path& file) {
        std::error_code error;
        const std::uintmax_t size = fs::file_size(file, error);
        const auto modified = fs::last_write_time(file, error).time_since_epoch();
        if (!error) record.files_[file.string()] = Stamp{size, std::chrono::duration_cast<std::chrono::nanoseconds>(modified).count()};
    };
    for (const fs::path& path : paths) {
        std::error_code error;
        if (fs::is_regular_file(path, error)) add(path);
        if (!fs::is_directory(path, error)) continue;
        for (fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, error), end;
             !error && it != end; it.increment(error)) {
            std::error_code stat_error;
            if (!it->is_regular_file(stat_error)) continue;
            if (!extensions.empty() && std::find(extensions.begin(), extensions.end(), it->path().extension().string()) == extensions.end())
                continue;
            add(it->path());
        }
    }
    return record;
}

std::optional<std::string> FileRecord::first_change(const FileRecord& now) const {
    for (const auto& [path, stamp] : files_) {
        const auto found = now.files_.find(path);
        if (found == now.files_.end()) return path + " was removed";
        if (!(found->second == stamp)) return path + " was changed";
    }
    for (const auto& [path, stamp] : now.files_)
        if (!files_.count(path)) return path + " was added";
    return std::nullopt;
}

} // namespace whitted::grade
