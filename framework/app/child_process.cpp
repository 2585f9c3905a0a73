#include "child_process.hpp"

#include <thread>
#include <utility>

#ifdef _WIN32
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cwchar>
#include <system_error>
#include <windows.h>
#else
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __APPLE__
#include <cstdint>
#include <mach-o/dyld.h> // _NSGetExecutablePath
#endif
extern char** environ;
#endif

namespace whitted {

#ifdef _WIN32

struct ChildProcess::Handle {
    HANDLE process = nullptr;
    ~Handle() { CloseHandle(process); }
};

namespace {

// The exit code a stopped child gets from TerminateProcess (its reason says "stopped" in any case).
constexpr UINT stopped_exit_code = EXIT_FAILURE;

// UTF-8 text as the UTF-16 of the Windows calls whose names end in W.
std::wstring utf16(const std::string& text) {
    if (text.empty()) return {};
    const int length = MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), nullptr, 0);
    std::wstring result(length, L'\0');
    MultiByteToWideChar(CP_UTF8, 0, text.data(), static_cast<int>(text.size()), result.data(), length);
    return result;
}

// Appends one argument to a command line as the Microsoft C runtime reads it back: in quotes if it has a space, a
// tab or a quote (or is empty), a quote escaped by a backslash, backslashes doubled only before a quote.
void append_argument(std::wstring& line, const std::wstring& argument) {
    if (!line.empty()) line += L' ';
    if (!argument.empty() && argument.find_first_of(L" \t\n\v\"") == std::wstring::npos) {
        line += argument;
        return;
    }
    line += L'"';
    std::size_t backslashes = 0;
    for (const wchar_t letter : argument) {
        if (letter == L'\\') {
            ++backslashes;
            continue;
        }
        line.append(letter == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
        line += letter;
        backslashes = 0;
    }
    line.append(2 * backslashes, L'\\'); // before the closing quote
    line += L'"';
}

// A handle the child inherits (only the ones of PROC_THREAD_ATTRIBUTE_HANDLE_LIST below), closed on leaving scope.
struct InheritedFile {
    HANDLE handle;
    InheritedFile(const std::filesystem::path& path, DWORD access, DWORD creation) {
        SECURITY_ATTRIBUTES inheritable{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
        handle = CreateFileW(path.c_str(), access, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, &inheritable,
                             creation, FILE_ATTRIBUTE_NORMAL, nullptr);
    }
    ~InheritedFile() {
        if (handle != INVALID_HANDLE_VALUE) CloseHandle(handle);
    }
    InheritedFile(const InheritedFile&) = delete;
    InheritedFile& operator=(const InheritedFile&) = delete;
};

// The system's sentence for the last error of a Windows call.
std::string last_error() {
    return std::error_code(static_cast<int>(GetLastError()), std::system_category()).message();
}

// How a process ended, from its exit code: one of NTSTATUS's error codes is the exception that ended it.
ChildExit exit_of(DWORD code) {
    ChildExit result{static_cast<int>(code), false, "exit code " + std::to_string(code)};
    if (code < ERROR_SEVERITY_ERROR) return result;
    result.crashed = true;
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08lX", static_cast<unsigned long>(code));
    const char* name = code == EXCEPTION_ACCESS_VIOLATION      ? "access violation"
                       : code == EXCEPTION_STACK_OVERFLOW      ? "stack overflow"
                       : code == EXCEPTION_ILLEGAL_INSTRUCTION ? "illegal instruction"
                       : code == EXCEPTION_INT_DIVIDE_BY_ZERO  ? "integer divide by zero"
                                                               : nullptr;
    result.reason = name ? "crashed: " + std::string(name) + " (exception " + hex + ")"
                         : "crashed: exception " + std::string(hex);
    return result;
}

} // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    if (argv.empty()) throw ChildStartError("no program to run");
    const std::wstring program = utf16(argv[0]);
    std::wstring command_line;
    for (const std::string& argument : argv) append_argument(command_line, utf16(argument));
    const InheritedFile out(output, GENERIC_WRITE, CREATE_ALWAYS);
    if (out.handle == INVALID_HANDLE_VALUE) throw ChildStartError("cannot write " + output.string() + ": " + last_error());
    const InheritedFile input(L"NUL", GENERIC_READ, OPEN_EXISTING); // always there
    // Only these two handles are inherited, not those another thread is giving its own child at the same time.
    HANDLE inherited[] = {input.handle, out.handle};
    SIZE_T size = 0;
    InitializeProcThreadAttributeList(nullptr, 1, 0, &size);
    std::vector<char> attributes(size);
    STARTUPINFOEXW startup{};
    startup.StartupInfo.cb = sizeof startup;
    startup.StartupInfo.dwFlags = STARTF_USESTDHANDLES;
    startup.StartupInfo.hStdInput = input.handle;
    startup.StartupInfo.hStdOutput = out.handle;
    startup.StartupInfo.hStdError = out.handle;
    startup.lpAttributeList = reinterpret_cast<LPPROC_THREAD_ATTRIBUTE_LIST>(attributes.data());
    if (!InitializeProcThreadAttributeList(startup.lpAttributeList, 1, 0, &size))
        throw ChildStartError("cannot run " + argv[0] + ": " + last_error());
    const bool listed = UpdateProcThreadAttribute(startup.lpAttributeList, 0, PROC_THREAD_ATTRIBUTE_HANDLE_LIST,
                                                  inherited, sizeof inherited, nullptr, nullptr);
    PROCESS_INFORMATION started{};
    const bool ok = listed && CreateProcessW(program.c_str(), command_line.data(), nullptr, nullptr, TRUE,
                                             EXTENDED_STARTUPINFO_PRESENT, nullptr, nullptr, &startup.StartupInfo, &started);
    const std::string error = ok ? "" : last_error();
    DeleteProcThreadAttributeList(startup.lpAttributeList);
    if (!ok) throw ChildStartError("cannot run " + argv[0] + ": " + error);
    CloseHandle(started.hThread);
    handle_ = new Handle{started.hProcess};
}

std::optional<ChildExit> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
    if (exit_ || !handle_) return exit_;
    const auto milliseconds = std::clamp<std::chrono::milliseconds::rep>(timeout.count(), 0, INFINITE - 1);
    const DWORD waited = WaitForSingleObject(handle_->process, static_cast<DWORD>(milliseconds));
    if (waited == WAIT_TIMEOUT) return std::nullopt;
    DWORD code = 0;
    if (waited != WAIT_OBJECT_0 || !GetExitCodeProcess(handle_->process, &code)) { // nothing to wait for
        exit_ = ChildExit{-1, false, "lost"};
        return exit_;
    }
    exit_ = exit_of(code);
    if (stopped_) exit_->reason = "stopped";
    return exit_;
}

void ChildProcess::stop() {
    if (exit_ || !handle_) return;
    stopped_ = true;
    TerminateProcess(handle_->process, stopped_exit_code);
}

std::filesystem::path own_executable() {
    std::wstring path(MAX_PATH, L'\0');
    for (;;) { // a longer path than the buffer is cut short: a buffer twice as large, until it fits
        const DWORD length = GetModuleFileNameW(nullptr, path.data(), static_cast<DWORD>(path.size()));
        if (length == 0) return {};
        if (length < path.size()) return path.substr(0, length);
        path.resize(2 * path.size());
    }
}

namespace {

// The process that made NAME.copy-PID.exe, from its name (`stem` is "NAME.copy-"), when the name is such a name.
std::optional<DWORD> copy_maker(const std::wstring& name, const std::wstring& stem, const std::wstring& extension) {
    if (!name.starts_with(stem) || !name.ends_with(extension) || name.size() <= stem.size() + extension.size())
        return std::nullopt;
    const std::wstring digits = name.substr(stem.size(), name.size() - stem.size() - extension.size());
    if (digits.size() > 10 || !std::all_of(digits.begin(), digits.end(), [](wchar_t c) { return c >= L'0' && c <= L'9'; }))
        return std::nullopt;
    return static_cast<DWORD>(std::wcstoul(digits.c_str(), nullptr, 10));
}

bool process_runs(DWORD pid) {
    const HANDLE process = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, pid);
    if (!process) return false;
    DWORD code = 0;
    const bool running = GetExitCodeProcess(process, &code) && code == STILL_ACTIVE;
    CloseHandle(process);
    return running;
}

} // namespace

void free_own_file() {
    const std::filesystem::path self = own_executable();
    if (self.empty()) return;
    const std::wstring extension = self.extension().wstring();
    const std::wstring moved_stem = self.stem().wstring() + L".running-";
    const std::wstring copy_stem = self.stem().wstring() + L".copy-";
    // What earlier runs left: the moved programs (a running one's is locked, and stays), and the copies of runs
    // stopped before they renamed them (not the copy of a run in the middle of this).
    std::error_code ignored;
    try {
        for (const auto& entry : std::filesystem::directory_iterator(self.parent_path(), ignored)) {
            const std::wstring name = entry.path().filename().wstring();
            const std::optional<DWORD> maker = copy_maker(name, copy_stem, extension);
            if (name.starts_with(moved_stem) || (maker && !process_runs(*maker)))
                std::filesystem::remove(entry.path(), ignored);
        }
    } catch (const std::filesystem::filesystem_error&) { // a folder that cannot be listed: nothing removed
    }
    // The copy is made first, under a name of its own: the program's name is never a half-written file for another
    // process starting the program, and missing only between two renames.
    const std::wstring pid = std::to_wstring(GetCurrentProcessId());
    const std::filesystem::path copy = self.parent_path() / (copy_stem + pid + extension);
    const std::filesystem::path moved = self.parent_path() / (moved_stem + pid + extension);
    if (!CopyFileW(self.c_str(), copy.c_str(), FALSE)) return; // as it was
    if (!MoveFileExW(self.c_str(), moved.c_str(), MOVEFILE_REPLACE_EXISTING)) { // as it was: the file is locked
        DeleteFileW(copy.c_str());
        return;
    }
    for (int attempt = 0; attempt < 5; ++attempt) { // a virus scanner may hold the new copy for a moment
        if (MoveFileExW(copy.c_str(), self.c_str(), 0)) return;
        Sleep(20);
    }
    if (MoveFileExW(moved.c_str(), self.c_str(), 0)) DeleteFileW(copy.c_str()); // put back: as it was
    // Else a build wrote a new program there meanwhile, or neither rename works: the copy stays, not to lose the
    // program (the next run removes it).
}

void add_library_folder(const std::filesystem::path& folder) {
    std::wstring path(GetEnvironmentVariableW(L"PATH", nullptr, 0), L'\0'); // its size with the final zero
    if (!path.empty()) path.resize(GetEnvironmentVariableW(L"PATH", path.data(), static_cast<DWORD>(path.size())));
    const std::wstring value = folder.wstring() + (path.empty() ? std::wstring() : L";" + path);
    SetEnvironmentVariableW(L"PATH", value.c_str());
}

#else // POSIX

struct ChildProcess::Handle {
    pid_t pid = -1;
};

namespace {

ChildExit exit_of(int status) {
    ChildExit result;
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        result.crashed = true;
        result.code = 128 + signal;
        const char* name = strsignal(signal);
        result.reason = "crashed: " + std::string(name ? name : "signal") + " (signal " + std::to_string(signal) + ")";
    } else {
        result.code = WEXITSTATUS(status);
        result.reason = "exit code " + std::to_string(result.code);
    }
    return result;
}

} // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    if (argv.empty()) throw ChildStartError("no program to run");
    // Checked here, as posix_spawn cannot always tell: under qemu-user the child's failed exec is only its exit code 127.
    if (access(argv[0].c_str(), X_OK) != 0) throw ChildStartError("cannot run " + argv[0] + ": " + std::strerror(errno));
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    // The output opened here for the same reason; close-on-exec, so that no other child inherits it.
    const int out = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0) throw ChildStartError("cannot write " + output.string() + ": " + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out, 1);
    posix_spawn_file_actions_adddup2(&actions, out, 2);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(out);
    if (error != 0) throw ChildStartError("cannot run " + argv[0] + ": " + std::strerror(error));
    handle_ = new Handle{pid};
}

std::optional<ChildExit> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
    if (exit_ || !handle_) return exit_;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int status = 0;
        const pid_t done = waitpid(handle_->pid, &status, WNOHANG);
        if (done == handle_->pid) {
            exit_ = exit_of(status);
            if (stopped_) exit_->reason = "stopped";
            return exit_;
        }
        if (done < 0 && errno != EINTR) { // not our child any more: nothing to wait for
            exit_ = ChildExit{-1, false, "lost"};
            return exit_;
        }
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

void ChildProcess::stop() {
    if (exit_ || !handle_) return;
    stopped_ = true;
    kill(handle_->pid, SIGKILL);
}

std::filesystem::path own_executable() {
#ifdef __APPLE__
    char path[4096];
    std::uint32_t size = sizeof path;
    if (_NSGetExecutablePath(path, &size) != 0) return {};
    return std::filesystem::canonical(path);
#else
    std::error_code error;
    return std::filesystem::read_symlink("/proc/self/exe", error);
#endif
}

void free_own_file() {}

void add_library_folder(const std::filesystem::path&) {}

#endif // POSIX

ChildProcess::~ChildProcess() {
    if (!handle_) return;
    stop();
    wait();
    delete handle_;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), exit_(std::move(other.exit_)), stopped_(other.stopped_) {}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
    if (this != &other) {
        ChildProcess old(std::move(*this));
        handle_ = std::exchange(other.handle_, nullptr);
        exit_ = std::move(other.exit_);
        stopped_ = other.stopped_;
    }
    return *this;
}

ChildExit ChildProcess::wait() {
    for (;;)
        if (std::optional<ChildExit> done = wait_for(std::chrono::hours(1))) return *done;
}

ChildExit run_child(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    return ChildProcess(argv, output).wait();
}

} // namespace whitted
