#!/usr/bin/env python3
"""Bytes per LCM channel in a dvpr event log, as a bar chart.

Reads an LCM log file (a simulated run's lcm/*.lcmlog with outputs.lcm_log: true, or an
lcm-logger recording of a live team) in pure Python, adds up the payload bytes of the events on
each channel and draws one bar per channel (README, "LCM tools").

    /usr/bin/python3 scripts/examples/bytes_per_channel.py LOG [OUT.png]

OUT.png defaults to LOG with .png appended. Needs python3-matplotlib (scripts/setup.sh).
"""
import collections
import struct
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

# LCM log format (https://lcm-proj.github.io/log_file_format.html): per event a big-endian
# header (sync word 0xEDA1DA01, event number, timestamp in microseconds, channel length, data
# length), the channel name and the data.
HEADER = struct.Struct(">IqqII")
SYNC = 0xEDA1DA01


def events(path):
    """Yields (timestamp in microseconds, channel, data) for each event of an LCM log file."""
    with open(path, "rb") as f:
        while True:
            header = f.read(HEADER.size)
            if len(header) < HEADER.size:
                return  # end of file (or a log cut short while being written)
            sync, _, utime, channel_len, data_len = HEADER.unpack(header)
            if sync != SYNC:
                raise ValueError("%s: not an LCM log (bad sync word at byte %d)" % (path, f.tell() - HEADER.size))
            yield utime, f.read(channel_len).decode("utf-8"), f.read(data_len)


def human(n):
    return "%d B" % n if n < 1e3 else "%.1f kB" % (n / 1e3) if n < 1e6 else "%.2f MB" % (n / 1e6)


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    log = argv[1]
    out = argv[2] if len(argv) == 3 else log + ".png"
    bytes_by_channel = collections.Counter()
    messages = collections.Counter()
    for _, channel, data in events(log):
        bytes_by_channel[channel] += len(data)
        messages[channel] += 1
    if not bytes_by_channel:
        sys.exit("%s: no events" % log)
    channels = sorted(bytes_by_channel)
    fig, ax = plt.subplots(figsize=(8, 1.5 + 0.28 * len(channels)))
    bars = ax.barh(channels, [bytes_by_channel[c] for c in channels], color="#4477aa")
    ax.bar_label(bars, labels=["%d msgs, %s" % (messages[c], human(bytes_by_channel[c])) for c in channels],
                 padding=3, fontsize=8)
    ax.set_xscale("log")  # verification requests outweigh queries and replies by orders of magnitude
    ax.invert_yaxis()  # first channel on top
    ax.set_xlabel("payload bytes, log scale (LCM-encoded messages, without LCM and UDP headers)")
    ax.set_title("Bytes per channel: %s\n%d messages, %.1f kB in all"
                 % (log.split("/")[-1], sum(messages.values()), sum(bytes_by_channel.values()) / 1e3), fontsize=10)
    ax.set_xlim(right=max(bytes_by_channel.values()) * 30)  # room for the labels
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    for c in channels:
        print("%-20s %8d messages %12d bytes" % (c, messages[c], bytes_by_channel[c]))
    print(out)


if __name__ == "__main__":
    main(sys.argv)
