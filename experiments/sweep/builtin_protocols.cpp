// The protocols `dvpr run` knows, by the names of their traits (experiments/results/protocol_traits.h):
// the static paper protocol (experiments/protocols/paper/paper_run.h) and the simulation
// (experiments/protocols/sim/sim_protocol.h).
#include <string>

#include "experiments/protocols/paper/paper_run.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

ProtocolRegistry BuiltinProtocols() {
  ProtocolRegistry registry;
  registry.Add(std::string(kPaperProtocol), MakePaperRun);
  registry.Add(std::string(kSimProtocol), MakeSimRun);
  return registry;
}

}  // namespace dvpr
