#include "platform.hpp"

#ifdef _WIN32
#include <io.h> // _isatty, _waccess (MSVC and MinGW)
#include <windows.h> // SetConsoleOutputCP
#else
#include <unistd.h> // isatty, access
#endif

#include <csignal>

namespace whitted {
namespace {
std::atomic<bool>* interrupt_flag = nullptr; // set once, before the handler is installed
extern "C" void on_interrupt(int) { interrupt_flag->store(true); }
} // namespace

void stop_on_interrupt(std::atomic<bool>& flag) {
    static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only set a lock-free atomic");
    interrupt_flag = &flag;
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
}

void use_utf8_console() {
#ifdef _WIN32
    SetConsoleOutputCP(CP_UTF8);
#endif
}

bool is_terminal(std::FILE* stream) {
#ifdef _WIN32
    return _isatty(_fileno(stream)) != 0;
#else
    return isatty(fileno(stream)) != 0;
#endif
}

bool may_write(const std::filesystem::path& path) {
#ifdef _WIN32
    // The wide-character call: a path with letters outside the system's code page
    // (a user name with accents) reaches the file system unchanged. 2: write permission.
    return _waccess(path.c_str(), 2) == 0;
#else
    return access(path.c_str(), W_OK) == 0;
#endif
}

} // namespace whitted
