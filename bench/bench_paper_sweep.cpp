// The whole paper sweep (DESIGN.md section 2): n = 2..20 robots x 10 runs, k-means (k = n) on
// 20 000 training descriptors, N = 4541 frames of KITTI 00, d = 128, synthetic descriptors
// (diverse training, as in the paper). A numpy/scikit-learn implementation takes about 180 s.
//   build/algo-rel/bench/bench_paper_sweep --benchmark_filter=PaperSweep/2
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Counters: the stages in CPU-seconds summed over threads (kmeans_cpu_s, distances_cpu_s, ...).
#include <filesystem>

#include <benchmark/benchmark.h>

#include "experiments/data/loaders.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/data/synthetic.h"

namespace dvpr {
namespace {

struct SweepData {
  Dataset deployment;
  DescriptorMatrix training;
};

const SweepData& Data() {
  static const SweepData data = [] {
    SweepData d;
    d.deployment.name = "kitti00_synthetic";
    // CMake passes absolute source paths, so the repository is two levels above this file.
    const auto repo = std::filesystem::path(__FILE__).parent_path().parent_path();
    d.deployment.trajectory = LoadKittiPoses(repo / "data/kitti/00_poses.txt");
    const SyntheticParams params;  // d = 128
    d.deployment.descriptors = SyntheticDeployment(d.deployment.trajectory, params, 1);
    d.training = SyntheticTrainingDiverse(params, SyntheticTrainingParams{.samples = 20000}, 2);
    return d;
  }();
  return data;
}

void BM_PaperSweep(benchmark::State& state) {
  const SweepData& data = Data();
  PaperProtocolParams params;
  for (int n = 2; n <= 20; ++n) params.robots.push_back(n);
  params.runs = 10;
  params.seed = 1;
  params.threads = static_cast<int>(state.range(0));
  PaperProtocolResult result;
  for (auto _ : state) {
    result = RunPaperProtocol(data.deployment, data.training, params);
    benchmark::DoNotOptimize(result.runs.data());
  }
  double fallbacks = 0;
  for (const auto& r : result.runs) fallbacks += static_cast<double>(r.fallback_scans);
  state.counters["runs"] = static_cast<double>(result.runs.size());
  state.counters["ground_truth_cpu_s"] = result.timings.ground_truth_s;
  state.counters["distances_cpu_s"] = result.timings.distances_s;
  state.counters["kmeans_cpu_s"] = result.timings.kmeans_s;
  state.counters["metrics_cpu_s"] = result.timings.metrics_s;
  state.counters["fallback_scans"] = fallbacks;
  state.counters["central_auc"] = result.centralized.auc;
}
BENCHMARK(BM_PaperSweep)->Arg(2)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// One k-means of the sweep's middle size (k = 11) on the 20 000 training descriptors.
void BM_KMeans(benchmark::State& state) {
  const SweepData& data = Data();
  KMeansParams p{.k = static_cast<int>(state.range(0)), .seed = 3};
  int iterations = 0;
  for (auto _ : state) {
    const KMeansResult r = KMeansDetailed(data.training, p);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.centroids.data());
  }
  state.counters["lloyd_iterations"] = iterations;
}
BENCHMARK(BM_KMeans)->Arg(2)->Arg(11)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace dvpr

BENCHMARK_MAIN();
