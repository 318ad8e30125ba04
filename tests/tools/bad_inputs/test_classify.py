#!/usr/bin/env python3
"""Checks the classifier of tests/tools/bad_inputs.py on hand-made outcomes (no dvpr needed):
each class is reached by the outcome that defines it, and a clear error only by exit code, one
line naming the key, nothing left behind and an earlier folder unchanged.

    python3 tests/tools/bad_inputs/test_classify.py
"""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import bad_inputs  # noqa: E402
from catalogue import Case  # noqa: E402


def outcome(case, rc, stderr="", left=(), prior_changed=(), new=(), fired=True, after=None):
    r = bad_inputs.Result(case, rc=rc, out_dir=Path("/nonexistent/out"))
    r.lines = [line for line in stderr.splitlines() if line.strip()]
    m = bad_inputs.SANITIZER.search(stderr)
    r.sanitizer = m.group(0) if m else ""
    r.left, r.prior_changed, r.new = list(left), list(prior_changed), list(new)
    bad_inputs.classify(r, stderr, fired, after or {})
    return r


KEY = Case("t01", "a bad latency", ("network.latency",))
FLAG = Case("t02", "a bad flag", ("--threads",), exit=2)
PRIOR = Case("t03", "into an earlier folder", ("runs",), prior="base.yaml")
ANY = Case("t04", "either key", (("network.bandwidth", "verification.request_bytes"),))
FORBID = Case("t05", "a pose error", ("poses.txt",), forbid=("dataset.descriptors",))
REPLACE = Case("t06", "a later run", success=True, prior="base.yaml")
ERR = "dvpr: error: c.yaml: network.latency: must be at most 1h, got 2562047h\n"


class ClassifyTest(unittest.TestCase):
    def test_one_line_naming_the_key_with_exit_1_is_clear(self):
        self.assertEqual(outcome(KEY, 1, ERR).cls, "clear error")

    def test_usage_error_needs_exit_2(self):
        line = "dvpr run: --threads: expected an integer, got 'abc'\n"
        self.assertEqual(outcome(FLAG, 2, line).cls, "clear error")
        r = outcome(FLAG, 1, line)
        self.assertEqual(r.cls, "misleading error")
        self.assertIn("exit 1, expected 2", r.reasons)

    def test_exit_0_is_silent_acceptance(self):
        self.assertEqual(outcome(KEY, 0, "").cls, "silent acceptance")

    def test_sanitizer_report_is_a_crash_even_with_exit_1(self):
        r = outcome(KEY, 1, "sim_time.h:31:50: runtime error: signed integer overflow\n")
        self.assertEqual(r.cls, "crash")
        self.assertIn("exit 1, the code of a user error", r.reasons)

    def test_signal_and_timeout_are_crashes(self):
        self.assertEqual(outcome(KEY, -11, "").cls, "crash")
        self.assertEqual(outcome(KEY, 134, "").cls, "crash")
        self.assertEqual(outcome(KEY, None, "").cls, "crash")

    def test_left_folder_is_partial_output(self):
        self.assertEqual(outcome(KEY, 1, ERR, left=["out"]).cls, "partial output")
        self.assertEqual(outcome(KEY, 1, ERR, left=["out/.runs.csv.tmp42"]).cls, "partial output")

    def test_changed_earlier_folder_is_partial_output(self):
        line = "dvpr: error: c.yaml: runs: must be at least 1, got 0\n"
        self.assertEqual(outcome(PRIOR, 1, line).cls, "clear error")
        r = outcome(PRIOR, 1, line, prior_changed=["out/config.yaml"])
        self.assertEqual(r.cls, "partial output")

    def test_refusing_an_earlier_folder_counts_as_naming_it(self):
        line = "dvpr: error: /s/f01/out: exists; remove it or choose another --out\n"
        self.assertEqual(outcome(PRIOR, 1, line).cls, "clear error")
        self.assertEqual(outcome(PRIOR, 1, "dvpr: error: no output for you\n").cls,
                         "misleading error")

    def test_two_lines_or_a_missing_key_mislead(self):
        self.assertEqual(outcome(KEY, 1, ERR + "more\n").cls, "misleading error")
        r = outcome(KEY, 1, "dvpr: error: stoi\n")
        self.assertEqual(r.cls, "misleading error")
        self.assertIn("does not name network.latency", r.reasons)

    def test_alternatives_and_forbidden_words(self):
        self.assertEqual(outcome(ANY, 1, "x: verification.request_bytes: too big\n").cls,
                         "clear error")
        self.assertEqual(outcome(FORBID, 1, "x: dataset.poses: poses.txt: line 5: bad\n").cls,
                         "clear error")
        r = outcome(FORBID, 1, "x: dataset.descriptors: poses.txt: line 5: bad\n")
        self.assertEqual(r.cls, "misleading error")

    def test_raw_bytes_mislead(self):
        r = outcome(KEY, 1, "dvpr: error: network.latency: \x01\x02\ufffd\n")
        self.assertIn("raw bytes in the message", r.reasons)

    def test_replacing_run_must_leave_a_whole_folder(self):
        whole = {"out": "/", "out/runs.csv": "h"}
        self.assertEqual(outcome(REPLACE, 0, after=whole).cls, "ok")
        self.assertEqual(outcome(REPLACE, 0, after={"out": "/"}).cls, "partial output")
        r = outcome(REPLACE, 0, after=whole, new=["out.tmp123"])
        self.assertEqual(r.cls, "partial output")
        refused = "dvpr: error: out: already holds results; choose another --out\n"
        self.assertEqual(outcome(REPLACE, 1, refused).cls, "ok")
        self.assertEqual(outcome(REPLACE, 1, refused, prior_changed=["out/runs.csv"]).cls,
                         "partial output")

    def test_a_run_into_a_folder_inside_out_is_whole_with_its_runs_csv(self):
        inside = Case("t09", "--out out/NAME", success=True)
        self.assertEqual(outcome(inside, 0, after={"out": "/", "out/n": "/", "out/n/runs.csv": "h"}).cls, "ok")
        self.assertEqual(outcome(inside, 0, after={"out": "/", "out/n": "/", "out/n/x.csv": "h"}).cls,
                         "partial output")


if __name__ == "__main__":
    unittest.main()
