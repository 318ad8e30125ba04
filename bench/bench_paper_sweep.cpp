// The whole paper sweep (docs/design.md section 2): n = 2..20 robots x 10 runs, k-means (k = n) on
// 20 000 training descriptors, N = 4541 frames of KITTI 00, d = 128, synthetic descriptors
// (diverse training, as in the paper). A numpy/scikit-learn implementation takes about 180 s.
//   build/release/bench/bench_paper_sweep --benchmark_filter=PaperSweep/2
//       --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The sweep goes through RunSweep, the driver `dvpr run` uses (the executor with the built-in
// paper protocol), on inputs made here instead of loaded from a config's files.
#include <filesystem>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/bench_main.h"

#include "agents/algorithms/kmeans.h"
#include "experiments/config/config.h"
#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/synthetic.h"
#include "experiments/sweep/run_sweep.h"

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
    // The source tree from CMake (absolute), so the benchmark runs from any directory.
    const std::filesystem::path repo(DVPR_SOURCE_DIR);
    d.deployment.trajectory = LoadKittiPoses(repo / "data/kitti/00_poses.txt");
    const SyntheticParams params;  // d = 128
    d.deployment.descriptors = SyntheticDeployment(d.deployment.trajectory, params, 1);
    d.training = SyntheticTrainingDiverse(params, SyntheticTrainingParams{.samples = 20000}, 2);
    return d;
  }();
  return data;
}

// The paper protocol's decentralized strategy, robots 2..20, 10 runs, seed 1, r = 5 m, window 250.
const ExperimentConfig& SweepConfig() {
  static const ExperimentConfig config = ParseConfig(
      "robots: {from: 2, to: 20}\nruns: 10\nseed: 1\nprotocols: [paper]\nstrategies: [decentralized]\n"
      "evaluation: {gt_radius_m: 5, suppression_frames: 250}\noutputs: {figures: false}\n",
      std::filesystem::current_path(), {}, "bench_paper_sweep");
  return config;
}

void BM_PaperSweep(benchmark::State& state) {
  SharedInputs inputs;  // no out_dir: the centroids are not written
  inputs.config = &SweepConfig();
  inputs.deployment = Data().deployment;
  inputs.training = Data().training;
  const ExecutorOptions options{.threads = static_cast<int>(state.range(0)), .progress = false};
  std::vector<RunOutput> outputs;
  for (auto _ : state) {
    outputs = RunSweepInMemory(inputs, options);
    benchmark::DoNotOptimize(outputs.data());
  }
  double relative_auc = 0;
  for (const auto& out : outputs) relative_auc += out.runs.at(0).relative_auc;
  state.counters["runs"] = static_cast<double>(outputs.size());
  state.counters["central_auc"] = outputs.at(0).runs.at(0).auc_reference;
  state.counters["mean_relative_auc"] = relative_auc / static_cast<double>(outputs.size());
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

DVPR_BENCHMARK_MAIN()
