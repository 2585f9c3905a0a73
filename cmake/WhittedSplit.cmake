# The programs of the grading split (framework/link/lab_link.hpp).
#
# check_<lab>: the lab's tests (public and hidden), the reference for every
#   other lab, and remote_<lab>: the graded lab is answered by a worker.
# check_integration: the whole-renderer tests, every lab answered by a worker.
# A worker: one implementation of the graded lab (or of all six), remote_<lab>
#   for the others, and the worker's main. It holds no reference code.

# The bits 1..6 of a set of lab names.
function(whitted_lab_bits out)
  set(bits 0)
  foreach(lab IN LISTS ARGN)
    whitted_lab_number(number ${lab})
    math(EXPR bits "${bits} | (1 << ${number})")
  endforeach()
  set(${out} ${bits} PARENT_SCOPE)
endfunction()

# whitted_checker(TARGET TESTS_OBJECTS LABS_ANSWERED_BY_THE_WORKER...)
function(whitted_checker target tests)
  whitted_lab_bits(bits ${ARGN})
  add_executable(${target} $<TARGET_OBJECTS:${tests}> ${PROJECT_SOURCE_DIR}/tests/support/checker_main.cpp)
  target_compile_definitions(${target} PRIVATE WHITTED_REMOTE_LABS=${bits})
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

function(whitted_split_programs)
  foreach(lab IN LISTS WHITTED_LABS)
    whitted_lab_number(number ${lab})
    whitted_checker(check_${lab} labtests_${lab} ${lab})
    whitted_worker(worker_${lab}_reference reference ${lab})
    whitted_worker(worker_${lab}_stub student ${lab})
    add_test(NAME split.lab${number}.reference COMMAND check_${lab} --worker=$<TARGET_FILE:worker_${lab}_reference> --gtest_brief=1)
    set_tests_properties(split.lab${number}.reference PROPERTIES LABELS "split;lab${number}" TIMEOUT 120)
    # Every test fails with the untouched stub: none passes.
    add_test(NAME split.lab${number}.stub COMMAND check_${lab} --worker=$<TARGET_FILE:worker_${lab}_stub>)
    set_tests_properties(split.lab${number}.stub PROPERTIES LABELS "split;stub" TIMEOUT 120
                         PASS_REGULAR_EXPRESSION "\\[  PASSED  \\] 0 tests\\.")
  endforeach()
  whitted_checker(check_integration labtests_integration ${WHITTED_LABS})
  whitted_worker(worker_integration_reference reference ${WHITTED_LABS})
  add_test(NAME split.integration.reference COMMAND check_integration --worker=$<TARGET_FILE:worker_integration_reference> --gtest_brief=1)
  set_tests_properties(split.integration.reference PROPERTIES LABELS "split;integration" TIMEOUT 120)
endfunction()
