// The data files behind the figures (see figures.h). Text files hold gnuplot "index" blocks
// (separated by two blank lines), each with a sibling .titles file naming the blocks in order.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "experiments/figures/figures.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/spread.h"

namespace dvpr {

namespace {

using Points = std::vector<std::pair<double, double>>;
using Series = std::vector<std::pair<std::string, Points>>;  // (title, points), in legend order

void WriteSeries(const std::filesystem::path& data_dir, const std::string& stem,
                 const Series& series) {
  std::ostringstream dat, titles;
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (i > 0) dat << "\n\n";
    dat << "# " << series[i].first << "\n";
    for (const auto& [x, y] : series[i].second) {
      dat << FormatDouble(x) << ' ' << FormatDouble(y) << '\n';
    }
    titles << series[i].first << '\n';
  }
  WriteFileAtomic(data_dir / (stem + ".dat"), dat.str());
  WriteFileAtomic(data_dir / (stem + ".titles"), titles.str());
}

// AUC of a curve by docs/design.md section 2 (for the legend).
double CurveAuc(const PrCurve& c) {
  double auc = 0;
  for (std::size_t k = 1; k < c.recall.size(); ++k) {
    auc += (c.recall[k] - c.recall[k - 1]) * c.precision[k];
  }
  return auc;
}

// Mean of y per x, for the rows `pick` accepts, grouped by `series_of`.
template <typename Pick, typename SeriesOf, typename Value>
Series MeansBy(const std::vector<RunResult>& rows, Pick pick, SeriesOf series_of, Value value) {
  std::vector<std::string> order;
  std::map<std::string, std::map<int, std::pair<double, int>>> acc;
  for (const auto& r : rows) {
    const double v = value(r);
    if (!pick(r) || std::isnan(v)) continue;
    const std::string s = series_of(r);
    if (!acc.contains(s)) order.push_back(s);
    auto& [sum, n] = acc[s][r.key.robots];
    sum += v;
    ++n;
  }
  Series out;
  for (const auto& s : order) {
    Points p;
    for (const auto& [robots, sn] : acc[s]) p.emplace_back(robots, sn.first / sn.second);
    out.emplace_back(s, std::move(p));
  }
  return out;
}

// Per x (robots), the 95 % confidence interval of the mean over the picked rows' values
// (spread.h): "x low high" lines, the mean itself on both sides where fewer than 2 runs count.
template <typename Pick, typename Value>
void WriteConfidenceBand(const std::filesystem::path& file, const std::vector<RunResult>& rows, Pick pick, Value value) {
  std::map<int, std::vector<double>> by_robots;
  for (const auto& r : rows) {
    if (pick(r) && !std::isnan(value(r))) by_robots[r.key.robots].push_back(value(r));
  }
  std::ostringstream dat;
  dat << "# robots, mean - ci95, mean + ci95\n";
  for (const auto& [robots, values] : by_robots) {
    const Spread s = SpreadOf(values);
    const double half = std::isnan(s.ci95) ? 0.0 : s.ci95;
    dat << robots << ' ' << FormatDouble(s.mean - half) << ' ' << FormatDouble(s.mean + half) << '\n';
  }
  WriteFileAtomic(file, dat.str());
}

// Why no row has a relative AUC to plot: no decentralized run, or decentralized runs whose
// reference AUC is 0 or missing (as when no query of the frames revisits a place).
std::string RelativeAucMissing(const std::vector<RunResult>& rows) {
  std::int64_t runs = 0, relevant = 0, known = 0, zero_reference = 0;
  for (const RunResult& r : rows) {
    const ProtocolTraits traits = RowTraits(r.key.protocol);
    if (r.key.strategy != "decentralized" || !(traits.static_evaluation || traits.simulated_network)) continue;
    ++runs;
    if (r.closures) {
      ++known;
      relevant += r.closures->inter_queries + r.closures->intra_queries;
    }
    if (r.auc_reference == 0) ++zero_reference;
  }
  if (runs == 0) return "no decentralized runs";
  const std::string all = std::to_string(runs) + " decentralized run" + (runs == 1 ? "" : "s");
  if (known > 0 && relevant == 0) {
    return all + ", none with a relative AUC: no query had a revisit within the frames";
  }
  if (zero_reference == runs) return all + ", none with a relative AUC: the reference's AUC is 0 in every run";
  return all + ", none with a relative AUC";
}

}  // namespace

std::string NetworkText(const NetworkLabel& network) { return NetworkName(network); }

long ConfusionStep(long frames, long step) {
  return std::max(step, (frames + kConfusionSide - 1) / kConfusionSide);
}

void WriteConfusionData(const std::filesystem::path& data_dir, const DescriptorMatrix& deployment,
                        int wanted_step) {
  const auto step = static_cast<Eigen::Index>(ConfusionStep(static_cast<long>(deployment.rows()), wanted_step));
  const Eigen::Index m = (deployment.rows() + step - 1) / step;
  DescriptorMatrix sample(m, deployment.cols());
  for (Eigen::Index i = 0; i < m; ++i) sample.row(i) = deployment.row(i * step);
  // ||a-b||^2 = |a|^2 + |b|^2 - 2ab, clamped at 0 against rounding.
  const Eigen::VectorXf norms = sample.rowwise().squaredNorm();
  Eigen::MatrixXf d = -2.0f * (sample * sample.transpose());
  d.colwise() += norms;
  d.rowwise() += norms.transpose();
  d = d.cwiseMax(0.0f);
  std::string bytes(static_cast<std::size_t>(m * m) * sizeof(float), '\0');
  // Row-major, little-endian float32: gnuplot's `binary array=(m,m) format='%float32'`.
  Eigen::Map<Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      reinterpret_cast<float*>(bytes.data()), m, m) = d;
  WriteFileAtomic(data_dir / "confusion.f32", bytes);
  WriteFileAtomic(data_dir / "confusion.meta",
                  std::to_string(m) + " " + std::to_string(step) + " " +
                      std::to_string(deployment.rows()) + "\n");
}

void WritePrCurveData(const std::filesystem::path& data_dir, const std::vector<PrCurve>& curves) {
  Series series;
  for (const auto& c : curves) {
    Points p;
    for (std::size_t k = 0; k < c.recall.size(); ++k) p.emplace_back(c.recall[k], c.precision[k]);
    series.emplace_back(c.label + " (n = " + std::to_string(c.robots) + ", AUC " +
                            FormatDouble(CurveAuc(c), 3) + ")",
                        std::move(p));
  }
  WriteSeries(data_dir, "pr_curves", series);
}

void WriteDescriptorDimsData(const std::filesystem::path& data_dir,
                             const DescriptorMatrix& training, const DescriptorMatrix& deployment) {
  auto points = [](const DescriptorMatrix& m) {
    Points p;
    if (m.cols() < 2) return p;
    const Eigen::Index step = std::max<Eigen::Index>(1, m.rows() / 5000);  // keep files small
    for (Eigen::Index i = 0; i < m.rows(); i += step) p.emplace_back(m(i, 0), m(i, 1));
    return p;
  };
  Series series;
  if (training.rows() > 0) {
    series.emplace_back("training (" + std::to_string(training.rows()) + ")", points(training));
  }
  series.emplace_back("deployment (" + std::to_string(deployment.rows()) + ")", points(deployment));
  WriteSeries(data_dir, "descriptor_dims", series);
}

void WriteFigureData(const std::filesystem::path& out_dir, const FigureData& data) {
  const auto dir = out_dir / "figures" / "data";
  std::filesystem::create_directories(dir);
  WriteConfusionData(dir, *data.deployment, 5);
  if (data.curves != nullptr && !data.curves->empty()) WritePrCurveData(dir, *data.curves);
  WriteDescriptorDimsData(dir, *data.training, *data.deployment);
}

bool WriteRelativeAucData(const std::filesystem::path& data_dir,
                          const std::vector<RunResult>& rows, std::string* why) {
  // The paper's figure: the static protocol's decentralized rows; the simulation's if there are
  // none (the first protocol with the trait that has such rows), on its lowest network variant
  // with a relative AUC (variant 0 unless that one has none).
  std::string protocol;
  int variant = 0;
  for (bool ProtocolTraits::*trait : {&ProtocolTraits::static_evaluation, &ProtocolTraits::simulated_network}) {
    const auto has = [&](const RunResult& r) {
      return RowTraits(r.key.protocol).*trait && r.key.strategy == "decentralized" && !std::isnan(r.relative_auc);
    };
    const auto it = std::find_if(rows.begin(), rows.end(), has);
    if (it != rows.end()) {
      protocol = it->key.protocol;
      variant = it->key.network.variant;
      for (const RunResult& r : rows) {
        if (has(r) && r.key.protocol == protocol) variant = std::min(variant, r.key.network.variant);
      }
      break;
    }
  }
  if (protocol.empty()) {
    if (why != nullptr) *why = RelativeAucMissing(rows);
    return false;
  }
  auto pick = [&](const RunResult& r) {
    return r.key.protocol == protocol && r.key.strategy == "decentralized" &&
           r.key.network.variant == variant;
  };
  Points runs_auc, runs_bal;
  for (const auto& r : rows) {
    if (!pick(r)) continue;
    runs_auc.emplace_back(r.key.robots, r.relative_auc);
    runs_bal.emplace_back(r.key.robots, r.worst_balance_ratio);
  }
  auto name = [](const RunResult&) { return std::string("mean"); };
  const Series auc = MeansBy(rows, pick, name, [](const RunResult& r) { return r.relative_auc; });
  const Series bal =
      MeansBy(rows, pick, name, [](const RunResult& r) { return r.worst_balance_ratio; });
  WriteSeries(data_dir, "relative_auc",
              {{"every run", runs_auc}, {"mean over runs", auc.at(0).second}});
  WriteSeries(data_dir, "balance",
              {{"every run", runs_bal}, {"mean over runs", bal.empty() ? Points{} : bal[0].second}});
  WriteConfidenceBand(data_dir / "relative_auc_ci.dat", rows, pick, [](const RunResult& r) { return r.relative_auc; });
  WriteConfidenceBand(data_dir / "balance_ci.dat", rows, pick, [](const RunResult& r) { return r.worst_balance_ratio; });
  // The simulation's numbers depend on its network: the second line names it.
  std::string network;
  for (const RunResult& r : rows) {
    if (pick(r) && RowTraits(protocol).simulated_network && !r.key.network.model.empty()) {
      network = NetworkName(r.key.network) + "\n";
      break;
    }
  }
  WriteFileAtomic(data_dir / "relative_auc.protocol", protocol + "\n" + network);
  return true;
}

}  // namespace dvpr
