#pragma once
// A fresh folder per test for the replay's inputs (messages.csv, config.yaml, a pose file).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace dvpr::replay {

class ReplayFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("replay");
  }
  std::filesystem::path Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  // The message of the std::runtime_error that `fn` throws ("(no error)" if none).
  template <typename Fn>
  static std::string ErrorOf(Fn&& fn) {
    try {
      fn();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::filesystem::path dir_;
};

// messages.csv's header with a column inserted (`extra`) and a trailing `role`, which the reader
// must skip.
inline constexpr const char* kHeader =
    "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,extra,type,payload_bytes,wire_bytes,"
    "dropped,network_variant,network_model,bandwidth_bps,latency_ms,loss,role\n";

}  // namespace dvpr::replay
