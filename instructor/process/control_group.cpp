#include "process/control_group.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

// One cgroup mount: where it is, which part of the hierarchy it shows, and its controllers (v1) or "" (v2).
struct Mount {
    fs::path point;
    std::string root;
    std::string options;
    bool v2 = false;
};

std::vector<Mount> cgroup_mounts() {
    std::vector<Mount> mounts;
    std::ifstream info("/proc/self/mountinfo");
    for (std::string line; std::getline(info, line);) {
        // id parent major:minor root point options [optional...] - type source super-options
        std::istringstream fields(line);
        std::string id, parent, device, root, point, options, field;
        fields >> id >> parent >> device >> root >> point >> options;
        while (fields >> field && field != "-") {}
        std::string type, source, super;
        fields >> type >> source >> super;
        if (type == "cgroup") mounts.push_back({point, root, std::string(1, ',').append(super).append(1, ','), false});
        if (type == "cgroup2") mounts.push_back({point, root, "", true});
    }
    return mounts;
}

// This process's path in the hierarchy with `controller` (v1), or in the unified one for "".
std::optional<std::string> own_path(const std::string& controller) {
    std::ifstream file("/proc/self/cgroup");
    for (std::string line; std::getline(file, line);) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        // "memory" or "cpu,cpuacct" (v1), "" (v2): compared as ",memory," within ",cpu,cpuacct,".
        std::string controllers(1, ',');
        controllers.append(line, first + 1, second - first - 1).push_back(',');
        std::string wanted(1, ',');
        wanted.append(controller).push_back(',');
        const bool match = controller.empty() ? controllers == ",," : controllers.find(wanted) != std::string::npos;
        if (match) return line.substr(second + 1);
    }
    return std::nullopt;
}

// The folder of this process's group as mounted, or empty.
fs::path own_folder(const Mount& mount, const std::string& path) {
    if (mount.root == "/") return mount.point / fs::path(path).relative_path();
    if (path.rfind(mount.root, 0) != 0) return {};
    return mount.point / fs::path(path.substr(mount.root.size())).relative_path();
}

bool write_text(const fs::path& file, const std::string& text) {
    std::ofstream out(file);
    out << text;
    out.flush();
    return static_cast<bool>(out);
}

std::string group_name() { return "whitted-grade-" + std::to_string(getpid()); }

// Whether a new process can join the group (a kernel may refuse, as v2 does for some groups): one tries.
bool can_join(const std::vector<fs::path>& join_files) {
    std::vector<int> fds;
    for (const fs::path& file : join_files) fds.push_back(open(file.c_str(), O_WRONLY | O_CLOEXEC));
    bool opened = true;
    for (const int fd : fds) opened &= fd >= 0;
    pid_t child = opened ? fork() : -1;
    if (child == 0) {
        for (const int fd : fds)
            if (write(fd, "0", 1) != 1) _exit(1);
        _exit(0);
    }
    int status = 0;
    const bool joined = child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    for (const int fd : fds)
        if (fd >= 0) close(fd);
    return joined;
}

} // namespace

std::optional<ControlGroup> ControlGroup::make(std::size_t memory_bytes, long max_processes, std::string& problem) {
    if (geteuid() != 0) {
        problem = "no cgroup: the grader is not root";
        return std::nullopt;
    }
    const std::vector<Mount> mounts = cgroup_mounts();
    ControlGroup group;
    // v1: a memory and a pids hierarchy of their own.
    const Mount* memory = nullptr;
    const Mount* pids = nullptr;
    for (const Mount& mount : mounts) {
        if (!mount.v2 && mount.options.find(",memory,") != std::string::npos) memory = &mount;
        if (!mount.v2 && mount.options.find(",pids,") != std::string::npos) pids = &mount;
    }
    if (memory && pids) {
        group.kind_ = "cgroup v1";
        for (const auto& [mount, controller] : {std::pair{memory, "memory"}, std::pair{pids, "pids"}}) {
            const std::optional<std::string> path = own_path(controller);
            const fs::path own = path ? own_folder(*mount, *path) : fs::path();
            std::error_code error;
            if (own.empty() || !fs::create_directory(own / group_name(), error)) {
                problem = "no cgroup: cannot make a group in " + (own.empty() ? std::string("the ") + controller + " hierarchy" : own.string());
                return std::nullopt; // the destructor removes what was made
            }
            group.folders_.push_back(own / group_name());
        }
        if (!write_text(group.folders_[1] / "pids.max", std::to_string(max_processes)) || !group.set_memory(memory_bytes)) {
            problem = "no cgroup: cannot set the group's ceilings";
            return std::nullopt;
        }
        if (!can_join(group.join_files())) {
            problem = "no cgroup: a process cannot join the group made for it";
            return std::nullopt;
        }
        return group;
    }
    // v2: a child of our own group if its controllers are delegated, else a sibling.
    for (const Mount& mount : mounts) {
        if (!mount.v2) continue;
        const std::optional<std::string> path = own_path("");
        if (!path) break;
        const fs::path own = own_folder(mount, *path);
        for (const fs::path& parent : {own, own.parent_path()}) {
            if (parent.empty() || parent.string().size() < mount.point.string().size()) continue;
            std::error_code error;
            if (!fs::create_directory(parent / group_name(), error)) continue;
            const fs::path folder = parent / group_name();
            if (fs::exists(folder / "memory.max") && fs::exists(folder / "pids.max") && write_text(folder / "pids.max", std::to_string(max_processes))) {
                group.kind_ = "cgroup v2";
                group.folders_.push_back(folder);
                if (group.set_memory(memory_bytes) && can_join(group.join_files())) return group;
                group.folders_.clear();
            }
            fs::remove(folder, error);
        }
        break;
    }
    problem = "no cgroup: no writable cgroup hierarchy with the memory and pids controllers";
    return std::nullopt;
}

ControlGroup::ControlGroup(ControlGroup&& other) noexcept : kind_(std::move(other.kind_)), folders_(std::move(other.folders_)) {
    other.folders_.clear();
}

ControlGroup::~ControlGroup() {
    if (folders_.empty()) return;
    kill_group_processes(join_files());
    for (const fs::path& folder : folders_) {
        // A group can be removed once its last process is reaped: try for a while.
        for (int attempt = 0; attempt < 100 && rmdir(folder.c_str()) != 0 && errno == EBUSY; ++attempt) usleep(10000);
    }
}

std::vector<fs::path> ControlGroup::join_files() const {
    std::vector<fs::path> files;
    for (const fs::path& folder : folders_) files.push_back(folder / "cgroup.procs");
    return files;
}

bool ControlGroup::set_memory(std::size_t memory_bytes) const {
    const std::string bytes = std::to_string(memory_bytes);
    if (kind_ == "cgroup v2") {
        if (!write_text(folders_[0] / "memory.max", bytes)) return false;
        if (fs::exists(folders_[0] / "memory.swap.max")) write_text(folders_[0] / "memory.swap.max", "0");
        return true;
    }
    // v1: memory plus swap may not be below memory alone; raise or lower them in the order that keeps that true.
    const fs::path limit = folders_[0] / "memory.limit_in_bytes", with_swap = folders_[0] / "memory.memsw.limit_in_bytes";
    if (!fs::exists(with_swap)) return write_text(limit, bytes);
    if (write_text(limit, bytes)) return write_text(with_swap, bytes);
    return write_text(with_swap, bytes) && write_text(limit, bytes);
}

void kill_group_processes(const std::vector<fs::path>& join_files) {
    for (const fs::path& procs : join_files) {
        // Rounds catch what forked since the last; the pids ceiling keeps them few.
        for (int round = 0; round < 1000; ++round) {
            std::ifstream file(procs);
            bool any = false;
            for (long pid; file >> pid;) {
                any = true;
                kill(static_cast<pid_t>(pid), SIGKILL);
            }
            if (!any) break;
            usleep(1000);
        }
    }
}

} // namespace whitted::grade
