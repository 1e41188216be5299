# Sanitizer and fuzzing instrumentation for the whole build (scripts/run_sanitizers.sh,
# fuzz/README.md). Set before any target so that libacd, the tests and the commands all get it:
# a report in an uninstrumented library frame is a report missed.
set(ACD_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(ACD_BUILD_FUZZERS "Build the libFuzzer harnesses in fuzz/ (clang only)" OFF)

if(ACD_SANITIZE)
  # Stop at the first report: a sanitizer finding must fail the run, not scroll past. Line
  # tables are all a report's stack needs; full debug info of CGAL's templates made the heaviest
  # file (alpha_wrap.cpp) take 86 s instead of 66 s to compile.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(ACD_SANITIZE_DEBUG_INFO -gline-tables-only)
  else()
    set(ACD_SANITIZE_DEBUG_INFO -g1)
  endif()
  add_compile_options(-fsanitize=${ACD_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer ${ACD_SANITIZE_DEBUG_INFO})
  add_link_options(-fsanitize=${ACD_SANITIZE} -fno-sanitize-recover=all)
endif()

if(ACD_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ACD_BUILD_FUZZERS needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage feedback from the library too, not only from the harness.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
