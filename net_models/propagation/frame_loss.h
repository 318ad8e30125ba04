#pragma once
// A loss process for the frames of one directed pair (ns-3's ErrorModel:
// public IsLost -> private DoIsLost). ReceptionLoss keeps one per pair, so a
// stateful process (Gilbert-Elliott) has its own state on every pair and
// pairs can use different processes (per-pair overrides).
#include <cstdint>
#include <memory>
#include <string_view>

#include "sim/random.h"

namespace dvpr {

class FrameLoss {
 public:
  virtual ~FrameLoss() = default;
  // Decides the fate of the next frame on this pair, drawing from rng.
  bool IsLost(RandomStream& rng) {
    ++frames_;
    const bool lost = DoIsLost(rng);
    lost_ += lost ? 1 : 0;
    return lost;
  }
  std::string_view Name() const { return DoName(); }
  std::uint64_t Frames() const { return frames_; }
  std::uint64_t Lost() const { return lost_; }

 private:
  virtual bool DoIsLost(RandomStream& rng) = 0;
  virtual std::string_view DoName() const = 0;

  std::uint64_t frames_ = 0;
  std::uint64_t lost_ = 0;
};

}  // namespace dvpr
