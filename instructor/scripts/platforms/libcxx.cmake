# Toolchain of test-platforms.sh's libcxx target (GoogleTest and the handout are built with it):
# clang with libc++, LLVM's standard library, the compiler and library of macOS's Xcode tools.
set(CMAKE_C_COMPILER clang) # GoogleTest's project enables C too
set(CMAKE_CXX_COMPILER clang++)
# CMake passes CMAKE_CXX_FLAGS to C++ links too: the programs link libc++.
set(CMAKE_CXX_FLAGS_INIT "-stdlib=libc++")
# Debian's cpp-httplib is a library compiled against GCC's standard library, which a libc++ program cannot
# link: the libcxx build goes without it, and its `whitted explore` says what to install (on a Mac, vcpkg's
# cpp-httplib is headers only, compiled with the program).
set(CMAKE_DISABLE_FIND_PACKAGE_httplib ON)
