#include "platform.hpp"

#ifdef _WIN32
#include <io.h> // _isatty, _waccess (MSVC and MinGW)
#include <windows.h> // SetConsoleOutputCP
#else
#include <unistd.h> // isatty, access
#endif

namespace whitted {

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
