# The labs, and how the build mixes implementations of them.
#
# Every lab is one file with the same name in solution/ (the reference) and in
# labs/ (the student's); instructor/tests/mistakes/<lab>/ holds patches of the reference
# (catalogued mistakes).
# Each file becomes an object library, so an executable can take lab k from one
# implementation and every other lab from another: that is how one lab is
# graded in isolation.

# WHITTED_LABS: the lab stems, in order, read from the rows of the lab table
# (framework/include/whitted/lab_table.hpp), the one list of labs.
set(WHITTED_LAB_TABLE ${PROJECT_SOURCE_DIR}/framework/include/whitted/lab_table.hpp)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${WHITTED_LAB_TABLE})
file(STRINGS ${WHITTED_LAB_TABLE} lab_rows REGEX "^ *LabInfo{")
set(WHITTED_LABS)
foreach(row IN LISTS lab_rows)
  list(LENGTH WHITTED_LABS index)
  math(EXPR number "${index} + 1")
  if(NOT row MATCHES "^ *LabInfo{([0-9]+), \"([0-9][0-9]_[a-z0-9_]+)\", \"[^\"]+\", Stage::[a-z0-9_]+, \"[a-z0-9_ ]+\"},$"
     OR NOT CMAKE_MATCH_1 EQUAL number)
    message(FATAL_ERROR "${WHITTED_LAB_TABLE}: row ${number} of kLabs is not of the form\n"
                        "  LabInfo{${number}, \"NN_stem\", \"title\", Stage::name, \"function function\"},\n"
                        "on one line: ${row}")
  endif()
  list(APPEND WHITTED_LABS ${CMAKE_MATCH_2})
endforeach()
if(NOT WHITTED_LABS)
  message(FATAL_ERROR "${WHITTED_LAB_TABLE}: no rows of kLabs found")
endif()

# The rubric grades exactly these labs and the integration tier, in this order.
function(whitted_check_rubric rubric)
  if(NOT EXISTS ${rubric})
    return()
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${rubric})
  file(READ ${rubric} text)
  string(JSON count ERROR_VARIABLE error LENGTH "${text}" labs)
  if(error)
    message(FATAL_ERROR "${rubric}: ${error}")
  endif()
  set(listed)
  math(EXPR last "${count} - 1")
  foreach(index RANGE ${last})
    string(JSON lab ERROR_VARIABLE error GET "${text}" labs ${index} lab)
    list(APPEND listed "${lab}")
  endforeach()
  set(expected ${WHITTED_LABS} integration)
  if(NOT listed STREQUAL expected)
    string(REPLACE ";" ", " listed "${listed}")
    string(REPLACE ";" ", " expected "${expected}")
    message(FATAL_ERROR "${rubric}: its labs are ${listed}; the lab table (${WHITTED_LAB_TABLE}) "
                        "asks for ${expected}, in that order")
  endif()
endfunction()

# whitted_lab_objects(SET DIR): object libraries SET_<lab> from DIR/<lab>.cpp.
function(whitted_lab_objects set dir)
  foreach(lab IN LISTS WHITTED_LABS)
    whitted_lab_object(${set}_${lab} ${dir}/${lab}.cpp)
  endforeach()
endfunction()

# whitted/labs.hpp precompiled for the lab files, with GCC (single-configuration builds): a lab file compiles in a
# third of the time, which is most of the wait between a student's save and the lab's verdict. It is GCC's own
# lookup, not a forced include: GCC takes lab-pch/whitted/labs.hpp.gch where the file includes whitted/labs.hpp,
# when the .gch was made with the same options, and reads the header otherwise. A lab file compiles exactly as
# without it (a file that forgets the include still fails), as in the grader, which stages the same .gch.
get_property(whitted_multi_config GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND NOT whitted_multi_config)
  set(WHITTED_LAB_PCH ${PROJECT_BINARY_DIR}/lab-pch/whitted/labs.hpp.gch)
else()
  set(WHITTED_LAB_PCH "")
endif()

# whitted_lab_flags(OUT): the compiler flags of a lab file's compile that come from the build type and the
# standard, before its target's options: the .gch below and the grading kit's compile share them.
function(whitted_lab_flags out)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" type)
  separate_arguments(flags UNIX_COMMAND "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${type}} ${CMAKE_CXX20_STANDARD_COMPILE_OPTION}")
  set(${out} ${flags} PARENT_SCOPE)
endfunction()

# whitted_lab_pch(LAB): the rule for WHITTED_LAB_PCH (target whitted_lab_pch), with the options lab object LAB
# compiles with.
function(whitted_lab_pch lab)
  if(NOT WHITTED_LAB_PCH)
    return()
  endif()
  whitted_lab_flags(flags)
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/framework/include/whitted/*.hpp)
  set(wrapper ${PROJECT_BINARY_DIR}/lab-pch/labs_pch.hpp)
  get_filename_component(folder ${WHITTED_LAB_PCH} DIRECTORY)
  file(MAKE_DIRECTORY ${folder})
  file(WRITE ${wrapper} "#include \"whitted/labs.hpp\"\n")
  # The folders a lab file's compile searches (not lab-pch/ itself: the header is read, not an older .gch): the
  # framework's, and GLM's as a system folder, as CMake gives it (no warning from a library's headers), unless it
  # is one of the compiler's own.
  set(includes -I${PROJECT_SOURCE_DIR}/framework/include)
  get_target_property(glm_includes glm::glm INTERFACE_INCLUDE_DIRECTORIES)
  foreach(folder IN LISTS glm_includes)
    if(NOT folder IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES)
      list(APPEND includes -isystem ${folder})
    endif()
  endforeach()
  set(definitions $<TARGET_PROPERTY:${lab},COMPILE_DEFINITIONS>)
  add_custom_command(OUTPUT ${WHITTED_LAB_PCH}
    COMMAND ${CMAKE_CXX_COMPILER} ${flags} $<TARGET_PROPERTY:${lab},COMPILE_OPTIONS>
            "$<$<BOOL:${definitions}>:-D$<JOIN:${definitions},;-D>>" ${includes}
            -x c++-header ${wrapper} -o ${WHITTED_LAB_PCH}
    DEPENDS ${headers} COMMENT "Precompiling whitted/labs.hpp for the lab files" COMMAND_EXPAND_LISTS VERBATIM)
  add_custom_target(whitted_lab_pch DEPENDS ${WHITTED_LAB_PCH})
endfunction()

# whitted_lab_object(TARGET FILE): one lab file as an object library.
function(whitted_lab_object target file)
  add_library(${target} OBJECT ${file})
  target_link_libraries(${target} PUBLIC whitted_framework)
  # Stubs name their parameters for the student but do not use them yet.
  target_compile_options(${target} PRIVATE $<IF:$<CXX_COMPILER_ID:MSVC>,/wd4100,-Wno-unused-parameter>)
  if(WHITTED_LAB_PCH)
    target_include_directories(${target} BEFORE PRIVATE ${PROJECT_BINARY_DIR}/lab-pch)
    add_dependencies(${target} whitted_lab_pch)
    # GCC's dependency file names no header read from the .gch: a new .gch (a framework header changed) recompiles
    # the lab file by this rule.
    set_source_files_properties(${file} PROPERTIES OBJECT_DEPENDS ${WHITTED_LAB_PCH})
  endif()
endfunction()

# whitted_lab_mix(OUT BASE [LAB SET]): the object libraries of every lab from
# set BASE, except LAB, which comes from set SET (or the exact target SET_TARGET
# when SET names an existing target).
function(whitted_lab_mix out base)
  set(lab_under_test "${ARGV2}")
  set(override "${ARGV3}")
  set(result)
  foreach(lab IN LISTS WHITTED_LABS)
    if(lab STREQUAL lab_under_test)
      if(TARGET ${override})
        list(APPEND result ${override})
      else()
        list(APPEND result ${override}_${lab})
      endif()
    else()
      list(APPEND result ${base}_${lab})
    endif()
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The lab number "3" of "03_blinn_phong".
function(whitted_lab_number out lab)
  string(SUBSTRING ${lab} 0 2 number)
  math(EXPR number "${number}")
  set(${out} ${number} PARENT_SCOPE)
endfunction()

# whitted_renderer(TARGET LABS <lab objects> [KERNELS <object>] [COMMANDS <object>] [LIVE_LABS <folder>]):
# the `whitted` program with one implementation of the labs. Without KERNELS it
# links no fast leaf kernels (every intersection goes through the labs' code);
# without COMMANDS, no instructor commands (no `whitted grade`). With LIVE_LABS (the
# folder of its lab files), `whitted explore` rebuilds and re-renders when a lab file
# there is saved: it runs TARGET-explore-worker, the same program built only when
# explore asks for it (framework/app/explore/live_build.hpp says why).
function(whitted_renderer target)
  cmake_parse_arguments(A "" "KERNELS;COMMANDS;LIVE_LABS" "LABS" ${ARGN})
  if(NOT A_KERNELS)
    set(A_KERNELS whitted_no_leaf_kernels)
  endif()
  if(NOT A_COMMANDS)
    set(A_COMMANDS whitted_no_instructor_commands)
  endif()
  whitted_program(${target} "${A_LABS}" ${A_KERNELS} ${A_COMMANDS})
  if(NOT TARGET whitted_explore)
    return()
  endif()
  if(NOT A_LIVE_LABS)
    target_link_libraries(${target} PRIVATE whitted_no_live_build)
    return()
  endif()
  # The worker compiles the lab files into objects of its own: explore rebuilds it on every save, often while the
  # student's own build (make test) compiles the same lab file for `whitted` in the same build folder.
  set(worker ${target}-explore-worker)
  whitted_lab_objects(${target}_explore ${A_LIVE_LABS})
  whitted_lab_mix(worker_labs ${target}_explore)
  set_target_properties(${worker_labs} PROPERTIES EXCLUDE_FROM_ALL ON) # built when explore asks, as the worker
  whitted_program(${worker} "${worker_labs}" ${A_KERNELS} whitted_no_instructor_commands)
  set_target_properties(${worker} PROPERTIES EXCLUDE_FROM_ALL ON)
  target_link_libraries(${worker} PRIVATE whitted_no_live_build)
  set(source ${PROJECT_BINARY_DIR}/explore/${target}_live_build$<CONFIG>.cpp)
  file(GENERATE OUTPUT ${source} CONTENT
"// Written by CMake (whitted_renderer in cmake/WhittedLabs.cmake): the build `whitted explore` rebuilds.
#include \"explore/live_build.hpp\"

namespace whitted {

std::optional<LiveBuild> live_build() {
    return LiveBuild{R\"path(${CMAKE_COMMAND})path\", R\"path(${PROJECT_BINARY_DIR})path\", \"$<CONFIG>\", \"${worker}\",
                     R\"path($<TARGET_FILE:${worker}>)path\", R\"path(${A_LIVE_LABS})path\"};
}

} // namespace whitted
")
  target_sources(${target} PRIVATE ${source})
endfunction()

# whitted_program(TARGET LABS KERNELS COMMANDS): one `whitted` executable (see whitted_renderer).
function(whitted_program target labs kernels commands)
  add_executable(${target} $<TARGET_OBJECTS:whitted_app>)
  target_link_libraries(${target} PRIVATE ${labs} ${kernels} ${commands} whitted_trace whitted_closest_name whitted_framework
                                          whitted_generators CLI11::CLI11)
  if(TARGET whitted_explore)
    target_link_libraries(${target} PRIVATE whitted_explore)
  endif()
  whitted_utf8(${target})
endfunction()

# whitted_utf8(TARGET): on Windows, the program's text and file names are UTF-8, as elsewhere: its
# "ANSI" code page is UTF-8 (framework/app/windows/utf8.manifest), so a path with any letter (a
# user name with accents) reaches it and the files it opens unchanged. Nothing on other systems.
function(whitted_utf8 target)
  if(NOT WIN32)
    return()
  endif()
  set(WHITTED_UTF8_MANIFEST ${PROJECT_SOURCE_DIR}/framework/app/windows/utf8.manifest)
  if(MSVC)
    target_sources(${target} PRIVATE ${WHITTED_UTF8_MANIFEST})
  else() # MinGW: as a resource
    configure_file(${PROJECT_SOURCE_DIR}/framework/app/windows/utf8.rc.in ${PROJECT_BINARY_DIR}/utf8.rc @ONLY)
    target_sources(${target} PRIVATE ${PROJECT_BINARY_DIR}/utf8.rc)
  endif()
endfunction()
