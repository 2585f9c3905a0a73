#include "grade/tamper_check.hpp"

#include <algorithm>

namespace whitted::grade {

namespace fs = std::filesystem;

FileRecord FileRecord::of(const std::vector<fs::path>& folders, const std::vector<std::string>& extensions) {
    FileRecord record;
    for (const fs::path& folder : folders) {
        std::error_code error;
        if (!fs::is_directory(folder, error)) continue;
        for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, error), end;
             !error && it != end; it.increment(error)) {
            std::error_code stat_error;
            if (!it->is_regular_file(stat_error)) continue;
            if (!extensions.empty() && std::find(extensions.begin(), extensions.end(), it->path().extension().string()) == extensions.end())
                continue;
            const std::uintmax_t size = it->file_size(stat_error);
            const auto modified = it->last_write_time(stat_error).time_since_epoch();
            if (stat_error) continue;
            record.files_[it->path().string()] =
                Stamp{size, std::chrono::duration_cast<std::chrono::nanoseconds>(modified).count()};
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
