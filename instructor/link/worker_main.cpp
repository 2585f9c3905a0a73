// The grading worker: the framework, the student's lab code and, for every
// other lab, calls to the checker (remote_NN.cpp). It serves the checker's calls
// through the channel on file descriptors 3 (shared memory), 4 (wake pipe in)
// and 5 (wake pipe out) until told goodbye.
// It decides nothing: every answer it gives is judged by the checker.
#include "lab_link.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

int main() {
    std::signal(SIGPIPE, SIG_IGN); // a closed link is an error to report, not a death
    int code = 0;
    try {
        whitted::link::Link link(whitted::link::Role::worker, {3, 4, 5}, 0);
        whitted::link::Link::set_current(&link);
        link.serve_until_closed();
    } catch (const std::exception& e) {
        std::cerr << "grading worker: " << e.what() << '\n';
        code = 2;
    }
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    _exit(code); // no static destructors of the lab code
}
