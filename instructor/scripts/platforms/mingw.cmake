# Toolchain of test-platforms.sh's mingw target: MinGW-w64's GCC for 64-bit Windows (its
# posix-threads flavour, which has std::thread), the programs run by Wine. Linked statically,
# so that a program needs no MinGW DLL beside it.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix) # GoogleTest's project enables C too
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)
# Wine, through a script that runs a program again when Wine itself fails it (wine-run.sh says when).
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/wine-run.sh CACHE FILEPATH "Runs the target's programs here")
# Headers, libraries and packages only from the folders of CMAKE_FIND_ROOT_PATH (test-platforms.sh
# gives them: GoogleTest built for the target, the header-only libraries), never this machine's /usr;
# programs (make, the emulator) from this machine.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
