#pragma once
// main() of every benchmark: BENCHMARK_MAIN, after the generic build of a dispatching build
// (cmake/DvprArch.cmake) has handed over to its fast sibling where the CPU runs it, so a
// benchmark measures what `dvpr` runs.
#include <benchmark/benchmark.h>

#include "experiments/arch/dispatch.h"

#ifdef DVPR_FAST_EXECUTABLE
#define DVPR_EXEC_FASTEST(argv) dvpr::ExecFastestVariant(argv, DVPR_FAST_EXECUTABLE)
#else
#define DVPR_EXEC_FASTEST(argv) static_cast<void>(argv)
#endif

#define DVPR_BENCHMARK_MAIN()                                       \
  int main(int argc, char** argv) {                                 \
    DVPR_EXEC_FASTEST(argv);                                        \
    ::benchmark::Initialize(&argc, argv);                           \
    if (::benchmark::ReportUnrecognizedArguments(argc, argv)) return 1; \
    ::benchmark::RunSpecifiedBenchmarks();                          \
    ::benchmark::Shutdown();                                        \
    return 0;                                                       \
  }
