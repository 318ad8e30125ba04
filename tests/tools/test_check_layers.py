#!/usr/bin/env python3
"""scripts/check_layers.py catches an include against docs/architecture.md.

Copies the checker and the architecture table into a scratch tree, then:
1. sim/ including a header of sim/ itself and net_models/ including sim/: clean (exit 0);
2. a planted sim/planted.cpp including agents/robot_agent.h (sim may use nothing above it):
   exit 1, and the message names the file, the line and both modules;
3. a test of tests/sim/ including an agents header: exit 1 (tests link only their module).
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])


def run(root):
    r = subprocess.run([sys.executable, str(root / "scripts/check_layers.py"), str(root)],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


def main():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "scripts").mkdir()
        (root / "docs").mkdir()
        shutil.copy(SOURCE / "scripts/check_layers.py", root / "scripts")
        shutil.copy(SOURCE / "docs/architecture.md", root / "docs")
        (root / "sim").mkdir()
        (root / "net_models").mkdir()
        (root / "sim/a.cpp").write_text('#include "sim/sim_time.h"\n#include <vector>\n')
        (root / "net_models/b.cpp").write_text('#include "sim/simulator.h"\n')
        code, err = run(root)
        assert code == 0, f"clean tree: exit {code}\n{err}"

        (root / "sim/planted.cpp").write_text('// planted\n#include "agents/robot_agent.h"\n')
        code, err = run(root)
        assert code == 1, f"planted include: exit {code}\n{err}"
        want = "sim/planted.cpp:2: dvpr_sim includes agents/robot_agent.h of dvpr_agents"
        assert want in err, f"message does not name file, line and modules:\n{err}"
        (root / "sim/planted.cpp").unlink()

        (root / "tests/sim").mkdir(parents=True)
        (root / "tests/sim/test_x.cpp").write_text('#include "agents/descriptor_index.h"\n')
        code, err = run(root)
        assert code == 1 and "tests/sim/test_x.cpp:1" in err, f"test include: exit {code}\n{err}"
    print("check_layers: clean tree passes, planted includes fail with file, line and modules")


if __name__ == "__main__":
    main()
