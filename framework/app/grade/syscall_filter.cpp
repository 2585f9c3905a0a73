#include "grade/syscall_filter.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <linux/filter.h>
#include <linux/sched.h>
#include <linux/seccomp.h>
#include <memory>
#include <seccomp.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <unistd.h>

namespace whitted::grade {
namespace {

// Calls denied outright: creating, changing or removing files and their
// attributes; sockets; IPC objects and keys that outlive the process; new
// namespaces and mounts; tracing; and the interfaces that would run such
// calls where the filter cannot see their arguments (io_uring, openat2, clone3).
constexpr const char* kDenied[] = {
    "creat", "openat2", "open_by_handle_at", "name_to_handle_at",
    "mkdir", "mkdirat", "mknod", "mknodat", "symlink", "symlinkat", "link", "linkat",
    "rename", "renameat", "renameat2", "unlink", "unlinkat", "rmdir", "truncate",
    "chmod", "fchmod", "fchmodat", "chown", "fchown", "fchownat", "lchown",
    "utime", "utimes", "utimensat", "futimesat",
    "setxattr", "lsetxattr", "fsetxattr", "removexattr", "lremovexattr", "fremovexattr",
    "socket", "shmget", "msgget", "semget", "mq_open", "mq_unlink", "add_key", "request_key", "keyctl",
    "unshare", "setns", "mount", "umount2", "pivot_root", "chroot", "fsopen", "fsmount", "open_tree", "move_mount",
    "ptrace", "process_vm_readv", "process_vm_writev", "bpf", "perf_event_open", "userfaultfd", "fanotify_init",
    "io_uring_setup", "io_uring_enter", "io_uring_register", "clone3",
};

struct ContextDeleter {
    void operator()(scmp_filter_ctx context) const { seccomp_release(context); }
};

// Denies `call` when its argument `index` has all of `bits` set (flags tests).
bool deny_bits(scmp_filter_ctx context, int call, unsigned index, std::uint64_t bits) {
    return seccomp_rule_add(context, SCMP_ACT_ERRNO(EPERM), call, 1, SCMP_CMP(index, SCMP_CMP_MASKED_EQ, bits, bits)) == 0;
}

// Denies `call` when its argument `index` masked with `mask` equals `value`.
bool deny_masked(scmp_filter_ctx context, int call, unsigned index, std::uint64_t mask, std::uint64_t value) {
    return seccomp_rule_add(context, SCMP_ACT_ERRNO(EPERM), call, 1, SCMP_CMP(index, SCMP_CMP_MASKED_EQ, mask, value)) == 0;
}

} // namespace

std::vector<std::byte> worker_syscall_filter(std::string& why) {
    const std::unique_ptr<void, ContextDeleter> context(seccomp_init(SCMP_ACT_ALLOW));
    if (!context) {
        why = "seccomp_init failed";
        return {};
    }
    scmp_filter_ctx ctx = context.get();
    bool ok = true;
    for (const char* name : kDenied) {
        const int call = seccomp_syscall_resolve_name(name);
        if (call == __NR_SCMP_ERROR) continue; // not a call of this architecture
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), call, 0) == 0;
    }
    // open(path, flags) and openat(dir, path, flags): reading only.
    for (const auto& [name, flags_index] : {std::pair{"open", 1u}, std::pair{"openat", 2u}}) {
        const int call = seccomp_syscall_resolve_name(name);
        if (call == __NR_SCMP_ERROR) continue;
        ok = ok && deny_masked(ctx, call, flags_index, O_ACCMODE, O_WRONLY) && deny_masked(ctx, call, flags_index, O_ACCMODE, O_RDWR) &&
             deny_bits(ctx, call, flags_index, O_CREAT) && deny_bits(ctx, call, flags_index, O_TRUNC) &&
             deny_bits(ctx, call, flags_index, O_TMPFILE & ~O_DIRECTORY);
    }
    // ioctl(fd, TIOCSTI or TIOCLINUX): typing into a terminal.
    for (const unsigned long request : {static_cast<unsigned long>(TIOCSTI), static_cast<unsigned long>(TIOCLINUX)})
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(ioctl), 1, SCMP_A1(SCMP_CMP_EQ, request)) == 0;
    // clone(flags, ...) into new namespaces.
    for (const std::uint64_t flag : {CLONE_NEWNS, CLONE_NEWUSER, CLONE_NEWNET, CLONE_NEWIPC, CLONE_NEWPID, CLONE_NEWUTS, CLONE_NEWCGROUP})
        ok = ok && deny_bits(ctx, SCMP_SYS(clone), 0, flag);
    if (!ok) {
        why = "a rule of the system call filter was refused";
        return {};
    }
    // libseccomp 2.5 exports to a descriptor only: a memory file, read back.
    const int file = memfd_create("whitted-filter", MFD_CLOEXEC);
    if (file < 0) {
        why = std::string("memfd_create: ") + std::strerror(errno);
        return {};
    }
    std::vector<std::byte> program;
    if (seccomp_export_bpf(ctx, file) == 0) {
        const off_t size = lseek(file, 0, SEEK_END);
        program.resize(size > 0 ? static_cast<std::size_t>(size) : 0);
        if (size <= 0 || pread(file, program.data(), program.size(), 0) != size || program.size() % sizeof(sock_filter) != 0) {
            program.clear();
        }
    }
    close(file);
    if (program.empty()) why = "the system call filter could not be exported";
    return program;
}

int install_syscall_filter(const std::vector<std::byte>& program) {
    sock_fprog fprog{};
    fprog.len = static_cast<unsigned short>(program.size() / sizeof(sock_filter));
    fprog.filter = reinterpret_cast<sock_filter*>(const_cast<std::byte*>(program.data()));
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return errno;
    if (prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &fprog) != 0) return errno;
    return 0;
}

std::string syscall_filter_summary() {
    return "a system call filter (no files written, created or removed, no sockets, no IPC objects or keys, no "
           "namespaces, no tracing, no typing into a terminal)";
}

} // namespace whitted::grade
