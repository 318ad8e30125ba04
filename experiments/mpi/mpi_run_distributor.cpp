#include "experiments/mpi/mpi_run_distributor.h"

#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "experiments/mpi/rank_share.h"
#include "experiments/results/safe_output.h"
#include "experiments/results/termination_cleanup.h"
#include "experiments/sweep/run_progress.h"

namespace dvpr {

namespace fs = std::filesystem;

namespace {

// The kind dvpr's exit status tells apart (cli.h ReportError): an input the user can fix
// (std::invalid_argument, std::runtime_error) or a bug.
RankFailure FailureOf(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::invalid_argument& e) {
    return {FailureKind::kInput, e.what()};
  } catch (const std::runtime_error& e) {
    return {FailureKind::kInput, e.what()};
  } catch (const std::exception& e) {
    return {FailureKind::kInternal, e.what()};
  } catch (...) {
    return {FailureKind::kInternal, "an unknown exception"};
  }
}

[[noreturn]] void ThrowFromRank(const RankFailure& failure, int rank, int size) {
  const std::string message = "rank " + std::to_string(rank) + " of " + std::to_string(size) + ": " + failure.message;
  if (failure.kind == FailureKind::kInput) throw std::runtime_error(message);
  throw std::logic_error(message);
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  if (!in) throw std::runtime_error(path.string() + ": cannot read a file this rank's runs wrote");
  return std::move(contents).str();
}

// A file from another rank's run folder, at the same place below out_dir.
void WriteRunFile(const fs::path& out_dir, const RunFile& file) {
  const fs::path rel(file.path);
  if (rel.empty() || rel.is_absolute() || std::find(rel.begin(), rel.end(), "..") != rel.end()) {
    throw std::logic_error("a run file outside the result folder from another rank: '" + file.path + "'");
  }
  // Through the one writer (safe_output.h): each folder below out_dir made or opened without
  // following a link, the file a private temporary renamed into place.
  OutputDir dir = OutputDir::Open(out_dir);
  for (const fs::path& part : rel.parent_path()) dir = dir.Sub(part.string());
  WriteFileAt(dir, rel.filename().string(), file.contents);
}

std::string HostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  return name;
}

// "dvpr-rank<r>-<host>-<pid>": the host in the name, so a temporary folder shared by several
// machines never has a live rank's folder taken for a dead one's.
std::string RunFolderPrefix(int rank) { return "dvpr-rank" + std::to_string(rank) + "-" + HostName() + "-"; }

bool AllDigits(const std::string& s) {
  return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The run folders of this machine's ranks that were killed (SIGKILL, a crash) before removing
// theirs: "dvpr-rank<r>-<host>-<pid>" whose process is gone (with kRemovingSuffix when the kill
// came while the cleanup removed it).
void RemoveStaleRunFolders(const fs::path& temp) {
  const std::string host = "-" + HostName() + "-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(temp, ec)) {
    const std::string name(WithoutRemovingSuffix(entry.path().filename().string()));
    const std::size_t at = name.find(host);
    if (name.rfind("dvpr-rank", 0) != 0 || at == std::string::npos) continue;
    const std::string rank = name.substr(9, at - 9), pid = name.substr(at + host.size());
    if (!AllDigits(rank) || !AllDigits(pid)) continue;
    const auto id = static_cast<pid_t>(std::stol(pid));
    if (id == ::getpid() || ::kill(id, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

}  // namespace

MpiRunDistributor::MpiRunDistributor(const MpiWorld& world) : world_(world) {
  RemoveStaleRunFolders(fs::temp_directory_path());
  if (world.rank() == 0) return;
  run_folder_ = fs::temp_directory_path() / (RunFolderPrefix(world.rank()) + std::to_string(::getpid()));
  // Ended by the launcher (another rank failed), the rank leaves nothing behind.
  std::error_code ec;
  if (!CreateRemovedOnTermination(run_folder_, ec)) {
    KeepOnTermination(run_folder_);
    throw fs::filesystem_error("cannot create this rank's run folder", run_folder_, ec);
  }
}

MpiRunDistributor::~MpiRunDistributor() {
  if (run_folder_.empty()) return;
  std::error_code ignored;
  fs::remove_all(run_folder_, ignored);
  KeepOnTermination(run_folder_);
}

std::vector<RunSpec> MpiRunDistributor::Share(const std::vector<RunSpec>& specs) const {
  std::vector<RunSpec> mine;
  for (const RunSpec& s : specs) {
    if (s.index % static_cast<std::size_t>(world_.size()) == static_cast<std::size_t>(world_.rank())) mine.push_back(s);
  }
  return mine;
}

void MpiRunDistributor::Execute(const std::vector<RunSpec>& specs,
                                const std::map<std::string, RunFunction>& run_functions, const fs::path& out_dir,
                                const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                                const ExecutorOptions& options) const {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (specs[i].index != i) throw std::logic_error("MpiRunDistributor: spec " + std::to_string(i) + " has index " +
                                                    std::to_string(specs[i].index));
  }
  AgreeBeforeStart(nullptr);
  if (world_.rank() == 0) {
    Gather(specs, run_functions, out_dir, consume, options);
  } else {
    Contribute(specs, run_functions, options);
  }
}

void MpiRunDistributor::Contribute(const std::vector<RunSpec>& specs,
                                   const std::map<std::string, RunFunction>& run_functions,
                                   const ExecutorOptions& options) const {
  {
    RankShare share(Share(specs), run_functions, options);
    while (!share.finished()) {
      if (auto out = share.Next(std::chrono::milliseconds(100))) {
        world_.Send(0, RankTag::kOutput, EncodeOutput(out->index, out->output));
      }
    }
  }
  SendRunFiles();
  world_.Send(0, RankTag::kDone, {});
  sent_done_ = true;
}

void MpiRunDistributor::SendRunFiles() const {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(run_folder_)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    world_.Send(0, RankTag::kFile, EncodeFile(RunFile{f.lexically_relative(run_folder_).generic_string(), ReadFile(f)}));
  }
}

void MpiRunDistributor::Gather(const std::vector<RunSpec>& specs,
                               const std::map<std::string, RunFunction>& run_functions, const fs::path& out_dir,
                               const std::function<void(const RunSpec&, RunOutput&&)>& consume,
                               const ExecutorOptions& options) const {
  RankShare share(Share(specs), run_functions, options);
  RunProgress progress(RunCosts(specs, options), options.progress, "runs", std::chrono::steady_clock::now());
  std::map<std::size_t, RunOutput> waiting;  // done, not yet in line
  const auto size = static_cast<std::size_t>(world_.size());
  std::size_t next = 0;
  std::size_t ranks_done = 1;  // this one, once `next` reaches the end
  while (next < specs.size() || ranks_done < size) {
    bool busy = false;
    while (std::optional<RankMessage> m = world_.TryReceive()) {
      busy = true;
      if (m->tag == RankTag::kDone) {
        ++ranks_done;
      } else if (m->tag == RankTag::kFile) {
        WriteRunFile(out_dir, DecodeFile(m->bytes));
      } else if (m->tag == RankTag::kFailure) {
        ThrowFromRank(DecodeFailure(m->bytes), m->source, world_.size());
      } else {
        IndexedOutput out = DecodeOutput(m->bytes);
        if (out.index >= specs.size() || out.index % size != static_cast<std::size_t>(m->source)) {
          throw std::logic_error("rank " + std::to_string(m->source) + " sent run " + std::to_string(out.index) +
                                 ", not one of its share");
        }
        progress.Finished(out.index);
        waiting.emplace(out.index, std::move(out.output));
      }
    }
    try {
      if (std::optional<IndexedOutput> out = share.Next(std::chrono::milliseconds(busy ? 0 : 1))) {
        progress.Finished(out->index);
        waiting.emplace(out->index, std::move(out->output));
      } else if (!busy && share.finished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));  // only other ranks to wait for
      }
    } catch (...) {
      ThrowFromRank(FailureOf(std::current_exception()), 0, world_.size());
    }
    for (auto it = waiting.find(next); it != waiting.end(); it = waiting.find(next)) {
      consume(specs[next], std::move(it->second));
      waiting.erase(it);
      ++next;
    }
  }
}

void MpiRunDistributor::ReportFailure(std::exception_ptr error) const {
  if (world_.rank() == 0 || sent_done_) return;
  try {
    world_.Send(0, RankTag::kFailure, EncodeFailure(FailureOf(error)));
  } catch (...) {
    return;  // rank 0 cannot be told: the caller reports and aborts
  }
  for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(50));  // until rank 0 aborts the job
}

void MpiRunDistributor::AgreeBeforeStart(std::exception_ptr error) const {
  if (agreed_) throw std::logic_error("MpiRunDistributor::AgreeBeforeStart called twice");
  agreed_ = true;
  const int first = world_.FirstFailedRank(error != nullptr);
  if (first == world_.size()) return;
  stopped_before_start_ = true;
  if (world_.rank() == 0) {
    if (first == 0) std::rethrow_exception(error);
    for (;;) {  // the first failed rank sends its error right after the agreement
      if (const std::optional<RankMessage> m = world_.TryReceive(); m && m->tag == RankTag::kFailure && m->source == first) {
        ThrowFromRank(DecodeFailure(m->bytes), first, world_.size());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  if (world_.rank() == first) world_.Send(0, RankTag::kFailure, EncodeFailure(FailureOf(error)));
  throw RanksStoppedBeforeStart();
}

int MachineCores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

int BoundCores() {
  const int cores = MachineCores();
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (::sched_getaffinity(0, sizeof allowed, &allowed) != 0) return cores;
  return std::clamp(CPU_COUNT(&allowed), 1, cores);
}

std::string BoundCoresNote(int machine_cores, int bound_cores, int local_ranks) {
  if (bound_cores >= machine_cores || static_cast<long>(bound_cores) * local_ranks >= machine_cores) return "";
  return "dvpr: note: the MPI launcher bound each of the " + std::to_string(local_ranks) + " rank(s) on this machine to " +
         std::to_string(bound_cores) + " of its " + std::to_string(machine_cores) +
         " cores; if the others are free, mpirun --bind-to none (or --map-by slot:PE=N) lets the runs use them\n";
}

int ThreadsPerRank(const MpiWorld& world, int requested) {
  if (requested > 0) return requested;
  const int cores = MachineCores();
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  // A rank the launcher bound to some cores (srun --cpus-per-task, mpirun --map-by ...:PE=n)
  // has them to itself; an unbound one shares the machine with the other ranks on it.
  if (::sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) < cores) {
    return std::max(1, CPU_COUNT(&allowed));
  }
  return std::max(1, cores / std::max(1, world.local_size()));
}

}  // namespace dvpr
