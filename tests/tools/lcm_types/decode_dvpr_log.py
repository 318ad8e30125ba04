#!/usr/bin/env python3
"""Decodes every event of an LCM log file with the Python types lcm-gen made from lcmtypes/dvpr.

The log is read here in pure Python (Debian 12 has no Python binding of LCM); the format is
LCM's documented one (https://lcm-proj.github.io/log_file_format.html): each event is a
big-endian header (sync word 0xEDA1DA01, u32; event number, i64; timestamp in microseconds,
i64; channel length, i32; data length, i32), the channel name, then the data.

Each event must carry the fingerprint of exactly one dvpr type, decode, and encode back to the
same bytes (LCM's own LCM_SELF_TEST messages, which lcm-logger records, are skipped). A
verification request's payload must be the bytes derived from its query frame's descriptor
(agents/messages/verification_payload.h), computed here independently. With --live (a launched
team's recording) each event's 34-byte authentication trailer is removed first (docs/security.md),
and every message's utime must lie within a second of the instant the
logger received it (the event's timestamp, wall clock), and a query's capture_utime must not be
after its utime.

    python3 tests/tools/lcm_types/decode_dvpr_log.py BUILD/lcmtypes/python LOG [--live]

Prints "python: N events decoded {type: count, ...}" and exits 0, or names the first bad event
and exits 1.
"""
import importlib
import os
import struct
import sys

SYNC = 0xEDA1DA01
HEADER = struct.Struct(">IqqII")


def read_events(path):
    """Yields (event number, timestamp, channel, data) for each event of an LCM log."""
    with open(path, "rb") as f:
        while True:
            header = f.read(HEADER.size)
            if not header:
                return
            if len(header) < HEADER.size:
                raise ValueError("truncated event header at byte %d" % (f.tell() - len(header)))
            sync, number, timestamp, channel_len, data_len = HEADER.unpack(header)
            if sync != SYNC:
                raise ValueError("bad sync word 0x%08x at byte %d" % (sync, f.tell() - HEADER.size))
            channel = f.read(channel_len).decode("utf-8")
            data = f.read(data_len)
            if len(data) != data_len:
                raise ValueError("truncated event %d" % number)
            yield number, timestamp, channel, data


def dvpr_types(python_dir):
    """The dvpr package's types, by packed fingerprint."""
    sys.path.insert(0, python_dir)
    package = importlib.import_module("dvpr")
    types = {}
    for name in sorted(os.listdir(os.path.join(python_dir, "dvpr"))):
        if name.endswith("_t.py"):
            t = getattr(package, name[:-3])
            types[t._get_packed_fingerprint()] = t
    return types


def verification_payload(frame, descriptor, size):
    """The bytes dvpr sends in a verify_request_t for `frame` (agents/messages/verification_payload.h):
    SplitMix64 seeded with the 64-bit FNV-1a hash of the frame id and descriptor, little-endian."""
    mask = (1 << 64) - 1
    h = 0xCBF29CE484222325
    for b in struct.pack("<i", frame) + struct.pack("<%df" % len(descriptor), *descriptor):
        h = ((h ^ b) * 0x100000001B3) & mask
    out = bytearray()
    while len(out) < size:
        h = (h + 0x9E3779B97F4A7C15) & mask
        z = h
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & mask
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & mask
        out += struct.pack("<Q", z ^ (z >> 31))
    return bytes(out[:size])


def check_payload(msg, descriptors, where):
    """A verify_request_t's payload must be the bytes derived from its query frame (when the log
    holds that frame's query). Returns 1 if checked, 0 if the query is not in the log."""
    descriptor = descriptors.get(msg.query_frame)
    if descriptor is None:
        return 0
    if bytes(msg.payload) != verification_payload(msg.query_frame, descriptor, msg.payload_size):
        sys.exit("python: %s: the payload is not the bytes derived from frame %d" % (where, msg.query_frame))
    return 1


TRAILER = 34  # robot, instance, counter and a 16-byte tag (docs/security.md)


def main(argv):
    if len(argv) not in (3, 4) or (len(argv) == 4 and argv[3] != "--live"):
        sys.exit(__doc__)
    types = dvpr_types(argv[1])
    live = len(argv) == 4
    counts = {}
    events = 0
    descriptors = {}  # frame -> the descriptor its query carried
    payloads = 0
    for number, timestamp, channel, data in read_events(argv[2]):
        if channel == "LCM_SELF_TEST":
            continue  # LCM's own, sent when a udpm instance opens
        where = "event %d on %s" % (number, channel)
        if live:
            # A launched team's message ends in its 34-byte authentication trailer
            # (agents/auth/message_auth.h): the LCM message is what precedes it.
            if len(data) < 8 + TRAILER:
                sys.exit("python: %s: shorter than a message and its trailer" % where)
            data = data[:-TRAILER]
        t = types.get(data[:8])
        if t is None:
            sys.exit("python: %s: no dvpr type has its fingerprint" % where)
        msg = t.decode(data)
        if msg.encode() != data:
            sys.exit("python: %s: does not encode back to its bytes" % where)
        if live and abs(msg.utime - timestamp) > 1000000:
            sys.exit("python: %s: utime %d is %d us from the wall clock at receipt"
                     % (where, msg.utime, msg.utime - timestamp))
        if hasattr(msg, "capture_utime") and msg.capture_utime > msg.utime:
            sys.exit("python: %s: captured at %d, after it was sent at %d" % (where, msg.capture_utime, msg.utime))
        if t.__name__ == "query_t":
            descriptors[msg.frame] = msg.descriptor
        elif t.__name__ == "verify_request_t":
            payloads += check_payload(msg, descriptors, where)
        counts[t.__name__] = counts.get(t.__name__, 0) + 1
        events += 1
    if events == 0:
        sys.exit("python: no events in " + argv[2])
    if counts.get("verify_request_t", 0) > 0 and payloads == 0:
        sys.exit("python: no verification request's query frame is in the log: payloads unchecked")
    print("python: %d events decoded %s, %d verification payloads are their frames' bytes"
          % (events, dict(sorted(counts.items())), payloads))


if __name__ == "__main__":
    main(sys.argv)
