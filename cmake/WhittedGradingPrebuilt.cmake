# Grading builds that import, instead of compile, what no submission changes.
#
# Why: `whitted grade` configures this tree into a fresh folder for every
# submission. Compiling the framework, the test support, every lab's tests and
# the reference labs there takes about a minute on two cores, yet only the
# student's six small lab files depend on the submission. The instructor's own
# build (the folder `whitted` is built in) compiles those shared parts anyway,
# from the same tree with the same flags. So that build exports them
# (whitted-grading-prebuilt.cmake, by export(TARGETS)), and a grading configure
# given -DWHITTED_GRADING_PREBUILT=<that build folder> imports them under the
# same target names instead of defining them from sources: the grading build
# then compiles the submission and links, nothing else.
#
# Correctness: the imported files are the instructor build's own, so they must
# be up to date. `whitted grade` first runs
# `cmake --build <folder> --target grading_shared_parts` there (a no-op when
# nothing changed); the grading build depends on the imported files and relinks
# when they change. The import is refused, and the grading build compiles
# everything from source as without the option, when the folder was configured
# from another tree, with another compiler, build type or flags, or lacks one
# of its files; the reason is printed as "whitted grading: ...".

set(WHITTED_PREBUILT_TARGETS_FILE whitted-grading-prebuilt.cmake)
set(WHITTED_PREBUILT_SETTINGS_FILE whitted-grading-prebuilt-settings.cmake)

# The settings that change object code; a grading build imports only from a
# build where they are the same as its own.
function(whitted_prebuilt_settings out)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" config)
  set(${out} PROJECT_SOURCE_DIR CMAKE_BUILD_TYPE CMAKE_CXX_COMPILER CMAKE_CXX_COMPILER_ID CMAKE_CXX_COMPILER_VERSION
             CMAKE_CXX_FLAGS CMAKE_CXX_FLAGS_${config} CMAKE_POSITION_INDEPENDENT_CODE
             CMAKE_INTERPROCEDURAL_OPTIMIZATION CMAKE_SYSROOT PARENT_SCOPE)
endfunction()

# whitted_grading_shared_targets(OUT): the targets every grading build needs
# and no submission changes.
function(whitted_grading_shared_targets out)
  set(targets whitted_framework test_support labtests_integration)
  foreach(lab IN LISTS WHITTED_LABS)
    list(APPEND targets reference_${lab} labtests_${lab})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The target grading_shared_parts: builds the shared targets, unless they are
# imported (then it is empty: the instructor build made them).
function(whitted_grading_shared_parts_target)
  add_custom_target(grading_shared_parts)
  if(NOT WHITTED_PREBUILT)
    whitted_grading_shared_targets(targets)
    add_dependencies(grading_shared_parts ${targets})
  endif()
endfunction()

# Instructor build: writes the export file, and the settings and files it was built with.
function(whitted_export_prebuilt)
  if(CMAKE_CONFIGURATION_TYPES)
    return() # one build type per folder only: the grading build is Release
  endif()
  whitted_grading_shared_targets(targets)
  export(TARGETS ${targets} FILE ${PROJECT_BINARY_DIR}/${WHITTED_PREBUILT_TARGETS_FILE})
  whitted_prebuilt_settings(settings)
  set(text "# How this build's shared grading parts were made (cmake/WhittedGradingPrebuilt.cmake).\n")
  foreach(name IN LISTS settings)
    string(APPEND text "set(WHITTED_PREBUILT_${name} [==[${${name}}]==])\n")
  endforeach()
  set(files)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "OBJECT_LIBRARY")
      list(APPEND files "$<TARGET_OBJECTS:${target}>")
    else()
      list(APPEND files "$<TARGET_FILE:${target}>")
    endif()
  endforeach()
  string(APPEND text "set(WHITTED_PREBUILT_FILES [==[${files}]==])\n")
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/${WHITTED_PREBUILT_SETTINGS_FILE} CONTENT "${text}")
endfunction()

# whitted_import_prebuilt(FOLDER): imports the shared targets from the
# instructor build FOLDER when it is compatible; sets WHITTED_PREBUILT in the
# caller's scope to ON when it did, OFF (with a message) when not.
macro(whitted_import_prebuilt folder)
  set(WHITTED_PREBUILT OFF)
  whitted_prebuilt_refusal(_whitted_refusal "${folder}")
  if(_whitted_refusal)
    message(STATUS "whitted grading: compiling the shared parts here: ${_whitted_refusal}")
  else()
    include(${folder}/${WHITTED_PREBUILT_TARGETS_FILE})
    # The instructor build compiles against these headers as plain (not system) includes; so does the submission.
    set(CMAKE_NO_SYSTEM_FROM_IMPORTED ON)
    set(WHITTED_PREBUILT ON)
    message(STATUS "whitted grading: using the prebuilt shared parts of ${folder}")
  endif()
endmacro()

# Why FOLDER cannot be imported from (into OUT), or empty when it can.
function(whitted_prebuilt_refusal out folder)
  set(settings_file ${folder}/${WHITTED_PREBUILT_SETTINGS_FILE})
  if(NOT EXISTS ${folder}/${WHITTED_PREBUILT_TARGETS_FILE} OR NOT EXISTS ${settings_file})
    set(${out} "${folder} has no ${WHITTED_PREBUILT_TARGETS_FILE} (not an instructor build with tests)" PARENT_SCOPE)
    return()
  endif()
  include(${settings_file})
  whitted_prebuilt_settings(settings)
  foreach(name IN LISTS settings)
    if(NOT "${WHITTED_PREBUILT_${name}}" STREQUAL "${${name}}")
      set(${out} "${folder} has ${name} '${WHITTED_PREBUILT_${name}}', this build '${${name}}'" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  foreach(file IN LISTS WHITTED_PREBUILT_FILES)
    if(NOT EXISTS ${file})
      set(${out} "${file} is missing (build the target grading_shared_parts in ${folder})" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out} "" PARENT_SCOPE)
endfunction()
