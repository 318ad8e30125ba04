// The note `dvpr run` prints under an MPI launcher that bound its ranks to fewer cores than the
// machine has (Open MPI binds one core per rank by default for -n 1 and 2: on a 2-core machine
// `mpirun -n 1 dvpr run` took 162 s against 78 s with --bind-to none), and the affinity read.
#include <sched.h>

#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "experiments/mpi/mpi_run_distributor.h"

namespace dvpr {
namespace {

TEST(BoundCoresNote, OnlyWhenTheRanksOnThisMachineCannotUseAllItsCores) {
  EXPECT_EQ(BoundCoresNote(2, 1, 1),
            "dvpr: note: the MPI launcher bound each of the 1 rank(s) on this machine to 1 of its 2 cores; if the "
            "others are free, mpirun --bind-to none (or --map-by slot:PE=N) lets the runs use them\n");
  EXPECT_EQ(BoundCoresNote(2, 1, 2), "");  // 2 ranks x 1 core: all used
  EXPECT_EQ(BoundCoresNote(2, 2, 1), "");  // not bound
  EXPECT_EQ(BoundCoresNote(2, 2, 3), "");  // oversubscribed, not bound
  EXPECT_NE(BoundCoresNote(8, 2, 3), "");  // 6 of 8
  EXPECT_EQ(BoundCoresNote(8, 2, 4), "");
}

// This thread pinned to one CPU reads 1; unpinned again, what it had.
TEST(BoundCores, ReadsTheAffinity) {
  cpu_set_t before;
  CPU_ZERO(&before);
  ASSERT_EQ(::sched_getaffinity(0, sizeof before, &before), 0);
  const int had = BoundCores();
  EXPECT_GE(had, 1);
  EXPECT_LE(had, static_cast<int>(std::thread::hardware_concurrency()));
  int first = 0;
  while (!CPU_ISSET(first, &before)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(::sched_setaffinity(0, sizeof one, &one), 0);
  EXPECT_EQ(BoundCores(), 1);
  ASSERT_EQ(::sched_setaffinity(0, sizeof before, &before), 0);
  EXPECT_EQ(BoundCores(), had);
}

}  // namespace
}  // namespace dvpr
