#!/usr/bin/env python3
"""scripts/check_layers.py refuses what goes against docs/architecture.md.

Copies the checker, the table, every CMakeLists.txt, source file and LCM type of the repository
into a scratch tree, checks that the copy passes, then plants one fault at a time and checks
that it is refused (exit 1) with a message naming the file and what is wrong:
1. sim/ including <lcm/lcm-cpp.hpp> (an angle-bracket include of a package sim may not use) and
   <dvpr/query_t.hpp> (lcm-gen's code of dvpr_lcmtypes);
2. sim/ including agents/robot_agent.h (a quoted include of a module above it);
3. bench/ including experiments/app/cli.h (the benchmarks may not use the command line), and
   sim/ including a header of bench/ (the wrong way round);
4. a test of tests/sim/ including an agents header (tests link only their module);
5. a dependency missing from a module's CMake links (dvpr_replay without dvpr_channels), one
   the row does not name, and a row naming a module no file of it includes;
6. a PUBLIC link only .cpp files need, and a PRIVATE link a header needs;
7. a module the "Kept apart" table keeps from liblcm reaching it (dvpr_evaluation allowed
   dvpr_lcm_log in its row);
8. the network's rooms: the network room (net_models/network/) including a concrete medium
   (net_models/medium/wifi_link.h), and its row allowed the medium room, which Kept apart forbids:
   the network knows a medium only as a LinkModel (net_models/link/);
9. the experiments' tiers: a domain module (dvpr_data) allowed a runner's module (dvpr_config) in
   its row, and an experiments module left out of the Tiers table.
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
COPIED = (".h", ".hpp", ".cpp", ".lcm")
sys.path.insert(0, str(SOURCE / "scripts"))
from source_tree import tree_files  # noqa: E402 (found through SOURCE)


def copy_tree(root):
    (root / "scripts").mkdir()
    (root / "docs").mkdir()
    shutil.copy(SOURCE / "scripts/check_layers.py", root / "scripts")
    shutil.copy(SOURCE / "scripts/source_tree.py", root / "scripts")
    shutil.copy(SOURCE / "docs/architecture.md", root / "docs")
    for f in tree_files(SOURCE):  # not build/: the tests running beside this one write there
        rel = f.relative_to(SOURCE)
        if f.is_file() and (f.suffix in COPIED or f.name == "CMakeLists.txt"):
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(f, root / rel)


def run(root):
    r = subprocess.run([sys.executable, str(root / "scripts/check_layers.py"), str(root)],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


def refused(root, want, what):
    code, err = run(root)
    assert code == 1, f"{what}: exit {code}, expected 1\n{err}"
    assert want in err, f"{what}: no '{want}' in\n{err}"


def planted(root, rel, text, want, what):
    path = root / rel
    path.write_text(text)
    refused(root, want, what)
    path.unlink()


def edited(root, rel, old, new, want, what):
    path = root / rel
    before = path.read_text()
    assert old in before, f"{rel} has no '{old}': update this test"
    path.write_text(before.replace(old, new, 1))
    refused(root, want, what)
    path.write_text(before)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        copy_tree(root)
        code, err = run(root)
        assert code == 0, f"the repository's copy: exit {code}\n{err}"

        # 1. Angle-bracket includes.
        planted(root, "sim/planted.cpp", "// planted\n#include <lcm/lcm-cpp.hpp>\n",
                "sim/planted.cpp:2: dvpr_sim includes lcm/lcm-cpp.hpp of PkgConfig::LCM", "<lcm/...> in sim/")
        planted(root, "sim/planted.cpp", "#include <vector>\n#include <dvpr/query_t.hpp>\n",
                "sim/planted.cpp:2: dvpr_sim includes dvpr/query_t.hpp of dvpr_lcmtypes", "<dvpr/*.hpp> in sim/")
        # 2. Quoted includes.
        planted(root, "sim/planted.cpp", '// planted\n#include "agents/robot_agent.h"\n',
                "sim/planted.cpp:2: dvpr_sim includes agents/robot_agent.h of dvpr_agents", "quoted, in sim/")
        # 3. bench/: both ways.
        planted(root, "bench/planted.cpp", '#include "experiments/app/cli.h"\n',
                "bench/planted.cpp:1: dvpr_bench includes experiments/app/cli.h of dvpr_app", "in bench/")
        planted(root, "sim/planted.cpp", '#include "bench/bench_main.h"\n',
                "sim/planted.cpp:1: dvpr_sim includes bench/bench_main.h of dvpr_bench", "of bench/")
        # 4. Tests.
        planted(root, "tests/sim/test_planted.cpp", '#include "agents/algorithms/descriptor_index.h"\n',
                "tests/sim/test_planted.cpp:1: dvpr_sim includes agents/algorithms/descriptor_index.h", "in tests/sim/")
        # 5. CMake links against the table.
        replay = "experiments/replay/CMakeLists.txt"
        edited(root, replay, "PUBLIC dvpr_channels ", "",
               f"{replay}: dvpr_replay does not link dvpr_channels, which its row", "a missing CMake dependency")
        edited(root, replay, "PRIVATE dvpr_data", "PRIVATE dvpr_sim dvpr_data",
               f"{replay}: dvpr_replay links dvpr_sim, which its row", "a CMake dependency the row lacks")
        doc = "docs/architecture.md"
        row = re.search(r"^\| `dvpr_figures` \|.*$", (root / doc).read_text(), re.M).group(0)
        edited(root, doc, row, row.replace("`dvpr_results` |", "`dvpr_results`, `dvpr_sim` |"),
               "dvpr_figures may use dvpr_sim, but no file of experiments/figures/ includes it", "an unused row entry")
        # 6. PUBLIC where a header needs it, PRIVATE elsewhere.
        edited(root, replay, "PRIVATE dvpr_data", "PUBLIC dvpr_data",
               f"{replay}: dvpr_replay links dvpr_data PUBLIC, but none of its headers", "PUBLIC for a .cpp")
        edited(root, replay, "PUBLIC dvpr_channels dvpr_results dvpr_config PRIVATE",
               "PUBLIC dvpr_results dvpr_config PRIVATE dvpr_channels",
               f"{replay}: dvpr_replay links dvpr_channels PRIVATE, but its header includes it", "PRIVATE for a header")

        # 7. Kept apart: the evaluation may not reach liblcm, not even through a row.
        row = re.search(r"^\| `dvpr_evaluation` \|.*$", (root / doc).read_text(), re.M).group(0)
        edited(root, doc, row, row.replace("`dvpr_data` |", "`dvpr_data`, `dvpr_lcm_log` |"),
               "dvpr_evaluation reaches PkgConfig::LCM (through dvpr_lcm_log), which Kept apart forbids",
               "liblcm under the evaluation")

        # 8. The network room sees a medium only through net_models/link/, never a concrete one.
        planted(root, "net_models/network/planted.cpp", '#include "net_models/medium/wifi_link.h"\n',
                "net_models/network/planted.cpp:1: dvpr_net_network includes net_models/medium/wifi_link.h "
                "of dvpr_net_medium", "a concrete medium in the network room")
        planted(root, "net_models/network/planted.h", '#pragma once\n#include "net_models/helper/link_factory.h"\n',
                "net_models/network/planted.h:2: dvpr_net_network includes net_models/helper/link_factory.h "
                "of dvpr_net_helper", "the helper in the network room")
        row = re.search(r"^\| `dvpr_net_network` \|.*$", (root / doc).read_text(), re.M).group(0)
        edited(root, doc, row, row.replace("`dvpr_net_routing` |", "`dvpr_net_routing`, `dvpr_net_medium` |"),
               "dvpr_net_network reaches dvpr_net_medium (through dvpr_net_medium), which Kept apart forbids",
               "the medium room under the network room")

        # 9. Tiers: the domain never uses the runner; every experiments module is in a tier.
        row = re.search(r"^\| `dvpr_data` \|.*$", (root / doc).read_text(), re.M).group(0)
        edited(root, doc, row, row.replace("`dvpr_algorithms` |", "`dvpr_algorithms`, `dvpr_config` |"),
               "dvpr_data (domain tier) may use dvpr_config of the runner tier above it (Tiers)",
               "the runner under the domain")
        edited(root, doc, ", `experiments/replay`", "",
               "dvpr_replay (experiments/replay/) is in no tier", "a module in no tier")

        code, err = run(root)
        assert code == 0, f"the copy after the plants were removed: exit {code}\n{err}"
    print("check_layers: the repository passes; planted includes (quoted and <...>, in sim/, bench/, tests/) "
          "and CMake links against the table are refused; the network room reaches no concrete medium; the domain tier never uses the runner")


if __name__ == "__main__":
    main()
