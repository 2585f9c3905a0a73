// A program that misbehaves on request, for the process runner's tests:
//   misbehaving_child exit N | segfault | abort | loop | sleep | allocate | touch MB | children MB | big-file | spew MB | env NAME | orphan | escaped
//                     | loops N (N children and itself loop, each under its own RLIMIT_CPU)
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    const std::string argument = argc > 2 ? argv[2] : "";
    if (mode == "exit") return std::atoi(argument.c_str());
    if (mode == "segfault") {
        volatile int* nowhere = nullptr;
        *nowhere = 1;
    }
    if (mode == "abort") std::abort();
    if (mode == "loop") {
        volatile unsigned long counter = 0;
        for (;;) counter = counter + 1;
    }
    if (mode == "sleep") std::this_thread::sleep_for(std::chrono::hours(1));
    if (mode == "loops") {
        for (int i = 0; i < std::atoi(argument.c_str()); ++i)
            if (fork() == 0) break;
        volatile unsigned long counter = 0;
        for (;;) counter = counter + 1;
    }
    if (mode == "allocate") {
        std::vector<char*> blocks;
        for (;;) {
            char* block = new char[64 << 20];
            std::memset(block, 1, 64 << 20);
            blocks.push_back(block);
        }
    }
    if (mode == "touch") { // uses MB megabytes of memory, then exits
        std::vector<char> block(static_cast<std::size_t>(std::atol(argument.c_str())) << 20);
        std::memset(block.data(), 1, block.size());
        return block[block.size() / 2] == 1 ? 0 : 1;
    }
    if (mode == "big-file") {
        std::ofstream out("big.bin", std::ios::binary);
        const std::string megabyte(1 << 20, 'x');
        for (;;) out << megabyte << std::flush;
    }
    if (mode == "spew") {
        const std::string line(1023, 'y');
        for (long i = 0; i < std::atol(argument.c_str()) * 1024; ++i) std::printf("%s\n", line.c_str());
        return 0;
    }
    if (mode == "lines") { // prints N numbered lines, then exits 0
        for (long i = 1; i <= std::atol(argument.c_str()); ++i) std::printf("line %ld\n", i);
        return 0;
    }
    if (mode == "env") {
        const char* value = std::getenv(argument.c_str());
        std::printf("%s\n", value ? value : "(unset)");
        return 0;
    }
    if (mode == "children") { // three children use MB megabytes each at once; exits 0 if all three did
        std::vector<pid_t> children;
        for (int i = 0; i < 3; ++i) {
            const pid_t child = fork();
            if (child == 0) {
                std::vector<char> block(static_cast<std::size_t>(std::atol(argument.c_str())) << 20);
                std::memset(block.data(), 1, block.size());
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
                _exit(block[block.size() / 2] == 1 ? 0 : 1);
            }
            children.push_back(child);
        }
        int failed = 0;
        for (const pid_t child : children) {
            int status = 0;
            waitpid(child, &status, 0);
            failed += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        }
        return failed == 0 ? 0 : 1;
    }
    if (mode == "escaped") { // leaves a sleeping child in a session of its own (out of the group) holding the output open
        const pid_t child = fork();
        if (child == 0) {
            setsid();
            std::this_thread::sleep_for(std::chrono::hours(1));
            _exit(0);
        }
        while (getsid(child) != child) std::this_thread::sleep_for(std::chrono::milliseconds(1)); // out of the group now
        std::printf("escaped %d\n", static_cast<int>(child));
        return 0;
    }
    if (mode == "orphan") { // leaves a sleeping child that holds the output open
        if (fork() == 0) std::this_thread::sleep_for(std::chrono::hours(1));
        std::printf("parent done\n");
        return 0;
    }
    std::fprintf(stderr, "unknown mode '%s'\n", mode.c_str());
    return 2;
}
