// The system calls of the `whitted` command that Windows and POSIX systems
// (Linux, macOS) spell differently, each behind one portable function.
#pragma once

#include <atomic>
#include <cstdio>
#include <filesystem>

namespace whitted {

/// Makes the console show this program's UTF-8 text as letters (Windows); nothing elsewhere, where it already does.
void use_utf8_console();

/// True when `stream` goes to a terminal (a console window), not to a file or a pipe.
bool is_terminal(std::FILE* stream);

/// From now on, Ctrl-C (and a request to end the program: SIGTERM) sets `flag` instead of ending the program.
void stop_on_interrupt(std::atomic<bool>& flag);

/// True when this process may write to the file or folder at `path`.
bool may_write(const std::filesystem::path& path);

} // namespace whitted
