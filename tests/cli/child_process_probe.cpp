// The child of child_process_test.cpp: does what its arguments say, in their order.
//   out TEXT   writes TEXT to standard output, as it is (no newline)
//   err TEXT   writes TEXT to standard error
//   exit N     exits with code N
//   crash      writes through a null pointer
//   sleep      sleeps for a minute (longer than any test waits)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string command = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : "";
        if (command == "out") {
            std::fputs(value, stdout);
            ++i;
        } else if (command == "err") {
            std::fputs(value, stderr);
            ++i;
        } else if (command == "exit") {
            std::exit(std::atoi(value));
        } else if (command == "crash") {
            volatile int* nowhere = nullptr;
            *nowhere = 1;
        } else if (command == "sleep") {
            std::this_thread::sleep_for(std::chrono::minutes(1));
        } else {
            std::fprintf(stderr, "child_process_probe: unknown command '%s'\n", argv[i]);
            return 2;
        }
    }
    return 0;
}
