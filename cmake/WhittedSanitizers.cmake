# Sanitizer and fuzzing builds (instructor/docs/robustness.md).
#
# WHITTED_SANITIZE builds every target with AddressSanitizer and
# UndefinedBehaviorSanitizer; any report stops the program with an error, so a
# test that triggers one fails. WHITTED_FUZZ (clang only) adds libFuzzer's
# coverage instrumentation and builds the fuzz_<name> programs of instructor/tests/fuzz.
option(WHITTED_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(WHITTED_FUZZ "Also build the libFuzzer programs of instructor/tests/fuzz (clang; implies WHITTED_SANITIZE)" OFF)

if(WHITTED_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "WHITTED_FUZZ needs clang: configure with -DCMAKE_CXX_COMPILER=clang++ (instructor/scripts/fuzz.sh does)")
  endif()
  set(WHITTED_SANITIZE ON)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(WHITTED_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# whitted_without_sanitizers(TARGET): for programs that must run under limits
# a sanitizer cannot live with (ASan reserves terabytes of address space, so
# RLIMIT_AS stops it from starting).
function(whitted_without_sanitizers target)
  if(WHITTED_SANITIZE)
    target_compile_options(${target} PRIVATE -fno-sanitize=all)
    target_link_options(${target} PRIVATE -fno-sanitize=all)
  endif()
endfunction()
