#!/usr/bin/env python3
"""`mpirun -n K dvpr run` against one process (ctest MpiSweepTest.*; see tests/CMakeLists.txt).

same-folder: tests/mpi/mpi_sweep.yaml run by one process, by 2 and by 3 MPI ranks; the three
  result folders must hold the same files, byte for byte, the summary be printed once, and no
  rank leave a temporary folder behind.
fail-input / fail-internal / die: tests/app/mpi_fault_sweep.cpp under 3 ranks with one run
  failing on a known rank (spec i runs on rank i mod 3): a std::runtime_error (exit 1), a
  std::logic_error (exit 3), or the rank killed (SIGKILL). The error names the run and the rank,
  mpirun ends (a hang would trip ctest's timeout), the result folder is not written, and nothing
  is left once the next job on this machine has started.

  Open MPI ends the other ranks of a failed job with SIGCONT, a wait, SIGTERM (on which a rank
  removes its run folder, and rank 0 its temporary result folder), a wait, SIGKILL; the waits
  are fixed (odls_base_sigkill_timeout, 1 s), so on a loaded machine a rank may be killed before
  its cleanup ends. The test does not bet on that window: it waits until every rank process is
  gone (this script adopts and reaps them), accepts as leftovers only folders of those dead
  processes, of the two kinds the next job removes, and checks that the next job removes them.
  It prints how many ranks cleaned up on SIGTERM.
config-error: an error found before the runs start, under 3 ranks: a config error (every rank
  finds it), rank 0's refused --out (a user's file in it) and a usage error are each one line,
  said once by rank 0; every rank exits with the status on its own (no MPI_Abort, whose text Open
  MPI prints; mpirun --quiet keeps out mpirun's own note on a non-zero status), nothing written.

Usage: test_mpi_sweep.py MODE MPIRUN DVPR FAULT_SWEEP SOURCE_DIR WORK_DIR
"""
import ctypes
import errno
import os
import pathlib
import re
import shutil
import socket
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
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_hwloc_base_binding_policy="none")
    cmd = [MPIRUN, "--allow-run-as-root", "-n", str(ranks), *command]
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)
    reap_ranks()
    return proc


def adopt_orphans():
    """Makes this script the subreaper of what it starts: a rank that outlives mpirun (Open MPI
    marks the ranks it SIGKILLs as ended without waiting for them) becomes its child."""
    PR_SET_CHILD_SUBREAPER = 36
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) != 0:
        sys.exit(f"FAIL: prctl(PR_SET_CHILD_SUBREAPER): {os.strerror(ctypes.get_errno())}")


def reap_ranks():
    """Waits until every rank process has ended and is reaped: the event the leftover checks
    need (a dead rank's folders are its to remove no more, and the next job removes them only
    once its process is gone). A rank that never ends trips ctest's timeout."""
    while True:
        try:
            os.waitpid(-1, 0)
        except ChildProcessError:
            return


def process_gone(pid):
    try:
        os.kill(pid, 0)
    except OSError as e:
        return e.errno == errno.ESRCH
    return False


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
    # What a rank ended by SIGKILL leaves: its run folder in TMPDIR ("dvpr-rank<r>-<host>-<pid>",
    # never rank 0's, which has none) and, for rank 0, the temporary result folder beside the
    # output (".dvpr-run-<tag>-<pid>-<random>"); either with ".removing" when the kill came during its SIGTERM
    # cleanup, which renames a folder before it removes it. Rank 0 reports a failure itself after
    # its cleanup, so the latter only when Open MPI ended it (die). The killed rank of die is
    # always among them.
    host = socket.gethostname()
    run_folder = re.compile(rf"dvpr-rank([12])-{re.escape(host)}-(\d+)(\.removing)?")
    left = sorted(p.name for p in TMP.iterdir())
    for name in left:
        m = run_folder.fullmatch(name)
        check(m is not None and process_gone(int(m.group(2))),
              f"left in TMPDIR: {name} (not the run folder of a rank that has ended)", proc)
    beside = sorted(p.name for p in WORK.iterdir() if p.name.startswith("."))
    for name in beside:
        m = re.fullmatch(r"\.dvpr-run-[0-9a-f]{8}-(\d+)-[0-9a-f]{16}(\.removing)?", name)
        check(status is None and m is not None and process_gone(int(m.group(1))),
              f"left beside the output: {name} (not the temporary folder of a rank 0 Open MPI ended)", proc)
    # Open MPI ends the two ranks that did not fail. Rank 0, when it failed or reported the
    # failure, cleaned up itself before it aborted the job.
    if status is None:  # die: ranks 0 and 2 were ended; the killed rank 1 left its run folder
        check(any(run_folder.fullmatch(n).group(1) == str(rank) for n in left),
              f"the killed rank {rank} left no run folder: {left}", proc)
        cleaned = (1 - (len(left) - 1)) + (1 - len(beside))
    else:  # ranks 1 and 2 were ended
        cleaned = 2 - len(left)
    # The next job on this machine (one rank, which makes no run folder of its own and fails
    # before it writes) removes what dead ranks left.
    again = mpirun(1, FAULT, str(CONFIG), str(out), "0", "input")
    check(again.returncode == 1, "the next job did not fail as it should", again)
    check(not any(TMP.iterdir()), f"the next job did not remove the dead ranks' run folders: "
          f"{sorted(p.name for p in TMP.iterdir())}", again)
    check(sorted(p.name for p in WORK.iterdir() if p.name.startswith(".")) == [],
          "the next job did not remove the dead rank 0's temporary result folder", again)
    print(f"ranks Open MPI ended that cleaned up on SIGTERM: {cleaned} of 2; "
          f"left for the next job: {left + beside}")
    print(f"{mode} on rank {rank}: exit {proc.returncode}, nothing written")


def config_error():
    bad = WORK / "bad.yaml"
    bad.write_text("robots: [2, 3]\nruns: abc\n")
    out = WORK / "out"
    line = f"dvpr: error: {bad}: runs: expected an integer, got 'abc'\n"
    proc = mpirun(3, "--quiet", DVPR, "run", str(bad), "--quiet", "--out", str(out))
    check(proc.returncode == 1, "a config error under 3 ranks: expected exit status 1", proc)
    check(proc.stderr == line, "a config error under 3 ranks: not one line from rank 0", proc)
    # Without --quiet mpirun adds its note that a rank exited with status 1, but the ranks ended
    # on their own: no MPI_ABORT text, and still one line of dvpr's.
    proc = mpirun(3, DVPR, "run", str(bad), "--quiet", "--out", str(out))
    check(proc.returncode == 1 and proc.stderr.startswith(line) and proc.stderr.count("dvpr") == 1,
          "without --quiet: not dvpr's one line first", proc)
    check("MPI_ABORT" not in proc.stderr + proc.stdout, "a config error aborted the job (MPI_ABORT)", proc)
    check(not out.exists(), "a config error wrote the result folder", proc)
    # Rank 0 alone refuses the --out (the other ranks do not check it): they learn it and end.
    user = WORK / "user"
    user.mkdir()
    (user / "NOTES.txt").write_text("mine")
    proc = mpirun(3, "--quiet", DVPR, "run", str(CONFIG), "--quiet", "--out", str(user))
    check(proc.returncode == 1 and proc.stderr.count("\n") == 1 and proc.stderr.startswith("dvpr: error: ")
          and "NOTES.txt" in proc.stderr, "rank 0's refused --out: not one error line naming the file", proc)
    check(sorted(p.name for p in user.iterdir()) == ["NOTES.txt"] and (user / "NOTES.txt").read_text() == "mine",
          "rank 0's refused --out: the folder changed", proc)
    proc = mpirun(3, "--quiet", DVPR, "run", str(CONFIG), "--bogus")
    check(proc.returncode == 2 and proc.stderr == "dvpr run: unknown option --bogus (see dvpr --help)\n",
          "a usage error under 3 ranks: not one line from rank 0 with status 2", proc)
    check(not any(TMP.iterdir()), f"left in TMPDIR: {sorted(p.name for p in TMP.iterdir())}")
    check(sorted(p.name for p in WORK.iterdir() if p.name.startswith(".")) == [],
          "a temporary result folder left beside the output")
    print("config error, refused --out and usage error under 3 ranks: one line each, nothing written")


adopt_orphans()
shutil.rmtree(WORK, ignore_errors=True)
TMP.mkdir(parents=True)
if MODE == "same-folder":
    same_folder()
elif MODE == "fail-input":
    failing("input", 5, 1)      # rank 2, a worker
elif MODE == "fail-internal":
    failing("internal", 3, 3)   # rank 0, the one that writes
elif MODE == "config-error":
    config_error()
elif MODE == "die":
    failing("die", 4, None)     # rank 1
else:
    sys.exit(f"unknown mode {MODE}")
