// ExecuteRuns names the failed run in its error but keeps the error's kind, so `dvpr run` still
// tells a bug (std::logic_error: exit 3) from an input error (exit 1).
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/sweep/run_executor.h"

namespace dvpr {
namespace {

// Runs one spec (paper, 2 robots, run 0) whose run function throws `thrown`; rethrows what came out.
void RunThrowing(const std::function<void()>& thrown) {
  RunSpec spec;
  spec.protocol = "paper";
  spec.robots = 2;
  spec.run = 0;
  const std::map<std::string, RunFunction> fns{{"paper", [&](const RunSpec&) -> RunOutput {
                                                  thrown();
                                                  return {};
                                                }}};
  ExecuteRuns({spec}, fns, [](const RunSpec&, RunOutput&&) {}, ExecutorOptions{.threads = 1, .progress = false});
}

TEST(RunExecutorErrors, ABugStaysALogicError) {
  try {
    RunThrowing([] { throw std::logic_error("boom"); });
    FAIL() << "no exception";
  } catch (const std::invalid_argument&) {
    FAIL() << "a logic_error came out as an invalid_argument";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()), "run paper n=2 run 0: boom");
  }
}

TEST(RunExecutorErrors, InputErrorsKeepTheirKind) {
  EXPECT_THROW(RunThrowing([] { throw std::invalid_argument("loss.p: bad"); }), std::invalid_argument);
  try {
    RunThrowing([] { throw std::runtime_error("c.npy: truncated"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "run paper n=2 run 0: c.npy: truncated");
  }
}

}  // namespace
}  // namespace dvpr
