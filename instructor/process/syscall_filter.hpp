// A seccomp filter for the student's worker: an allow list of the system calls
// a worker needs (computing, threads, reading files, its own descriptors);
// every other call fails with ENOSYS.
//
// Why: a worker only computes and answers over the descriptors it was given.
// Without namespaces (users mode) its user id could still create files where
// every user may write, open sockets (the network, or abstract Unix sockets),
// keep System V or POSIX IPC objects or kernel keys for a later run, and push
// input into a terminal; each is a channel out of a test or into the next one.
// A filter needs no privileges and works in containers that forbid
// namespaces, so it holds in both modes. The filter is made once, in the
// grader, and installed in the child between fork and exec with two prctl
// calls (nothing that allocates).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace whitted::grade {

/// The compiled filter (a classic BPF program: struct sock_filter records),
/// or empty with `why` set when this machine cannot make one.
std::vector<std::byte> worker_syscall_filter(std::string& why);

/// In a child, before exec: no new privileges, then the filter. Only
/// async-signal-safe calls. Returns 0, or the errno of the call that failed.
int install_syscall_filter(const std::vector<std::byte>& program);

/// One line for the instructor: what the filter denies.
std::string syscall_filter_summary();

} // namespace whitted::grade
