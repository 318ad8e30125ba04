#pragma once
// The messages between the ranks of a distributed sweep (mpi_run_distributor.h), as bytes: a
// run's output, a file one of its runs wrote, a failure, and "done". Every double travels as its
// 64 bits, so the writing rank writes the very numbers the run computed (the result folder is the
// one a single process writes, byte for byte). A Decode* of bytes that are short or too long
// throws std::logic_error (both ends are the same dvpr). Native byte order: the ranks of one job run the
// same dvpr build on the same kind of machine.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/protocols/run.h"

namespace dvpr {

using Bytes8 = std::vector<std::byte>;

// The message tags.
enum class RankTag : int { kOutput = 1, kFile = 2, kFailure = 3, kDone = 4 };

struct IndexedOutput {
  std::size_t index = 0;  // RunSpec::index
  RunOutput output;
};
Bytes8 EncodeOutput(std::size_t index, const RunOutput& output);
IndexedOutput DecodeOutput(const Bytes8& bytes);

// A file below a rank's run folder: its path relative to it, and its contents.
struct RunFile {
  std::string path;
  std::string contents;
};
Bytes8 EncodeFile(const RunFile& file);
RunFile DecodeFile(const Bytes8& bytes);

// What went wrong on a rank, with the kind of exception it was, so the writing rank throws the
// same kind and dvpr exits with the same status as a single process would (cli.h).
enum class FailureKind : std::int32_t { kInput = 0, kInternal = 1 };
struct RankFailure {
  FailureKind kind = FailureKind::kInternal;
  std::string message;
};
Bytes8 EncodeFailure(const RankFailure& failure);
RankFailure DecodeFailure(const Bytes8& bytes);

}  // namespace dvpr
