# Building and testing your labs, on Windows, macOS and Linux alike, with nothing but CMake.
# Run it from the folder of the labs:
#
#   cmake -P scripts/lab.cmake 7    lab 7: builds what its tests need and the whitted program
#                                   (never older than the labs its tests just passed), runs lab 7's
#                                   tests, and draws lab 7's picture with your code in
#                                   build/pictures/lab7.png
#   cmake -P scripts/lab.cmake      every lab: builds everything, runs every test, and prints how far
#                                   each lab is (tests passed, functions still to write)
#
# The first time, it configures build/ (Release). On Linux, `make test LAB=7` and `make test` do the
# same. Options, before -P: -DBUILD_DIR=folder (build/ by default), -DJOBS=n (the number of CPUs).
# Why a script and not a workflow preset: the presets file stays at a version every Visual Studio 2022 reads.

cmake_minimum_required(VERSION 3.22) # the policies of the project's CMake (IN_LIST, ...)

# The arguments after the script's name (cmake's own, and -P with the script, come first).
set(arguments)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(CMAKE_ARGV${i} STREQUAL "-P")
    math(EXPR first "${i} + 2")
  endif()
endforeach()
if(first LESS_EQUAL last)
  foreach(i RANGE ${first} ${last})
    list(APPEND arguments "${CMAKE_ARGV${i}}")
  endforeach()
endif()
list(LENGTH arguments count)
if(count GREATER 1 OR (count EQUAL 1 AND NOT arguments MATCHES "^0*([1-9]|10)$"))
  message(FATAL_ERROR "usage: cmake -P scripts/lab.cmake [N], where N is a lab number from 1 to 10 "
                      "(cmake -P scripts/lab.cmake 7); without N, every lab and how far each is")
endif()

get_filename_component(source "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
if(NOT DEFINED BUILD_DIR)
  set(BUILD_DIR build)
endif()
get_filename_component(build "${BUILD_DIR}" ABSOLUTE BASE_DIR "${source}")
file(RELATIVE_PATH shown "${source}" "${build}") # build/, as the messages name it
if(NOT DEFINED JOBS)
  cmake_host_system_information(RESULT JOBS QUERY NUMBER_OF_LOGICAL_CORES)
endif()

# run(WHAT COMMAND...): runs the command, its output on the terminal; stops with WHAT when it fails.
function(run what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${source}" RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what}")
  endif()
endfunction()

if(NOT EXISTS "${build}/CMakeCache.txt")
  run("configuring ${shown}/ failed (see the messages above)"
      "${CMAKE_COMMAND}" -S "${source}" -B "${build}" -DCMAKE_BUILD_TYPE=Release)
endif()

if(count EQUAL 0)
  run("the build failed (see the compiler's messages above)"
      "${CMAKE_COMMAND}" --build "${build}" --config Release --parallel ${JOBS})
  include("${CMAKE_CURRENT_LIST_DIR}/progress.cmake")
  whitted_progress("${source}" "${build}" ${JOBS} status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "not every test passes yet: the report above says how far each lab is")
  endif()
  return()
endif()

math(EXPR lab "${arguments}") # 07 is lab 7
run("lab ${lab} does not compile (see the compiler's messages above)"
    "${CMAKE_COMMAND}" --build "${build}" --config Release --target lab${lab} --parallel ${JOBS})
run("lab ${lab}: some tests fail (see above); ${shown}/pictures/lab${lab}.png shows what your code draws, once it can"
    "${CMAKE_CTEST_COMMAND}" --test-dir "${build}" --build-config Release --label-regex "^lab${lab}$"
    --output-on-failure --parallel ${JOBS})
message("lab ${lab}: every test passes; its picture: ${shown}/pictures/lab${lab}.png")
