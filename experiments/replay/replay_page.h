#pragma once
// The replay as one self-contained HTML page: the template (replay_page.html,
// hand-written JS drawing on canvas, compiled into dvpr) with the run's data
// put in as JSON. Nothing is loaded when the page opens.
//
// The data holds only what the page draws, compactly (docs/replay.md):
// positions in decimetres, one per frame and robot; times in microseconds,
// each message as five integers (time since the previous message's send,
// latency or -1 dropped / -2 never delivered, src, dst, kind), where a kind
// indexes a short table of (role, counted bytes, queue effect).
#include <string>

#include "experiments/replay/replay_messages.h"
#include "experiments/replay/replay_tracks.h"

namespace dvpr::replay {

// The JSON the page reads (ASCII; '<' escaped so it cannot close its script element).
std::string PageData(const ReplayRun& run, const Tracks& tracks);

// The whole page.
std::string ReplayPage(const ReplayRun& run, const Tracks& tracks);

// The page's template, with kDataPlaceholder where PageData goes (generated from
// replay_page.html at build time).
extern const char* const kPageTemplate;
inline constexpr const char* kDataPlaceholder = "{{REPLAY_DATA}}";

}  // namespace dvpr::replay
