#!/usr/bin/env python3
"""`mpirun -n K dvpr run` against one process (ctest MpiSweepTest.*; see tests/CMakeLists.txt).

same-folder: tests/mpi/mpi_sweep.yaml run by one process, by 2 and by 3 MPI ranks; the three
  result folders must hold the same files, byte for byte, the summary be printed once, and no
  rank leave a temporary folder behind.
fail-input / fail-internal / die: tests/app/mpi_fault_sweep.cpp under 3 ranks with one run
  failing on a known rank (spec i runs on rank i mod 3): a std::runtime_error (exit 1), a
  std::logic_error (exit 3), or the rank killed (SIGKILL). The error names the run and the rank,
  mpirun ends (a hang would trip ctest's timeout), and neither the result folder nor a temporary
  folder is left (but for a killed rank's run folder, which the next job removes).

Usage: test_mpi_sweep.py MODE MPIRUN DVPR FAULT_SWEEP SOURCE_DIR WORK_DIR
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

MODE, MPIRUN, DVPR, FAULT, SOURCE, WORK = sys.argv[1:7]
CONFIG = pathlib.Path(SOURCE) / "tests" / "mpi" / "mpi_sweep.yaml"
WORK = pathlib.Path(WORK) / ("mpi_" + MODE)
TMP = WORK / "tmp"  # the ranks' TMPDIR: their run folders must be gone at the end


def mpirun(ranks, *command):
    """Runs command on `ranks` ranks of this machine: as root in a container, over shared memory."""
    env = dict(os.environ, TMPDIR=str(TMP),
               # Open MPI's own allocations at exit are not dvpr's leaks.
               ASAN_OPTIONS="detect_leaks=0",
               # No ptrace-based single copy in a container; no network beyond loopback.
               OMPI_MCA_btl="self,vader", OMPI_MCA_btl_vader_single_copy_mechanism="none",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_hwloc_base_binding_policy="none",
               # Ending a failed job, Open MPI sends the other ranks SIGCONT, waits, SIGTERM (on
               # which each removes its run folder), waits, SIGKILL: 3 s, not 1, for each wait,
               # so that an ASan build on a loaded 2-core machine has time to clean up.
               OMPI_MCA_odls_base_sigkill_timeout="3")
    cmd = [MPIRUN, "--allow-run-as-root", "-n", str(ranks), *command]
    return subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)


def check(condition, message, proc=None):
    if condition:
        return
    if proc is not None:
        message += f"\n--- exit {proc.returncode}\n--- stdout\n{proc.stdout}\n--- stderr\n{proc.stderr}"
    sys.exit("FAIL: " + message)


def files(folder):
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file())


def same_folder():
    one = WORK / "one"
    proc = subprocess.run([DVPR, "run", str(CONFIG), "--quiet", "--out", str(one)],
                          capture_output=True, text=True, timeout=300)
    check(proc.returncode == 0, "the single-process run failed", proc)
    expected = files(one)
    # config.yaml, 5 row files, summary.json, 4 centroid files, 8 LCM logs, figures and their data
    check(len(expected) >= 18 and "centroids/centroids_n3_r1.npy" in expected
          and any(f.startswith("lcm/") for f in expected), f"unexpected single-process folder: {expected}")
    for ranks in (2, 3):
        out = WORK / f"ranks{ranks}"
        proc = mpirun(ranks, DVPR, "run", str(CONFIG), "--quiet", "--out", str(out))
        check(proc.returncode == 0, f"mpirun -n {ranks} failed", proc)
        check(proc.stdout.count("results in ") == 1, f"-n {ranks}: the summary not printed once", proc)
        got = files(out)
        check(got == expected, f"-n {ranks}: other files\n  missing {sorted(set(expected) - set(got))}"
              f"\n  extra {sorted(set(got) - set(expected))}")
        for f in expected:
            check((one / f).read_bytes() == (out / f).read_bytes(), f"-n {ranks}: {f} differs from one process's")
        check(not any(TMP.iterdir()), f"-n {ranks}: left in TMPDIR: {list(TMP.iterdir())}")
        check(sorted(p.name for p in WORK.iterdir() if p.name.startswith(".")) == [],
              f"-n {ranks}: a temporary result folder left beside the output")
    print(f"same {len(expected)} files from 1, 2 and 3 ranks")


def failing(mode, index, status):
    out = WORK / "out"
    proc = mpirun(3, FAULT, str(CONFIG), str(out), str(index), mode)
    rank = index % 3
    if status is None:  # killed: mpirun reports the rank and the signal, and fails
        check(proc.returncode != 0, "mpirun succeeded although a rank was killed", proc)
        check(re.search(rf"rank {rank}\b.*(signal 9|Killed)", proc.stderr + proc.stdout, re.S) is not None,
              f"mpirun did not name rank {rank} and its signal", proc)
    else:
        check(proc.returncode == status, f"expected exit status {status}", proc)
        pattern = rf"dvpr: (internal )?error: rank {rank} of 3: run (.+?): injected failure \((.+?)\)"
        match = re.search(pattern, proc.stderr)
        check(match is not None and match.group(2) == match.group(3),
              f"the error does not name rank {rank} and the failed run", proc)
        check(proc.stderr.count("injected failure") == 1, "the error reported more than once", proc)
    check(not out.exists(), "the result folder was written although a run failed", proc)
    check(sorted(p.name for p in WORK.iterdir() if p.name.startswith(".")) == [],
          "a temporary result folder was left beside the output", proc)
    left = sorted(p.name for p in TMP.iterdir())
    if status is None:
        # SIGKILL leaves the killed rank's run folder; the next job's rank 0 removes it.
        check(len(left) <= 1 and all(n.startswith(f"dvpr-rank{rank}-") for n in left),
              f"left in TMPDIR: {left}", proc)
        # One rank: rank 0 makes no run folder of its own, so what is left is the killed one's.
        again = mpirun(1, FAULT, str(CONFIG), str(out), "0", "input")
        check(again.returncode == 1 and not any(TMP.iterdir()),
              f"the next job did not remove the killed rank's run folder: {list(TMP.iterdir())}", again)
    else:
        check(not left, f"left in TMPDIR: {left}", proc)
    print(f"{mode} on rank {rank}: exit {proc.returncode}, nothing written")


shutil.rmtree(WORK, ignore_errors=True)
TMP.mkdir(parents=True)
if MODE == "same-folder":
    same_folder()
elif MODE == "fail-input":
    failing("input", 5, 1)      # rank 2, a worker
elif MODE == "fail-internal":
    failing("internal", 3, 3)   # rank 0, the one that writes
elif MODE == "die":
    failing("die", 4, None)     # rank 1
else:
    sys.exit(f"unknown mode {MODE}")
