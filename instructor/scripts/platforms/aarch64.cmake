# Toolchain of test-platforms.sh's aarch64 target: Debian's GCC cross compiler for 64-bit ARM,
# the instruction set of Apple silicon (no SSE: the framework's portable paths), the programs
# run by qemu-user with Debian's ARM system libraries (-L: the cross compiler's own).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc) # GoogleTest's project enables C too
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu CACHE STRING "Runs the target's programs here")
# Headers, libraries and packages only from the folders of CMAKE_FIND_ROOT_PATH (test-platforms.sh
# gives them: GoogleTest built for the target, the header-only libraries), never this machine's /usr;
# programs (make, the emulator) from this machine.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
