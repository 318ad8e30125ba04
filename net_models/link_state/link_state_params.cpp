#include "net_models/link_state/link_state_params.h"

#include "net_models/core/param_checks.h"

namespace dvpr {

void LinkStateParams::Validate() const {
  CheckInRange("hello", hello, SimTime::Nanos(1), kMaxPeriod);
  CheckInRange("topology", topology, SimTime::Nanos(1), kMaxPeriod);
}

}  // namespace dvpr
