# Included by the top-level CMakeLists.txt when DVPR_FUZZ is ON, before any library is added:
# every library the fuzz targets link is compiled with libFuzzer's coverage instrumentation and
# ASan + UBSan, so the fuzzer is guided by our code and a memory error or undefined behaviour
# stops it. The targets themselves are tests/fuzz/CMakeLists.txt; scripts/fuzz.sh builds and runs them.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "DVPR_FUZZ needs clang (libFuzzer is part of clang, not GCC): configure a "
                      "build directory of its own with -DCMAKE_C_COMPILER=clang "
                      "-DCMAKE_CXX_COMPILER=clang++, as scripts/fuzz.sh does")
endif()
if(DVPR_SANITIZE)
  message(FATAL_ERROR "DVPR_FUZZ already builds with ASan + UBSan; leave DVPR_SANITIZE OFF")
endif()
# -fno-sanitize-recover: UBSan aborts at the first report instead of printing and going on, so
# libFuzzer sees it as a crash and keeps the input.
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                    -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)
