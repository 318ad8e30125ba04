#pragma once
// messages.csv (DESIGN.md §6): one row per message and destination,
//   protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,type,
//   payload_bytes,wire_bytes,dropped
// delivered_ns is empty when the message was dropped, or was still in flight
// when the run ended (then dropped is 0). Runs of a sweep append to one file:
// write the header once, then each run's rows.
#include <ostream>
#include <string>

namespace dvpr {

class Network;

// The leading columns, identifying the run, as they should appear.
struct RunLabels {
  std::string protocol;
  std::string strategy;
  std::string robots;
  std::string run;
};

void WriteMessagesCsvHeader(std::ostream& os);
// Writes the network's records (Network::EnableRecords(true) before the run).
void AppendMessagesCsv(std::ostream& os, const Network& network, const RunLabels& labels);

}  // namespace dvpr
