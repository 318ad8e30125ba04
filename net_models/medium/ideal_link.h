#pragma once
// "ideal": every message arrives the instant it is sent; no rate limit, no
// queue, no loss. For checking protocol logic without network effects.
#include "net_models/link/link_model.h"

namespace dvpr {

class IdealLink final : public LinkModel {
 private:
  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return "ideal"; }
};

}  // namespace dvpr
