#pragma once
// The result files of docs/design.md section 6. Every file is written atomically (a temporary file
// in the same folder, renamed over the target when complete), so a reader or a crashed run never
// leaves a half-written file. Formatting is deterministic and locale-free: integers as they are,
// doubles in the shortest form that reads back to the same double (std::to_chars without a
// precision, e.g. 0.1, 0.8666666666666667, 1e+06), so another tool can compare to the last bit;
// NaN and empty optionals as empty fields, booleans as 0/1.
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "experiments/results/bow_rows.h"
#include "experiments/results/closure_rows.h"
#include "experiments/results/medium_rows.h"
#include "experiments/results/radio_rows.h"
#include "experiments/results/connectivity_rows.h"
#include "experiments/results/results.h"
#include "experiments/results/safe_output.h"  // AtomicFile, WriteFileAtomic

namespace dvpr {

// Creates `dir` (and parents); throws std::runtime_error naming it if that fails.
void CreateOutputDir(const std::filesystem::path& dir);

// CSV headers and rows, one function per file.
extern const char* const kRunsHeader;       // runs.csv
extern const char* const kPerRobotHeader;   // per_robot.csv
extern const char* const kLinksHeader;      // links.csv
extern const char* const kQueriesHeader;    // queries.csv
extern const char* const kMessagesHeader;   // messages.csv
extern const char* const kFailoverHeader;   // failover.csv
std::string CsvRow(const RunResult& r);
std::string CsvRow(const RobotLoadRow& r);
std::string CsvRow(const LinkRow& r);
std::string CsvRow(const QueryRow& r);
std::string CsvRow(const MessageRow& r);
std::string CsvRow(const FailoverRow& r);
// bow.csv and bow_sizes.csv, written only when a bow_ strategy runs (docs/bow.md).
extern const char* const kBowHeader;
extern const char* const kBowSizesHeader;
std::string CsvRow(const BowRow& r);
std::string CsvRow(const BowSizeRow& r);
// When a network variant of the sweep is a radio (docs/network_model.md, "The radio"): radio.csv,
// and per_robot.csv, messages.csv and queries.csv each gain their radio columns at the end
// (relay_transmissions and relay_bytes; hops; hops), for every row of the sweep. Without a radio
// the files are as above.
extern const char* const kRadioHeader;
std::string CsvRow(const RadioRow& r);
// When a network variant contends for its medium (csma, wifi): medium.csv, and per_robot.csv
// gains, after any radio columns, each robot's mac_attempts, mac_backoffs, mac_collisions,
// mac_retries, mac_dropped_queue_full, mac_dropped_retry_limit and airtime_share.
extern const char* const kMediumHeader;
std::string CsvRow(const MediumRow& r);
std::string PerRobotHeader(bool radio, bool mac = false);
std::string CsvRow(const RobotLoadRow& r, bool radio, bool mac = false);
std::string MessagesHeader(bool radio);
std::string CsvRow(const MessageRow& r, bool radio);
// When the sweep runs a team (sim or lcm protocol): closure_pairs.csv.
extern const char* const kClosurePairsHeader;
std::string CsvRow(const ClosurePairRow& r);
std::string QueriesHeader(bool radio);
std::string CsvRow(const QueryRow& r, bool radio);

// Whole files at once (tests, small outputs).
void WriteRunsCsv(const std::filesystem::path& path, const std::vector<RunResult>& rows);
// summary.json: per (protocol, strategy, robots, network variant), in order of first
// appearance, the number of runs and the mean of every runs.csv metric (NaNs skipped; null
// when no run has the metric; the by-role ones only where a network counted them), then
// place_recognition_ratio: broadcast over decentralized PlaceRecognitionBytesPerQuery means.
// A group with runs in `connectivity` (outputs.connectivity) also has the means over those runs
// of connected_time_share and connected_pair_mean_hops (connectivity_rows.h).
std::string SummaryJson(const std::vector<RunResult>& rows, const std::vector<RunConnectivity>& connectivity = {});

// Offered wire bytes of the place-recognition messages (query and reply, every destination
// copy) per query: the quantity of the paper's n - 1 law. NaN without bytes by role.
double PlaceRecognitionBytesPerQuery(const RunResult& r);

// Reads runs.csv back (dvpr plot). Throws naming the file and line on a malformed row.
std::vector<RunResult> ReadRunsCsv(const std::filesystem::path& path);

// Gives each simulated network's row of `rows` (read from `runs_csv`; not the paper protocol's,
// which has none, nor dvpr launch's, whose network is real) its variant's whole label, from the
// variants of the config that made them (VariantLabels, experiments/config/network_variants.h):
// runs.csv's columns name the variant, its model, rate, latency and loss, the label adds what has
// no column (propagation, range, next hop). Throws, naming the file and the row's line, when a
// row's variant is not among `networks` or differs from it in a column (another config's folder).
void LabelNetworks(std::vector<RunResult>& rows, std::span<const NetworkLabel> networks,
                   const std::filesystem::path& runs_csv);
// Whether two labels agree in what the result files' network columns hold (model, rate, latency,
// loss; NaN equals NaN): a row read back against its config's variant.
bool SameNetworkColumns(const NetworkLabel& a, const NetworkLabel& b);

// Number formatting shared with the figures' data files: the shortest decimal that reads back
// to exactly `v` ("" for NaN, 0 for -0).
std::string FormatDouble(double v);
// Fixed notation with `decimals` decimals, for labels and axes only (it rounds: never for data).
std::string FormatDouble(double v, int decimals);

}  // namespace dvpr
