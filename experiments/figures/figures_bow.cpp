// Figure 9 (see figures.h): the bag-of-words comparison of docs/bow.md. Its data come from
// runs.csv (relative AUC, paper protocol), bow.csv (query bytes, votes) and bow_sizes.csv
// (partial-query sizes), all written only when a bow_ strategy ran; its data files go through
// the one writer (safe_output.h), as every figure's do.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "experiments/figures/figures.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/safe_output.h"
#include "experiments/results/spread.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// The designs compared, in legend order, with their legend text.
const std::pair<const char*, const char*> kDesigns[] = {
    {"decentralized", "global descriptor, decentralized"},
    {"broadcast", "global descriptor, broadcast"},
    {"bow_decentralized", "BoW inverted index, word mod n"},
    {"bow_decentralized_df", "BoW inverted index, load-aware (df)"},
    {"bow_broadcast", "BoW broadcast"}};
constexpr const char* kColours[5] = {"#1f77b4", "#7fb4e0", "#d62728", "#ff7f0e", "#f0a0a0"};
// Broadcasts are dashed: both reach relative AUC 1, and the dashes let the line under show through.
constexpr int kDashes[5] = {1, 2, 1, 1, 1};

// A CSV file as rows of named fields (the result files hold no quoted commas).
std::vector<std::map<std::string, std::string>> ReadCsv(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    if (header.empty()) {
      header = fields;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    rows.push_back(std::move(row));
  }
  return rows;
}

double Number(const std::map<std::string, std::string>& row, const std::string& key) {
  const auto it = row.find(key);
  if (it == row.end() || it->second.empty()) return kNotApplicable;
  return std::stod(it->second);
}

// Mean over runs per (strategy, n) of one value.
using Means = std::map<std::pair<std::string, int>, std::pair<double, int>>;
void Add(Means& m, const std::string& strategy, int robots, double v) {
  if (std::isnan(v)) return;
  auto& [sum, count] = m[{strategy, robots}];
  sum += v;
  ++count;
}

std::string Mean(const Means& m, const std::string& strategy, int robots) {
  const auto it = m.find({strategy, robots});
  return it == m.end() ? std::string("NaN") : FormatDouble(it->second.first / it->second.second);
}

// Each run's value per (strategy, n), for the spread of the relative AUC (spread.h).
using Values = std::map<std::pair<std::string, int>, std::vector<double>>;

// The mean over the runs and the half-width of its 95 % confidence interval, NaN where it did
// not run (the half-width NaN below 2 runs).
std::string MeanAndHalfWidth(const Values& v, const std::string& strategy, int robots) {
  const auto it = v.find({strategy, robots});
  const Spread s = it == v.end() ? Spread{} : SpreadOf(it->second);
  return (std::isnan(s.mean) ? "NaN" : FormatDouble(s.mean)) + " " + (std::isnan(s.ci95) ? "NaN" : FormatDouble(s.ci95));
}

// One line per n, then `cell` of each design (its column or columns).
void WriteTable(const fs::path& file, const std::set<int>& robots, const std::string& what,
                const std::function<std::string(const std::string&, int)>& cell) {
  std::ostringstream out;
  out << "# n, then " << what << " of:";
  for (const auto& [name, title] : kDesigns) out << ' ' << name;
  out << '\n';
  for (int n : robots) {
    out << n;
    for (const auto& [name, title] : kDesigns) out << ' ' << cell(name, n);
    out << '\n';
  }
  WriteFileAtomic(file, out.str());
}

// Partial-query sizes of bow_decentralized at up to four n, in bins of 5 words (40 bytes):
// one block per n, x = bin centre in bytes, y = share of that n's messages.
std::vector<int> WriteSizes(const fs::path& data_dir, const fs::path& out_dir) {
  std::map<int, std::map<std::int64_t, double>> bins;  // n -> bin -> messages (run 0)
  for (const auto& row : ReadCsv(out_dir / "bow_sizes.csv")) {
    if (row.at("strategy") != "bow_decentralized" || !RowTraits(row.at("protocol")).static_evaluation ||
        row.at("run") != "0") {
      continue;
    }
    const int n = std::stoi(row.at("robots"));
    const std::int64_t words = (std::stoll(row.at("payload_bytes")) - 26) / 8;
    bins[n][words / 5] += std::stod(row.at("messages"));
  }
  std::vector<int> shown;
  for (int n : {2, 5, 10, 20}) if (bins.contains(n)) shown.push_back(n);
  for (auto it = bins.begin(); shown.size() < 3 && it != bins.end(); ++it) {
    if (std::find(shown.begin(), shown.end(), it->first) == shown.end()) shown.push_back(it->first);
  }
  std::sort(shown.begin(), shown.end());
  std::ostringstream out;
  for (int n : shown) {
    double total = 0;
    for (const auto& [bin, count] : bins[n]) total += count;
    out << "# n = " << n << ": bin centre (bytes), share of messages\n";
    for (const auto& [bin, count] : bins[n]) out << 26 + 8 * (5 * bin + 2) << ' ' << FormatDouble(count / total) << '\n';
    out << "\n\n";
  }
  WriteFileAtomic(data_dir / "bow_sizes.dat", out.str());
  return shown;
}

}  // namespace

bool WriteBowComparisonData(const fs::path& out_dir, const fs::path& data_dir, const std::vector<RunResult>& rows) {
  if (!fs::exists(out_dir / "bow.csv")) return false;
  Means auc, bytes, vote;
  Values auc_runs;
  std::set<int> robots;
  for (const RunResult& r : rows) {
    if (!RowTraits(r.key.protocol).static_evaluation) continue;
    Add(auc, r.key.strategy, r.key.robots, r.relative_auc);
    if (!std::isnan(r.relative_auc)) auc_runs[{r.key.strategy, r.key.robots}].push_back(r.relative_auc);
    robots.insert(r.key.robots);
  }
  for (const auto& row : ReadCsv(out_dir / "bow.csv")) {
    if (!RowTraits(row.at("protocol")).static_evaluation) continue;
    const int n = std::stoi(row.at("robots"));
    Add(bytes, row.at("strategy"), n, Number(row, "query_bytes_per_query"));
    Add(vote, row.at("strategy"), n, Number(row, "vote_not_centralized_fraction"));
  }
  if (robots.empty()) return false;
  const auto mean_of = [](const Means& m) {
    return [&m](const std::string& design, int n) { return Mean(m, design, n); };
  };
  WriteTable(data_dir / "bow_auc.dat", robots, "mean relative AUC (paper protocol)", mean_of(auc));
  WriteTable(data_dir / "bow_auc_ci.dat", robots, "relative AUC (paper protocol) (mean, 95 % CI half-width)",
             [&](const std::string& design, int n) { return MeanAndHalfWidth(auc_runs, design, n); });
  WriteTable(data_dir / "bow_bytes.dat", robots, "mean query bytes per query", mean_of(bytes));
  WriteTable(data_dir / "bow_vote.dat", robots, "share of votes not the centralized BoW best", mean_of(vote));
  std::string titles;
  for (int n : WriteSizes(data_dir, out_dir)) titles += std::to_string(n) + '\n';
  WriteFileAtomic(data_dir / "bow_sizes.titles", titles);
  return true;
}

std::string BowComparisonScript(const fs::path& data_dir, const fs::path& png) {
  std::string s = "set terminal pngcairo size 1400,1000 font 'DejaVu Sans,11' noenhanced\n"
                  "set output (exists('dvpr_output') ? dvpr_output : " +  // as Preamble (figures.cpp)
                  GnuplotQuote("../" + png.filename().string()) +
                  ")\nset grid lc rgb '#dddddd'\nset key box opaque\nset multiplot layout 2,2\nset xlabel 'robots n'\n";
  const auto lines = [](const std::string& dat, const std::vector<int>& columns) {
    std::string p = "plot ";
    for (int c : columns) {
      const auto i = static_cast<std::size_t>(c - 2);
      p += std::string(c == columns.front() ? "" : ", ") + "'" + dat + "' using 1:" + std::to_string(c) +
           " with linespoints lw 2 pt 7 ps 0.7 dt " + std::to_string(kDashes[i]) + " lc rgb '" + kColours[i] +
           "' title '" + kDesigns[i].second + "'";
    }
    return p + "\n";
  };
  // The mean's 95 % confidence interval as bars in the line's colour (bow_auc_ci.dat: mean and
  // half-width per design), drawn under the lines.
  std::string auc_plot = "plot ";
  for (std::size_t i = 0; i < std::size(kDesigns); ++i) {
    auc_plot += "'bow_auc_ci.dat' using 1:" + std::to_string(2 + 2 * i) + ":" + std::to_string(3 + 2 * i) +
                " with yerrorbars ps 0 lw 1 lc rgb '" + kColours[i] + "' notitle, ";
  }
  auc_plot += lines("bow_auc.dat", {2, 3, 4, 5, 6}).substr(5);  // after its "plot "
  auc_plot.pop_back();  // the newline
  s += "set title 'Relative AUC (static protocol; BoW against centralized BoW, global against centralized global)'."
       "\"\\n\".'mean over runs, bars: its 95 % confidence interval'\n"
       "set ylabel 'relative AUC'\nset yrange [0:1.05]\nset key bottom left\n" +
       auc_plot + "\n";
  // The seed paper's sizes as reference lines: BoW's distributed query, 16 kB (about 2000 words
  // of 8 bytes) plus the overhead of sending to n robots, and NetVLAD's, 512 bytes to one robot.
  std::string bytes_plot = lines("bow_bytes.dat", {2, 3, 4, 5, 6});
  bytes_plot.pop_back();  // the newline
  bytes_plot += ", " + std::to_string(kSeedBowQueryBytes) + " with lines lw 1.5 dt 3 lc rgb '" + kColours[2] +
                "' title 'seed paper: BoW query, 16 kB', " + std::to_string(kSeedGlobalQueryBytes) +
                " with lines lw 1.5 dt 3 lc rgb '" + kColours[0] + "' title 'seed paper: NetVLAD query, 512 B'\n";
  // The top three decades are left to the key's seven lines, above every data line (BoW broadcast:
  // 300 kB at n = 20 at 2000 words a frame; with two decades the key covered it from n = 5 to 10).
  s += "set title 'Query bytes per query (encoded payload, no replies or verification; log scale)'\n"
       "set ylabel 'bytes per query'\nset yrange [100:100000000]\nset logscale y\nset key top left\n" +
       bytes_plot + "unset logscale y\n";
  std::ifstream titles(data_dir / "bow_sizes.titles");
  std::vector<std::string> ns;
  for (std::string n; std::getline(titles, n);) ns.push_back(n);
  s += "set title 'Partial-query sizes, bow_decentralized (bins of 5 words)'\nset xlabel 'bow_query_t bytes'\n"
       "set ylabel 'share of partial queries'\nset yrange [0:*]\nset logscale x\nset key top right\nplot ";
  for (std::size_t i = 0; i < ns.size(); ++i) {
    s += std::string(i ? ", " : "") + "'bow_sizes.dat' index " + std::to_string(i) +
         " using 1:2 with steps lw 2 title " + GnuplotQuote("n = " + ns[i]);
  }
  s += (ns.empty() ? "NaN notitle" : "") + std::string("\nunset logscale x\nset xlabel 'robots n'\n");
  s += "set title 'Vote (step 4) returns another frame than the centralized BoW best'\n"
       "set ylabel 'share of queries'\nset yrange [0:1]\nset key bottom right\n" +
       lines("bow_vote.dat", {4, 5}) + "unset multiplot\n";
  return s;
}

}  // namespace dvpr
