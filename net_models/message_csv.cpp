#include "net_models/message_csv.h"

#include <sstream>
#include <string_view>

#include "net_models/network.h"

namespace dvpr {
namespace {

// RFC 4180: quote a field that holds a comma, quote or line break.
void WriteField(std::ostream& os, std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) {
    os << s;
    return;
  }
  os << '"';
  for (const char c : s) {
    if (c == '"') os << '"';
    os << c;
  }
  os << '"';
}

}  // namespace

void WriteMessagesCsvHeader(std::ostream& os) {
  os << "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,type,"
        "payload_bytes,wire_bytes,dropped\n";
}

void AppendMessagesCsv(std::ostream& os, const Network& network, const RunLabels& labels) {
  std::string prefix;
  {
    std::ostringstream p;
    WriteField(p, labels.protocol);
    p << ',';
    WriteField(p, labels.strategy);
    p << ',';
    WriteField(p, labels.robots);
    p << ',';
    WriteField(p, labels.run);
    p << ',';
    prefix = p.str();
  }
  for (const MessageRecord& r : network.Records()) {
    os << prefix << r.sent.ns() << ',';
    if (r.arrived && !r.dropped()) os << r.delivered.ns();
    os << ',' << r.src.value << ',' << r.dst.value << ',';
    WriteField(os, network.ChannelName(r.channel));
    os << ',';
    WriteField(os, network.TypeName(r.type));
    os << ',' << r.payload_bytes << ',' << r.wire_bytes << ',' << (r.dropped() ? 1 : 0) << '\n';
  }
}

}  // namespace dvpr
