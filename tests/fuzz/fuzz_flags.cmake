# Included by the top-level CMakeLists.txt when DVPR_FUZZ is ON, before any library is added.
# The fuzz targets are built inside the GCC sanitizer build (DVPR_SANITIZE=ON), from the same
# objects the test suite uses, so no file is compiled twice for fuzzing. What libFuzzer needs
# on top:
# - coverage: GCC's -fsanitize-coverage=trace-pc calls __sanitizer_cov_trace_pc in every basic
#   block of the libraries listed below, and fuzz_coverage.cpp turns the caller's address into a
#   libFuzzer "extra counter" (libFuzzer 14 no longer reads trace-pc itself and clang's
#   inline counters are clang's only); trace-cmp hands it the operands of every comparison;
# - the driver: libFuzzer's archive from Debian's libclang-rt-14-dev (built by clang, linked
#   here with g++), its own __sanitizer_cov_trace_pc made weak so fuzz_coverage.cpp's is taken.
# tests/fuzz/CMakeLists.txt makes the targets; scripts/fuzz.sh builds and runs them.
if(NOT DVPR_SANITIZE OR NOT DVPR_BUILD_TESTS)
  message(FATAL_ERROR "DVPR_FUZZ builds the fuzz targets inside the sanitizer test build: "
                      "add -DDVPR_SANITIZE=ON (and keep DVPR_BUILD_TESTS ON), as scripts/test.sh does")
endif()
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  message(FATAL_ERROR "DVPR_FUZZ: the coverage hook (tests/fuzz/fuzz_coverage.cpp) is written for "
                      "GCC's -fsanitize-coverage=trace-pc; configure with g++")
endif()

file(GLOB dvpr_libfuzzer_candidates
     /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-${CMAKE_SYSTEM_PROCESSOR}.a)
list(SORT dvpr_libfuzzer_candidates COMPARE NATURAL ORDER DESCENDING)
list(GET dvpr_libfuzzer_candidates 0 DVPR_LIBFUZZER_ARCHIVE)
if(NOT DVPR_LIBFUZZER_ARCHIVE)
  message(FATAL_ERROR "DVPR_FUZZ: libFuzzer not found (libclang_rt.fuzzer-${CMAKE_SYSTEM_PROCESSOR}.a): "
                      "install libclang-rt-14-dev (scripts/setup.sh does)")
endif()
find_program(DVPR_OBJCOPY objcopy REQUIRED)

# The libraries whose code reads the fuzzed inputs get coverage (cmake/DvprModule.cmake adds the
# flags); the rest of the program runs uninstrumented, so the test suite, which runs the same
# objects, pays only for these. A target fuzzing code of another library adds it here.
set(DVPR_FUZZ_COVERED dvpr_config dvpr_data dvpr_udpm)
set(DVPR_FUZZ_COVERAGE_FLAGS -fsanitize-coverage=trace-pc,trace-cmp)

# The hook every instrumented object calls; in a program without libFuzzer (the tests) it only
# counts. Not instrumented itself.
add_library(dvpr_fuzz_coverage STATIC ${CMAKE_CURRENT_LIST_DIR}/fuzz_coverage.cpp)
target_link_libraries(dvpr_fuzz_coverage PRIVATE dvpr_warnings)
