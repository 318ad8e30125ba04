#pragma once
// `dvpr agent`: one robot of the team as a process, talking LCM (UDP
// multicast) to the others in wall-clock time (README, "Running real agents").
//
// It loads the same inputs as `dvpr run` and computes the same centroids
// (same config and seed), builds the routing strategy, joins the start
// barrier on DVPR_STATUS (experiments agree on a wall-clock start instant),
// drives a RobotAgent (a BowRobotAgent for the bow_ strategies, docs/bow.md) over
// LcmTransport, and ends when every robot announced
// done or at its deadline (the team's last frame + grace), then writes its
// log (experiments/protocols/lcm/agent_log.h).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "experiments/config/config.h"

namespace dvpr {

inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

// The bounds of the wall-clock flags of `dvpr agent` and `dvpr launch`. Agent time is wall time
// x speedup in int64 nanoseconds: a speedup of at most 10^4 keeps 10 days of wall time and a
// grace of 10^5 s (1.16 days) x 10^4 within it. A larger value was accepted and overflowed the
// clock (the agents never finished).
inline constexpr double kMaxSpeedup = 1e4;
inline constexpr double kMaxWallSeconds = 1e5;
// --hold-bytes of `dvpr agent` and `dvpr launch`: its default and bounds.
inline constexpr std::int64_t kDefaultHoldBytes = std::int64_t{16} << 20;
inline constexpr std::int64_t kMinHoldBytes = std::int64_t{64} << 10;
inline constexpr std::int64_t kMaxHoldBytes = std::int64_t{1} << 30;
// Throws std::invalid_argument naming --hold-bytes unless it is within those bounds.
void CheckHoldBytes(std::int64_t bytes);

// Throws std::invalid_argument naming the flag unless 0 < speedup <= kMaxSpeedup.
void CheckSpeedup(double speedup);
// Throws std::invalid_argument naming `flag` unless low <= seconds <= kMaxWallSeconds (low < seconds
// when `low_open`).
void CheckWallSeconds(const char* flag, double seconds, double low, bool low_open);
// Throws std::invalid_argument unless a team of `robots` can drive `data` (2..frames, at most
// 32767: the LCM messages' int16 robot ids; at most a team plan's count), then keeps a team plan's
// first `robots` robots (FirstRobots), as a sweep's team of that size drives them.
void FitTeamSize(std::int64_t robots, Dataset& data);
// Throws std::invalid_argument "<origin>: network.model: ..." when the config asks for the radio:
// real agents talk over the real network, and do not emulate the radio's range yet, so a run
// would silently be the full mesh.
void CheckRealNetwork(const ExperimentConfig& config, const std::string& origin);

struct AgentProcessOptions {
  std::filesystem::path config;
  std::vector<ConfigOverride> overrides;
  int robot = -1;
  std::optional<int> robots;       // default: the config's first robot count
  int run = 0;
  std::string strategy;            // default: the config's first strategy
  std::string lcm_url = kDefaultLcmUrl;  // udpm only (agents/udpm/udpm_url.h)
  // Mixed into the team key: agents started with other nonces are another team, even of the same
  // config on the same URL. `dvpr launch` draws one per launch; 0 (the default) lets agents
  // started by hand form a team by their config alone.
  std::uint64_t team_nonce = 0;
  // The team's secret (agents/auth/team_secret.h, docs/security.md): a file of 64 hexadecimal
  // digits that only its owner may read. Required: every message the agent sends carries a tag
  // made with it, and it takes only messages whose tag verifies. `dvpr launch` makes a fresh one
  // per launch.
  std::filesystem::path team_secret;
  // What the agent keeps for its channels while it waits for its team (LcmTransport::
  // HoldUntilSubscribed): bytes of authenticated messages, in [64 KiB, 1 GiB].
  std::int64_t hold_bytes = kDefaultHoldBytes;
  double speedup = 1.0;
  std::filesystem::path out;       // default: agent_<strategy>_n<robots>_r<run>_robot<robot>.log
                                   // (its folder must exist: checked before the team starts)
  double grace_s = 2.0;            // wall seconds after the team's last frame before giving up
  double barrier_timeout_s = 120;  // wall seconds to wait for the whole team
  double start_margin_s = 0.3;     // between the last robot ready and the start
  void Validate() const;           // throws std::invalid_argument naming the option
};

// Throws std::invalid_argument naming --lcm unless `url` is a udpm URL a team can use
// (agents/udpm/udpm_url.h): file://, memq:// and the other providers are refused before
// anything is opened.
void CheckLcmUrl(const std::string& url);
// A team nonce as --team-nonce takes it: 1 to 16 hexadecimal digits. Throws std::invalid_argument.
std::uint64_t ParseTeamNonce(const std::string& text);
std::string TeamNonceText(std::uint64_t nonce);

// Parses the arguments after "agent". Throws std::invalid_argument.
AgentProcessOptions ParseAgentArgs(const std::vector<std::string>& args);

// Runs the agent to its end; returns the exit status (0: the log is written,
// whether or not every reply came). Throws on errors before the run.
int RunAgentProcess(const AgentProcessOptions& options, std::ostream& out);

}  // namespace dvpr
