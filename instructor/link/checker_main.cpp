// The main of a grading checker: the GoogleTest tests of a lab, with that lab's
// functions answered by a worker over the grading link (instructor/link/).
//
//   check_<lab> --worker-fds=M,IN,OUT [gtest options]  the grader made the worker and the channel
//   check_<lab> --worker=PROGRAM [gtest options]     start the worker here (CTest, by hand)
//
// whitted_remote_labs is the set of labs the worker answers, as bits 1..N (lab k is bit k), defined by each
// checker's own one-line file (instructor/cmake/WhittedSplit.cmake): this file compiles once for every checker.
// With WHITTED_LINK_REPORT=<file> in the environment, a broken link's reason is also written to that file (for the grader), then the
// line "during box_entry() (labs/10_bvh.cpp)" when a call to the worker was in progress. Exit
// code: GoogleTest's (0 all passed, 1 a failure), or 3 when the link broke (the worker died, stalled, or broke the protocol) or
// the worker ended badly: then no test of this run may count as passed.
#include "printers.hpp" // the tests' printers, as every test file sees them (tests/CMakeLists.txt)
#include "lab_link.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>
#include <vector>

extern const std::uint32_t whitted_remote_labs;
static_assert(std::is_same_v<whitted::link::LabSet, std::uint32_t>, "whitted_remote_labs is a LabSet");

namespace {

using whitted::link::Link;

struct WorkerProcess {
    pid_t pid = -1;
    whitted::link::ChannelFds channel;
};

// Starts the worker with its side of a new channel as descriptors 3, 4 and 5.
WorkerProcess start_worker(const char* program) {
    whitted::link::ChannelPair pair;
    try {
        pair = whitted::link::make_channel_pair();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "checker: %s\n", e.what());
        std::exit(3);
    }
    const pid_t pid = fork();
    if (pid < 0) {
        std::perror("checker: fork");
        std::exit(3);
    }
    if (pid == 0) {
        // Above 10 first, so that dup2 always makes new descriptors 3, 4 and 5 (without close-on-exec).
        const whitted::link::ChannelFds& w = pair.worker;
        const int fds[3] = {fcntl(w.memory, F_DUPFD_CLOEXEC, 10), fcntl(w.wake_in, F_DUPFD_CLOEXEC, 10),
                            fcntl(w.wake_out, F_DUPFD_CLOEXEC, 10)};
        for (int i = 0; i < 3; ++i)
            if (fds[i] < 0 || dup2(fds[i], 3 + i) < 0) _exit(127);
        execl(program, program, static_cast<char*>(nullptr));
        std::perror("checker: cannot start the worker");
        _exit(127);
    }
    close(pair.worker.wake_in);
    close(pair.worker.wake_out);
    return {pid, pair.checker};
}

// Reports how the link and the worker ended; true when both ended well. A
// worker that does not end within two seconds of goodbye is killed.
bool ended_well(const Link& link, const WorkerProcess& worker) {
    std::fflush(stdout);
    bool well = link.broken().empty();
    if (!well) {
        std::fprintf(stderr, "grading link broken: %s\n", link.broken().c_str());
        if (!link.broken_during().empty()) std::fprintf(stderr, "grading link broken during %s\n", link.broken_during().c_str());
        // For the grader, apart from the output, which also carries what the worker's exceptions said:
        // the reason, then "during CALL" when a call to the worker was in progress.
        if (const char* report = std::getenv("WHITTED_LINK_REPORT"); report && *report)
            if (FILE* file = std::fopen(report, "w")) {
                std::fprintf(file, "%s\n", link.broken().c_str());
                if (!link.broken_during().empty()) std::fprintf(file, "during %s\n", link.broken_during().c_str());
                std::fclose(file);
            }
    }
    if (worker.pid > 0) {
        int status = 0;
        int waited_ms = 0;
        while (waitpid(worker.pid, &status, WNOHANG) == 0) {
            if (waited_ms >= 2000) {
                std::fprintf(stderr, "grading worker did not end after goodbye: killed\n");
                kill(worker.pid, SIGKILL);
                waitpid(worker.pid, &status, 0);
                return false;
            }
            usleep(10000);
            waited_ms += 10;
        }
        if (WIFSIGNALED(status)) {
            std::fprintf(stderr, "grading worker killed by signal %d (%s)\n", WTERMSIG(status),
                         strsignal(WTERMSIG(status)));
            well = false;
        } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
            std::fprintf(stderr, "grading worker exited with code %d\n", WEXITSTATUS(status));
            well = false;
        }
    }
    return well;
}

} // namespace

int main(int argc, char** argv) {
    std::signal(SIGPIPE, SIG_IGN);
    WorkerProcess worker;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--worker-fds=", 0) == 0) {
            whitted::link::ChannelFds& fds = worker.channel;
            if (std::sscanf(arg.c_str() + 13, "%d,%d,%d", &fds.memory, &fds.wake_in, &fds.wake_out) != 3) {
                std::fprintf(stderr, "checker: --worker-fds=M,IN,OUT expects three numbers\n");
                return 2;
            }
        } else if (arg.rfind("--worker=", 0) == 0) {
            worker = start_worker(argv[i] + 9);
        } else {
            args.push_back(argv[i]);
        }
    }
    int count = static_cast<int>(args.size());
    args.push_back(nullptr);
    ::testing::InitGoogleTest(&count, args.data());
    if (worker.channel.memory < 0) { // listing tests, or no worker: every call fails
        const int result = RUN_ALL_TESTS();
        return ::testing::GTEST_FLAG(list_tests) ? result : 3;
    }
    std::optional<Link> link;
    try {
        link.emplace(whitted::link::Role::checker, worker.channel, whitted_remote_labs);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "checker: %s\n", e.what());
        return 3;
    }
    Link::set_current(&*link);
    const int result = RUN_ALL_TESTS();
    link->say_goodbye();
    close(worker.channel.wake_out); // the worker sees the end of its wake pipe
    if (!ended_well(*link, worker)) return 3;
    return result;
}
