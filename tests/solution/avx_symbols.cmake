# The AVX kernels' object file (compiled with -mavx) may define one outside
# symbol, whitted::avx_leaf_kernels. Any other (an inline function of a shared
# header, emitted as a weak copy) could be picked by the linker for the whole
# program and run AVX instructions on a CPU without AVX.
# Usage: cmake -DNM=nm "-DOBJECTS=a.o;b.o" -P avx_symbols.cmake
foreach(object IN LISTS OBJECTS)
  if(object MATCHES "leaf_kernels_avx")
    execute_process(COMMAND ${NM} -C --defined-only ${object} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${NM} failed on ${object}")
    endif()
    string(REGEX MATCHALL "[^\n]+" lines "${symbols}")
    set(outside)
    foreach(line IN LISTS lines)
      # Upper-case kinds (and V, u, i, w) are visible outside the object file.
      if(line MATCHES "^[0-9a-f]* [A-Zuvwi] " AND NOT line MATCHES " whitted::avx_leaf_kernels\\(\\)$")
        list(APPEND outside "${line}")
      endif()
    endforeach()
    if(outside)
      list(JOIN outside "\n  " shown)
      message(FATAL_ERROR "the AVX kernels define symbols the rest of the program could pick:\n  ${shown}")
    endif()
    message(STATUS "AVX object defines only whitted::avx_leaf_kernels")
    return()
  endif()
endforeach()
message(FATAL_ERROR "no leaf_kernels_avx object among: ${OBJECTS}")
