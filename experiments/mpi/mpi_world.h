#pragma once
// The MPI job this process is part of, or a world of one. dvpr joins MPI only when an MPI
// launcher started it (mpirun, srun: their environment says so), so a plain `dvpr run` neither
// initialises MPI nor needs an MPI library to be reachable; a dvpr built without MPI refuses to
// run as one of several ranks (each would write the whole folder). Only the thread that made the
// world calls MPI (MPI_THREAD_FUNNELED): the runs have threads of their own.
#include <cstddef>
#include <optional>

#include "experiments/mpi/rank_messages.h"

namespace dvpr {

struct RankMessage {
  int source = 0;
  RankTag tag = RankTag::kDone;
  Bytes8 bytes;
};

class MpiWorld {
 public:
  // Joins the job (MPI_Init_thread) when an MPI launcher started this process. Throws
  // std::runtime_error when it did, with more than one rank, and this dvpr has no MPI.
  MpiWorld();
  // MPI_Finalize.
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The ranks on this machine (this one included): they share its cores.
  int local_size() const { return local_size_; }
  bool distributed() const { return size_ > 1; }
  // Started by an MPI launcher (and joined the job), one rank or more.
  bool joined() const { return joined_; }

  // Blocks until `bytes` may be reused (the receiver may not have them yet).
  void Send(int dest, RankTag tag, const Bytes8& bytes) const;
  // A message from any rank that has arrived, received; nullopt when none has.
  std::optional<RankMessage> TryReceive() const;
  // A collective: every rank calls it once at the same point. The lowest rank that passed
  // `failed` true, or size() when none did (MPI_Allreduce, MPI_MIN).
  int FirstFailedRank(bool failed) const;
  // Ends every rank of the job with `status` (MPI_Abort): what a rank does when the job failed
  // and the others may be waiting for it.
  [[noreturn]] void Abort(int status) const;

 private:
  bool joined_ = false;
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
};

// True when an MPI launcher started this process (Open MPI's mpirun, or PMI/PMIx as srun sets).
bool StartedByMpiLauncher();

// This process's rank as the launcher's environment gives it (before MPI is joined), 0 when it
// gives none: a usage error found before joining is printed by rank 0 only.
int LauncherRank();

}  // namespace dvpr
