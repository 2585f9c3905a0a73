# The programs of the grading split (instructor/link/lab_link.hpp).
#
# check_<lab>: the lab's tests (public and hidden), the reference for every
#   other lab, and remote_<lab>: the graded lab is answered by a worker.
# check_integration: the whole-renderer tests, every lab answered by a worker.
# A worker: one implementation of the graded lab (or of all of them), remote_<lab>
#   for the others, and the worker's main. It holds no reference code.

# The bits 1..N of a set of lab names (lab k is bit k).
function(whitted_lab_bits out)
  set(bits 0)
  foreach(lab IN LISTS ARGN)
    whitted_lab_number(number ${lab})
    math(EXPR bits "${bits} | (1 << ${number})")
  endforeach()
  set(${out} ${bits} PARENT_SCOPE)
endfunction()

# The checkers' main, compiled once; each checker adds the one line that says which labs its worker answers.
add_library(whitted_checker_main OBJECT ${PROJECT_SOURCE_DIR}/instructor/link/checker_main.cpp)
target_link_libraries(whitted_checker_main PUBLIC whitted_link test_support)

# whitted_checker(TARGET TESTS_OBJECTS LABS_ANSWERED_BY_THE_WORKER...)
function(whitted_checker target tests)
  whitted_lab_bits(bits ${ARGN})
  set(remote_labs ${CMAKE_CURRENT_BINARY_DIR}/${target}_remote_labs.cpp)
  file(CONFIGURE OUTPUT ${remote_labs} CONTENT "#include <cstdint>\n\nextern const std::uint32_t whitted_remote_labs = ${bits};\n")
  add_executable(${target} $<TARGET_OBJECTS:${tests}> $<TARGET_OBJECTS:whitted_checker_main> ${remote_labs})
  set(labs)
  foreach(lab IN LISTS WHITTED_LABS)
    if(lab IN_LIST ARGN)
      list(APPEND labs remote_${lab})
    else()
      list(APPEND labs reference_${lab})
    endif()
  endforeach()
  target_link_libraries(${target} PRIVATE ${labs} whitted_link test_support)
endfunction()

# whitted_worker(TARGET SET LABS_IT_ANSWERS...): labs from SET_<lab>, the rest remote.
function(whitted_worker target set)
  set(labs)
  foreach(lab IN LISTS WHITTED_LABS)
    if(lab IN_LIST ARGN)
      list(APPEND labs ${set}_${lab})
    else()
      list(APPEND labs remote_${lab})
    endif()
  endforeach()
  add_executable(${target} $<TARGET_OBJECTS:whitted_worker_main>)
  target_link_libraries(${target} PRIVATE ${labs} whitted_link)
endfunction()

# The link's tests run one at a time (RUN_SERIAL): a checker and its worker
# each want a core, and two pairs on two cores slow each other about twice.
function(whitted_split_programs)
  foreach(lab IN LISTS WHITTED_LABS)
    whitted_lab_number(number ${lab})
    whitted_checker(check_${lab} labtests_${lab} ${lab})
    whitted_worker(worker_${lab}_reference reference ${lab})
    whitted_worker(worker_${lab}_stub student ${lab})
    add_test(NAME split.lab${number}.reference COMMAND check_${lab} --worker=$<TARGET_FILE:worker_${lab}_reference> --gtest_brief=1)
    set_tests_properties(split.lab${number}.reference PROPERTIES LABELS "split;lab${number}" TIMEOUT 600 RUN_SERIAL TRUE)
    # Every test fails with the untouched stub: none passes.
    add_test(NAME split.lab${number}.stub COMMAND check_${lab} --worker=$<TARGET_FILE:worker_${lab}_stub>)
    set_tests_properties(split.lab${number}.stub PROPERTIES LABELS "split;stub" TIMEOUT 600 RUN_SERIAL TRUE
                         PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests\\.")
  endforeach()
  # Workers that attack the link: each must leave the reflection tests failed
  # and the checker saying the link broke (instructor/tests/link/).
  add_executable(raw_hostile_worker ${PROJECT_SOURCE_DIR}/instructor/tests/link/raw_hostile_worker.cpp)
  target_link_libraries(raw_hostile_worker PRIVATE whitted_link)
  whitted_lab_object(hostile_04_reflection ${PROJECT_SOURCE_DIR}/instructor/tests/link/hostile_reflection.cpp)
  whitted_worker(hostile_reflection_worker hostile 04_reflection)
  set(attacks raw:garbage raw:oversized raw:short_reply raw:long_reply raw:goodbye raw:scene_from_worker
              raw:exit0 raw:abort raw:forged_positions lab:later_lab lab:forged_hit lab:own_tracer lab:segfault)
  foreach(attack IN LISTS attacks)
    string(REPLACE ":" ";" parts ${attack})
    list(GET parts 0 kind)
    list(GET parts 1 mode)
    if(kind STREQUAL "raw")
      set(worker raw_hostile_worker)
    else()
      set(worker hostile_reflection_worker)
    endif()
    set(expected "\\[  PASSED  \\] 0 tests\\.")
    if(mode STREQUAL "segfault") # the checker names the call the worker died in
      string(APPEND expected "[^\n]*\n(.|\n)*grading link broken during reflection\\(\\) \\(labs/04_reflection\\.cpp\\)")
    elseif(NOT mode STREQUAL "own_tracer")
      string(APPEND expected "[^\n]*\n(.|\n)*grading (link broken|worker killed|worker exited)")
    endif()
    add_test(NAME split.hostile.${mode}
             COMMAND check_04_reflection --worker=$<TARGET_FILE:${worker}> --gtest_filter=Reflection.*:HiddenReflection.*)
    set_tests_properties(split.hostile.${mode} PROPERTIES LABELS "split;hostile" TIMEOUT 600 RUN_SERIAL TRUE
      ENVIRONMENT WHITTED_HOSTILE=${mode} PASS_REGULAR_EXPRESSION "${expected}")
  endforeach()

  # A worker that asks the checker for a shortcut only the checker asks (a pixel's lens rays, in lab 10's checker,
  # where lab 9 is an earlier lab; a block of pixels): the link breaks and says why.
  foreach(mode wrong_way wrong_way_pixels)
    add_test(NAME split.hostile.${mode} COMMAND check_10_bvh --worker=$<TARGET_FILE:raw_hostile_worker> --gtest_filter=BvhClosestHit.*)
    set_tests_properties(split.hostile.${mode} PROPERTIES LABELS "split;hostile" TIMEOUT 600 RUN_SERIAL TRUE
      ENVIRONMENT WHITTED_HOSTILE=${mode}
      PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests\\.[^\n]*\n(.|\n)*that only the other side makes")
  endforeach()

  # A lab 10 whose walks ask the checker for their answer (lab 1's closest_hit(), the scene's queries):
  # the checker refuses inside a walk, so every walk test fails and the checker names the call.
  whitted_lab_object(hostile_10_bvh ${PROJECT_SOURCE_DIR}/instructor/tests/link/hostile_bvh.cpp)
  whitted_worker(hostile_bvh_worker hostile 10_bvh)
  foreach(attack IN ITEMS walk_by_lab1:BvhClosestHit.*:BvhOccluded.* walk_by_scene:BvhClosestHit.*:BvhOccluded.*
                          box_by_intersect:BoxEntry.*)
    string(REPLACE ":" ";" parts ${attack})
    list(POP_FRONT parts mode)
    list(JOIN parts ":" filter)
    add_test(NAME split.hostile.${mode}
             COMMAND check_10_bvh --worker=$<TARGET_FILE:hostile_bvh_worker> --gtest_filter=${filter})
    set_tests_properties(split.hostile.${mode} PROPERTIES LABELS "split;hostile" TIMEOUT 600 RUN_SERIAL TRUE
      ENVIRONMENT WHITTED_HOSTILE=${mode}
      PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests\\.[^\n]*\n(.|\n)*which grading does not answer inside it")
  endforeach()

  # A lab 10 the handout allows but the reference is not (a median split, a near-first walk written otherwise):
  # every test of lab 10, the walk's cost against the framework's among them, passes on it.
  whitted_lab_object(alternative_10_bvh ${PROJECT_SOURCE_DIR}/instructor/tests/link/median_split_bvh.cpp)
  whitted_worker(median_split_worker alternative 10_bvh)
  add_test(NAME split.alternative.median_split COMMAND check_10_bvh --worker=$<TARGET_FILE:median_split_worker> --gtest_brief=1)
  set_tests_properties(split.alternative.median_split PROPERTIES LABELS "split;lab10" TIMEOUT 600 RUN_SERIAL TRUE)

  whitted_checker(check_integration labtests_integration ${WHITTED_LABS})
  whitted_worker(worker_integration_reference reference ${WHITTED_LABS})
  add_test(NAME split.integration.reference COMMAND check_integration --worker=$<TARGET_FILE:worker_integration_reference> --gtest_brief=1)
  set_tests_properties(split.integration.reference PROPERTIES LABELS "split;integration" TIMEOUT 600 RUN_SERIAL TRUE)
endfunction()

# The grading kit: what `whitted grade` needs to build a worker from a student's
# lab file without this tree. grading-kit.txt names, one item a line, the
# compiler and its arguments for a lab file (those of the labs here), the
# framework's public headers, the libraries and objects a worker links, and the
# checker of every lab. The grader copies the files it names to a folder of its
# own, so that the worker never sees this build. Target grading_parts builds
# them all (the grader brings it up to date before each grading).
function(whitted_grading_kit)
  whitted_lab_flags(flags)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" type)
  separate_arguments(link_flags UNIX_COMMAND "${CMAKE_EXE_LINKER_FLAGS} ${CMAKE_EXE_LINKER_FLAGS_${type}}")
  set(lab student_01_ray_casting)
  set(text "# whitted grade's kit for building workers (instructor/cmake/WhittedSplit.cmake); one item a line\n")
  string(APPEND text "build-type ${CMAKE_BUILD_TYPE}\n")
  string(APPEND text "compiler ${CMAKE_CXX_COMPILER}\n")
  foreach(flag IN LISTS flags)
    string(APPEND text "compile ${flag}\n")
  endforeach()
  string(APPEND text "compile $<JOIN:$<TARGET_PROPERTY:${lab},COMPILE_OPTIONS>,\ncompile >\n")
  string(APPEND text "define $<JOIN:$<TARGET_PROPERTY:${lab},COMPILE_DEFINITIONS>,\ndefine >\n")
  foreach(flag IN LISTS link_flags)
    string(APPEND text "link ${flag}\n")
  endforeach()
  string(APPEND text "link $<JOIN:$<TARGET_PROPERTY:worker_01_ray_casting_stub,LINK_OPTIONS>,\nlink >\n")
  string(APPEND text "link -pthread\n")
  # gold, where the toolchain has it, links a worker in a third of the time of the default linker (11 workers a
  # grading: 0.35 s -> 0.12 s each on the project's machine).
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=gold" WHITTED_HAS_GOLD)
  if(WHITTED_HAS_GOLD)
    string(APPEND text "link -fuse-ld=gold\n")
  endif()
  string(APPEND text "headers ${PROJECT_SOURCE_DIR}/framework/include/whitted\n")
  # The lab files' precompiled whitted/labs.hpp (cmake/WhittedLabs.cmake), made with the same compiler and
  # arguments: a lab file that includes it first compiles in a third of the time.
  if(WHITTED_LAB_PCH)
    string(APPEND text "precompiled ${WHITTED_LAB_PCH}\n")
  endif()
  string(APPEND text "main $<TARGET_OBJECTS:whitted_worker_main>\n")
  set(parts whitted_worker_main whitted_link whitted_channel whitted_framework)
  foreach(lab IN LISTS WHITTED_LABS)
    string(APPEND text "remote ${lab} $<TARGET_OBJECTS:remote_${lab}>\n")
    string(APPEND text "checker ${lab} $<TARGET_FILE:check_${lab}>\n")
    list(APPEND parts remote_${lab} check_${lab})
  endforeach()
  string(APPEND text "checker integration $<TARGET_FILE:check_integration>\n")
  # Libraries last, in link order.
  string(APPEND text "library $<TARGET_FILE:whitted_link>\nlibrary $<TARGET_FILE:whitted_channel>\n")
  string(APPEND text "library $<TARGET_FILE:whitted_framework>\n")
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/grading-kit.txt CONTENT "${text}")
  add_custom_target(grading_parts)
  add_dependencies(grading_parts ${parts} check_integration)
  if(WHITTED_LAB_PCH)
    add_dependencies(grading_parts whitted_lab_pch)
  endif()
endfunction()
