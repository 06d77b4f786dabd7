# Sanitizer tests (issue 17), built when SPHV_SANITIZER_TESTS is on (scripts/test.sh, i.e. CI):
# harness_input (parameters, level lists, case names, results, the CSV/SWIFT/H5Part readers,
# scoring) built again with AddressSanitizer + UndefinedBehaviorSanitizer at -O0 (line tables for
# the reports), linked with the uninstrumented sweep and physics objects of this build; the first
# finding ends the test. What runs: the fuzzers of every parser a user reaches in-process (--set
# values, case names, level lists: 26,400 inputs; CSV snapshots 10,000 and SWIFT/GADGET and
# H5Part snapshots 1,000 each, malformed in structure, read and then scored by sod, sedov, noh,
# heat, gravity and evrard) and the result and non-finite tests. Not instrumented here: the
# physics (sph/, cases) and the sweep code; scripts/test-sanitizers.sh instruments everything.
sphv_harness_library(harness_input_sanitized ${INPUT_SOURCES})
if(SPHV_UNITY)  # eight to a unit, as harness_input
  set_target_properties(harness_input_sanitized PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
endif()
# No precompiled header: one with its own flags (-O0, sanitizers) takes longer to build than it
# saves over the two units that would use it.
set(_tests fuzz fuzz_snapshots reliability)
list(TRANSFORM _tests PREPEND ${CMAKE_SOURCE_DIR}/verification/tests/)
list(TRANSFORM _tests APPEND .cpp)
add_executable(sphv_sanitized_tests ${_tests} verification/tests/sanitizer/options.cpp
               $<TARGET_OBJECTS:harness_io> $<TARGET_OBJECTS:harness_physics> $<TARGET_OBJECTS:build_state>)
target_link_libraries(sphv_sanitized_tests PRIVATE harness_input_sanitized catch_main)
if(SPHV_UNITY)  # the test files in one unit: their headers parsed once at -O0
  set_target_properties(sphv_sanitized_tests PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
endif()
target_compile_definitions(sphv_sanitized_tests PRIVATE SPHV_SOURCE_DIR="${CMAKE_SOURCE_DIR}" SPHV_EXE="$<TARGET_FILE:sphv>" SPHV_SANITIZED)
foreach(_target harness_input_sanitized sphv_sanitized_tests)
  target_compile_options(${_target} PRIVATE ${SPHV_FP_FLAGS} ${SPHV_WARNINGS} ${SPHV_SANITIZER_FLAGS} -O0 -g1)
  target_link_options(${_target} PRIVATE ${SPHV_SANITIZER_FLAGS})
endforeach()
# Runtime options: compiled in (verification/tests/sanitizer/options.cpp).
catch_discover_tests(sphv_sanitized_tests TEST_PREFIX "sanitized: " TEST_SPEC "[fuzz]~[cli],[result],[params]"
                     PROPERTIES COST 10)  # started early, as sphv_tests' (CMakeLists.txt)
