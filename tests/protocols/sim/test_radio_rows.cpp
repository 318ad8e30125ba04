// radio.csv's drop columns (experiments/results/radio_rows.h) name the network's drop reasons
// (net_models/link/link_model.h) in their order after kNone: the simulation copies the counts by
// index, so a reason added to one list and not the other would shift every column after it.
#include <gtest/gtest.h>

#include <string>

#include "experiments/results/radio_rows.h"
#include "net_models/link/link_model.h"

namespace dvpr {
namespace {

TEST(RadioRows, DropColumnsAreTheNetworksReasonsInOrder) {
  ASSERT_EQ(kRadioDropReasons.size() + 1, kDropReasons);
  EXPECT_EQ(ToString(DropReason::kNone), "none");
  for (std::size_t i = 0; i < kRadioDropReasons.size(); ++i) {
    EXPECT_EQ(std::string(kRadioDropReasons[i]), ToString(static_cast<DropReason>(i + 1))) << i;
  }
}

}  // namespace
}  // namespace dvpr
