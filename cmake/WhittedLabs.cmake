# The six labs, and how the build mixes implementations of them.
#
# Every lab is one file with the same name in solution/ (the reference), in
# labs/ (the student's) and in tests/mistakes/<lab>/ (catalogued mistakes).
# Each file becomes an object library, so an executable can take lab k from one
# implementation and every other lab from another: that is how one lab is
# graded in isolation.

set(WHITTED_LABS 01_ray_casting 02_shadows 03_blinn_phong 04_reflection 05_refraction 06_fresnel)

# whitted_lab_objects(SET DIR): object libraries SET_<lab> from DIR/<lab>.cpp.
function(whitted_lab_objects set dir)
  foreach(lab IN LISTS WHITTED_LABS)
    whitted_lab_object(${set}_${lab} ${dir}/${lab}.cpp)
  endforeach()
endfunction()

# whitted_lab_object(TARGET FILE): one lab file as an object library.
function(whitted_lab_object target file)
  add_library(${target} OBJECT ${file})
  target_link_libraries(${target} PUBLIC whitted_framework)
  # Stubs name their parameters for the student but do not use them yet.
  target_compile_options(${target} PRIVATE -Wno-unused-parameter)
endfunction()

# whitted_lab_mix(OUT BASE [LAB SET]): the object libraries of all six labs from
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
