# The fuzz harnesses and their smoke runs in the test suite: each harness fuzzes its generated
# seeds for ACD_FUZZ_SMOKE_SECONDS. Included by fuzz/CMakeLists.txt (a build with the harnesses)
# and by the top-level CMakeLists.txt otherwise, where the harnesses come from a clang
# sanitizer build next to this one (build-asan/, scripts/build_sanitized.sh).
set(ACD_FUZZ_HARNESSES fuzz_read_off fuzz_read_obj fuzz_read_obj_objects fuzz_read_ply fuzz_read_stl fuzz_read_scene fuzz_decompose)
set(ACD_FUZZ_SMOKE_SECONDS 30 CACHE STRING "Length of each harness's smoke run in the test suite")
# The smoke runs are a regression check, so they do not depend on a random seed: a test suite
# that fails on one run in several proves nothing about the commit. Exploring is fuzz/run.sh
# without -seed (docs/FUZZING.md); its findings go into the seeds once fixed.
set(ACD_FUZZ_SMOKE_SEED 1 CACHE STRING "libFuzzer seed of the smoke runs")

# binary_dir: where the harness executables are; extra_fixture: a fixture that builds them (or "").
function(acd_add_fuzz_smoke_tests binary_dir extra_fixture)
  find_program(ACD_SYSTEM_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
  set(seeds ${PROJECT_BINARY_DIR}/fuzz-seeds)
  add_test(NAME fuzz.seeds COMMAND ${ACD_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/fuzz/make_seeds.py ${seeds})
  set_tests_properties(fuzz.seeds PROPERTIES FIXTURES_SETUP fuzz_seeds LABELS fuzz)
  foreach(harness ${ACD_FUZZ_HARNESSES})
    add_test(NAME fuzz.smoke.${harness}
             COMMAND ${PROJECT_SOURCE_DIR}/fuzz/run.sh ${binary_dir}/${harness} ${seeds}
                     -max_total_time=${ACD_FUZZ_SMOKE_SECONDS} -seed=${ACD_FUZZ_SMOKE_SEED})
    set_tests_properties(fuzz.smoke.${harness} PROPERTIES
                         FIXTURES_REQUIRED "fuzz_seeds;${extra_fixture}" LABELS fuzz TIMEOUT 900
                         ENVIRONMENT FUZZ_ARTIFACTS=${PROJECT_BINARY_DIR}/fuzz-artifacts)
  endforeach()
endfunction()
