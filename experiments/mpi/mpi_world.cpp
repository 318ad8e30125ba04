#include "experiments/mpi/mpi_world.h"

#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef DVPR_HAVE_MPI
// The C API only: the C++ bindings (removed from MPI 3) would need libmpi_cxx.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace dvpr {

bool StartedByMpiLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

int LauncherRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    const char* value = std::getenv(name);
    if (value == nullptr) continue;
    char* end = nullptr;
    const long rank = std::strtol(value, &end, 10);
    if (end != value && *end == '\0' && rank >= 0) return static_cast<int>(rank);
  }
  return 0;
}

#ifdef DVPR_HAVE_MPI

namespace {

void Check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string(call) + ": " + std::string(text, static_cast<std::size_t>(length)));
}

}  // namespace

MpiWorld::MpiWorld() {
  if (!StartedByMpiLauncher()) return;
  int provided = 0;
  Check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  joined_ = true;
  // A failed call throws here rather than ending the job at once: dvpr then reports it and
  // aborts the job itself (RunOnRanks).
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  Check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local),
        "MPI_Comm_split_type");
  MPI_Comm_size(local, &local_size_);
  MPI_Comm_free(&local);
}

MpiWorld::~MpiWorld() {
  if (joined_) MPI_Finalize();
}

void MpiWorld::Send(int dest, RankTag tag, const Bytes8& bytes) const {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
    throw std::runtime_error("a message of " + std::to_string(bytes.size()) +
                             " bytes for rank " + std::to_string(dest) + " is over MPI's 2 GiB count");
  }
  Check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, static_cast<int>(tag),
                 MPI_COMM_WORLD), "MPI_Send");
}

std::optional<RankMessage> MpiWorld::TryReceive() const {
  int arrived = 0;
  MPI_Status status;
  Check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status), "MPI_Iprobe");
  if (arrived == 0) return std::nullopt;
  int count = 0;
  Check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
  RankMessage m{status.MPI_SOURCE, static_cast<RankTag>(status.MPI_TAG), Bytes8(static_cast<std::size_t>(count))};
  Check(MPI_Recv(m.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE), "MPI_Recv");
  return m;
}

int MpiWorld::FirstFailedRank(bool failed) const {
  const int mine = failed ? rank_ : size_;
  int first = size_;
  Check(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
  return first;
}

void MpiWorld::Abort(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);  // MPI_Abort does not return; should it, end this rank at least
}

#else  // no MPI in this build: a world of one

MpiWorld::MpiWorld() {
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size == nullptr) size = std::getenv("PMI_SIZE");
  if (size != nullptr && std::string(size) != "1") {
    throw std::runtime_error("started as one of " + std::string(size) + " MPI ranks, but this dvpr was "
                             "built without MPI (install libopenmpi-dev and rebuild, or run it without mpirun)");
  }
}

MpiWorld::~MpiWorld() = default;

void MpiWorld::Send(int, RankTag, const Bytes8&) const {
  throw std::logic_error("MpiWorld::Send in a dvpr built without MPI");
}

std::optional<RankMessage> MpiWorld::TryReceive() const { return std::nullopt; }

int MpiWorld::FirstFailedRank(bool failed) const { return failed ? 0 : 1; }

void MpiWorld::Abort(int status) const { std::_Exit(status); }

#endif

}  // namespace dvpr
