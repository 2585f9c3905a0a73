# One lab at a time, on Windows, macOS and Linux alike, with nothing but CMake:
#
#   cmake -P scripts/lab.cmake 7
#
# run from the folder of the labs. It configures build/ the first time (Release),
# builds what lab 7's tests need and the whitted program (which is then never
# older than the labs its tests just passed), runs lab 7's tests, and draws
# lab 7's picture with your code in build/pictures/lab7.png. On Linux,
# `make test LAB=7` does the same. Why a script and not a workflow preset: the
# presets file stays at a version that every Visual Studio 2022 reads.

if(NOT CMAKE_ARGC EQUAL 4 OR NOT CMAKE_ARGV3 MATCHES "^0*([1-9]|10)$")
  message(FATAL_ERROR "usage: cmake -P scripts/lab.cmake N, where N is a lab number from 1 to 10 (cmake -P scripts/lab.cmake 7)")
endif()
math(EXPR lab "${CMAKE_ARGV3}") # 07 is lab 7
get_filename_component(source "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
set(build "${source}/build")
cmake_host_system_information(RESULT jobs QUERY NUMBER_OF_LOGICAL_CORES)

# run(WHAT COMMAND...): runs the command, its output on the terminal; stops with WHAT when it fails.
function(run what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${source}" RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what}")
  endif()
endfunction()

if(NOT EXISTS "${build}/CMakeCache.txt")
  run("configuring build/ failed (see the messages above)"
      "${CMAKE_COMMAND}" -S "${source}" -B "${build}" -DCMAKE_BUILD_TYPE=Release)
endif()
run("lab ${lab} does not compile (see the compiler's messages above)"
    "${CMAKE_COMMAND}" --build "${build}" --config Release --target lab${lab} --parallel ${jobs})
run("lab ${lab}: some tests fail (see above); build/pictures/lab${lab}.png shows what your code draws, once it can"
    "${CMAKE_CTEST_COMMAND}" --test-dir "${build}" --build-config Release --label-regex "^lab${lab}$"
    --output-on-failure --parallel ${jobs})
message("lab ${lab}: every test passes; its picture: build/pictures/lab${lab}.png")
