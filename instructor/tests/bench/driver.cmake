# End-to-end checks of whitted-bench, run by CTest:
#   cmake -DMODE=smoke|compare|failure -DBENCH=whitted-bench -DWHITTED=whitted -DFAKES=dir -DOUT=dir -P driver.cmake
# smoke: a tiny benchmark without POV-Ray or Embree writes its three files.
# compare: the driver, copied beside stand-ins for the POV-Ray writer, POV-Ray and
#   the Embree harness, fills their columns and ratios.
# failure: a failing Embree harness marks the row failed, is named in one line,
#   and makes the exit code 1 while the rest of the benchmark completes.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(args --flake 1 --size 32 --out "${OUT}/results")
set(env)
if(MODE STREQUAL "smoke")
  set(program "${BENCH}")
  list(APPEND args --tetra 1 --soup 1 --runs 1 --warmup 0 --no-povray --no-embree)
  set(expect_exit 0)
  set(expect "POV-Ray comparison skipped: --no-povray.*\\| flake1 \\|.*\\| tetra1 \\|.*\\| soup1 \\|.*whitted  █")
else()
  # The driver looks for its helpers in its own folder, and for povray on PATH.
  file(COPY "${BENCH}" "${FAKES}/whitted-pov-export" "${FAKES}/povray" "${FAKES}/whitted-embree-rays"
       DESTINATION "${OUT}/bin")
  file(CREATE_LINK "${WHITTED}" "${OUT}/bin/whitted" SYMBOLIC)
  get_filename_component(name "${BENCH}" NAME)
  set(program "${OUT}/bin/${name}")
  list(APPEND args --runs 2 --warmup 1)
  set(env "PATH=${OUT}/bin:$ENV{PATH}")
  if(MODE STREQUAL "compare")
    set(expect_exit 0)
    set(expect "\\| flake1 \\| 12 \\|.*\\| 0\\.250 \\| [0-9.]+× \\| 0\\.00400 \\| [0-9.]+× \\| [0-9,]+ \\| 3,524 \\|")
  else()
    list(APPEND env FAKE_EMBREE_FAIL=1)
    set(expect_exit 1)
    set(expect "\\| flake1 \\(failed\\) \\|.*\\| 0\\.250 \\|.*Embree on flake1 exited with code 3: whitted-embree-rays: no Embree device")
  endif()
endif()
set(COMMAND ${CMAKE_COMMAND} -E env ${env} "${program}" ${args})
set(EXPECT_EXIT ${expect_exit})
set(EXPECT_OUTPUT "${expect}")
include(${CMAKE_CURRENT_LIST_DIR}/../../../tests/cli/expect.cmake) # runs COMMAND, checks the exit code and output; sets `all`
foreach(file results.md results.json chart.svg scenes/flake1.nff images/flake1.png)
  if(NOT EXISTS "${OUT}/results/${file}")
    message(FATAL_ERROR "whitted-bench did not write ${file}\noutput:\n${all}")
  endif()
endforeach()
file(READ "${OUT}/results/chart.svg" svg)
if(NOT svg MATCHES "^<svg .*</svg>\n$")
  message(FATAL_ERROR "chart.svg is not an SVG picture:\n${svg}")
endif()
