# A unity build compiles several source files as one: the headers they share
# (CLI11, nlohmann-json, GLM, the standard library) are compiled once per batch
# instead of once per file, which halves the time to the first picture.
option(WHITTED_UNITY_BUILD "Compile the framework, the command and the grader a few files at a time (a faster first build)" ON)
# whitted_unity(TARGET BATCH): TARGET's sources compiled BATCH at a time.
function(whitted_unity target batch)
  if(WHITTED_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
  endif()
endfunction()
# whitted_unity_apart_from_labs(TARGET): TARGET's sources as two unity files, those
# that call the labs (they include whitted/labs.hpp) and the others, so that a program
# linking the library without labs (the grading link's test workers) pulls no lab call in.
function(whitted_unity_apart_from_labs target)
  if(NOT WHITTED_UNITY_BUILD)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  get_target_property(sources ${target} SOURCES)
  get_target_property(folder ${target} SOURCE_DIR)
  foreach(source IN LISTS sources)
    file(STRINGS ${folder}/${source} calls REGEX "^#include \"whitted/labs.hpp\"")
    set(group without_labs)
    if(calls)
      set(group with_labs)
    endif()
    set_property(SOURCE ${source} DIRECTORY ${folder} PROPERTY UNITY_GROUP ${group})
  endforeach()
endfunction()
