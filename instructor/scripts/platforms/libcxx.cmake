# Toolchain of test-platforms.sh's libcxx target (GoogleTest and the handout are built with it):
# clang with libc++, LLVM's standard library, the compiler and library of macOS's Xcode tools.
set(CMAKE_C_COMPILER clang) # GoogleTest's project enables C too
set(CMAKE_CXX_COMPILER clang++)
# CMake passes CMAKE_CXX_FLAGS to C++ links too: the programs link libc++.
set(CMAKE_CXX_FLAGS_INIT "-stdlib=libc++")
# Debian's cpp-httplib is a library compiled against GCC's standard library, which a libc++ program cannot
# link: test-platforms.sh gives upstream's header-only httplib.h instead (WHITTED_HTTPLIB_HEADER_ONLY), as
# vcpkg's cpp-httplib does on a Mac.
