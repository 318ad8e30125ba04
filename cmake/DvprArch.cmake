# Which instruction set the code is compiled for: DVPR_ARCH.
#   generic    the compiler's default target (any x86-64; any other architecture).
#   x86-64-v3  AVX2 + FMA + BMI2 throughout (Haswell, Zen and later); the binary
#              stops with SIGILL on an older CPU.
#   dispatch   both: every module twice, the generic `dvpr` and `dvpr-x86-64-v3`
#              beside it; `dvpr` runs the fast one when the CPU can
#              (experiments/arch/dispatch.h), so the build runs on any x86-64 and
#              is as fast as x86-64-v3 where the CPU allows. Costs twice the
#              compile time.
#   host       x86-64-v3 when the CPU of the machine that builds runs it,
#              generic otherwise: one variant, for binaries that stay on this
#              machine (scripts/demo.sh). Its outputs are those of the dispatch
#              build on the same machine, which hands over to the same code.
#   auto       (default) dispatch on x86-64 with a compiler that knows
#              -march=x86-64-v3, generic elsewhere (e.g. ARM): binaries that
#              travel (scripts/build_release.sh).
#
# Why whole programs rather than a few multi-versioned kernels: Eigen chooses its
# packet width and FMA at compile time for a whole translation unit, and GCC
# contracts a*b+c into FMA wherever the target has it, so per-function clones
# (target_clones) would leave Eigen on SSE2 and would not compute what the
# x86-64-v3 build computes. With whole-program variants the fast variant's
# outputs are byte-identical to an x86-64-v3 build's (docs/architecture.md,
# "Instruction sets").
set(DVPR_ARCH "auto" CACHE STRING "generic, x86-64-v3, dispatch, host or auto")
set_property(CACHE DVPR_ARCH PROPERTY STRINGS auto generic x86-64-v3 dispatch host)

include(CheckCXXCompilerFlag)
set(DVPR_FAST_ARCH x86-64-v3)
set(DVPR_FAST_FLAGS -march=x86-64-v3)
set(DVPR_FAST_SUFFIX _v3)
# Interface targets every variant shares (no code of their own to compile twice).
set(DVPR_SHARED_TARGETS dvpr_includes dvpr_warnings dvpr_version dvpr_lcmtypes dvpr_opencv)

# Whether the compiler knows -march=x86-64-v3 (x86-64 only) and, for host, whether this CPU runs
# it: the check experiments/arch/dispatch.cpp makes at run time, made once at configure time.
set(dvpr_fast_compiles OFF)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  check_cxx_compiler_flag(-march=x86-64-v3 DVPR_HAS_X86_64_V3)
  set(dvpr_fast_compiles ${DVPR_HAS_X86_64_V3})
endif()

set(dvpr_arch_resolved ${DVPR_ARCH})
if(DVPR_ARCH STREQUAL "auto")
  set(dvpr_arch_resolved generic)
  if(dvpr_fast_compiles)
    set(dvpr_arch_resolved dispatch)
  endif()
elseif(DVPR_ARCH STREQUAL "host")
  set(dvpr_arch_resolved generic)
  if(dvpr_fast_compiles)
    # The run-time check of experiments/arch/dispatch.cpp, made once per build folder (try_run
    # keeps its result in the cache).
    set(probe ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/dvpr_host_arch.cpp)
    file(WRITE ${probe} "int main() { __builtin_cpu_init(); "
                        "return __builtin_cpu_supports(\"x86-64-v3\") ? 0 : 1; }\n")
    try_run(DVPR_HOST_ARCH_RUN DVPR_HOST_ARCH_COMPILED ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/dvpr_host_arch ${probe})
    if(DVPR_HOST_ARCH_COMPILED AND DVPR_HOST_ARCH_RUN EQUAL 0)
      set(dvpr_arch_resolved x86-64-v3)
    endif()
  endif()
elseif(NOT DVPR_ARCH MATCHES "^(generic|x86-64-v3|dispatch)$")
  message(FATAL_ERROR "DVPR_ARCH=${DVPR_ARCH}: expected auto, generic, x86-64-v3, dispatch or host")
endif()

set(DVPR_DISPATCH OFF)
if(dvpr_arch_resolved STREQUAL "x86-64-v3")
  add_compile_options(${DVPR_FAST_FLAGS})
elseif(dvpr_arch_resolved STREQUAL "dispatch")
  set(DVPR_DISPATCH ON)
endif()
message(STATUS "dvpr: instruction set ${dvpr_arch_resolved} (DVPR_ARCH=${DVPR_ARCH})")
