#!/usr/bin/env python3
"""scripts/check_docs.py refuses docs that disagree with the code about the network's keys and
models, and only that.

Copies the checker, the config reader (experiments/config/*.cpp), the models' spellings
(net_models/helper/link_factory.cpp) and the two docs into a scratch tree, checks that the copy passes,
then changes one thing at a time and checks that it is refused (exit 1) with a line naming the
doc and the key or model:
1. docs/config.md: a key's row gone (a key nested four readers deep), a row for a key the reader
   does not take, a map key in a row renamed (`{model: bernoulli, q}`);
2. the reader: a key added to an ExpectMap (nested through ReadRadio, ReadRadioMap and
   ReadLogDistance; and in ReadLoss, which network.links[i].loss reads too), a key added through
   ReadKindOrMap's list, a new section read through a Field variable;
3. docs/network_model.md: a model's row gone, a row for a model the code lacks, a contention cell
   that says no for wifi; the code: a new model in the spellings table, one more model that
   contends, a model gone; docs/config.md's network.model row without `csma`;
4. exit 2 when the reader's root cannot be found or Contends() has another form than
   `kind == LinkModelKind::k... || ...`.
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
SECTIONS = "experiments/config/config_sections.cpp"
FACTORY = "net_models/helper/link_factory.cpp"
CONFIG_DOC = "docs/config.md"
MODEL_DOC = "docs/network_model.md"


def copy_tree(root):
    for rel in ("scripts/check_docs.py", "scripts/check_protocol_names.py", "scripts/source_tree.py",
                FACTORY, CONFIG_DOC, MODEL_DOC):
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(SOURCE / rel, root / rel)
    (root / "experiments/config").mkdir(parents=True)
    for f in (SOURCE / "experiments/config").glob("*.cpp"):
        shutil.copy(f, root / "experiments/config")


def run(root):
    r = subprocess.run([sys.executable, str(root / "scripts/check_docs.py"), str(root)],
                       capture_output=True, text=True)
    return r.returncode, r.stderr


def edited(root, rel, old, new, wants, what, want_code=1):
    path = root / rel
    before = path.read_text()
    assert old in before, f"{rel} has no '{old}': update this test"
    path.write_text(before.replace(old, new, 1))
    code, err = run(root)
    path.write_text(before)
    assert code == want_code, f"{what}: exit {code}, expected {want_code}\n{err}"
    for want in wants:
        assert want in err, f"{what}: no '{want}' in\n{err}"


def main():
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        copy_tree(root)
        code, err = run(root)
        assert code == 0, f"the repository's copy: exit {code}\n{err}"

        # 1. docs/config.md against the reader.
        row = next(l for l in (root / CONFIG_DOC).read_text().splitlines(True)
                   if l.startswith("| `network.radio.log_distance.shadowing_window` |"))
        edited(root, CONFIG_DOC, row, "",
               ["docs/config.md: network.radio.log_distance.shadowing_window: the config reader accepts it "
                "(experiments/config/config_sections.cpp: ReadLogDistance)"], "a key's row gone")
        edited(root, CONFIG_DOC, row, row + "| `network.radio.antenna_gain` | number | 0 |\n",
               ["docs/config.md: network.radio.antenna_gain: documented (its row"], "a row the reader does not take")
        edited(root, CONFIG_DOC, "{model: bernoulli, p}", "{model: bernoulli, q}",
               ["docs/config.md: network.loss.p: the config reader accepts it",
                "docs/config.md: network.links.loss.p: the config reader accepts it",
                "docs/config.md: network.loss.q: documented (a key of the map in the row of network.loss)"],
               "a map key renamed")

        # 2. The reader against docs/config.md.
        edited(root, SECTIONS, '"shadowing_db",', '"shadowing_db", "fading",',
               ["docs/config.md: network.radio.log_distance.fading: the config reader accepts it "
                "(experiments/config/config_sections.cpp: ReadLogDistance)"], "a key four readers deep")
        edited(root, SECTIONS, '"loss_good", "loss_bad"}', '"loss_good", "loss_bad", "burst"}',
               ["docs/config.md: network.loss.burst: the config reader accepts it",
                "docs/config.md: network.links.loss.burst: the config reader accepts it"], "a loss key")
        edited(root, SECTIONS, '{"kind", "hold_bytes", "hold_time"}', '{"kind", "hold_bytes", "hold_time", "hold_count"}',
               ["docs/config.md: network.disconnected.hold_count: the config reader accepts it "
                "(experiments/config/config_sections.cpp: ReadDisconnected through ReadKindOrMap)"],
               "a key through ReadKindOrMap")
        edited(root, SECTIONS, '"disconnected", "schedule", "wifi"});',
               '"disconnected", "schedule", "wifi", "mac"});\n'
               '  if (const Field mac = f.Child("mac"); mac.present()) ReadWifi(mac, n);',
               ["docs/config.md: network.mac: the config reader accepts it",
                "docs/config.md: network.mac.rate: the config reader accepts it "
                "(experiments/config/config_sections.cpp: ReadWifi)"], "a section read through a variable")

        # 3. The models.
        row = next(l for l in (root / MODEL_DOC).read_text().splitlines(True) if l.startswith("| `csma` |"))
        edited(root, MODEL_DOC, row, "",
               ["docs/network_model.md: csma: network.model accepts it (net_models/helper/link_factory.cpp), "
                "the table under 'Link models at a glance' has no row for it"], "a model's row gone")
        edited(root, MODEL_DOC, row, row + "| `token_ring` | - | a ring | no | yes | no | no |\n",
               ["docs/network_model.md: token_ring: a row under 'Link models at a glance', but network.model "
                "accepts no such model"], "a row for no model")
        wifi = next(l for l in (root / MODEL_DOC).read_text().splitlines(True) if l.startswith("| `wifi` |"))
        edited(root, MODEL_DOC, wifi, wifi.replace("| yes: DIFS", "| no: DIFS"),
               ["docs/network_model.md: wifi: its contention cell says 'no: DIFS"], "wifi said not to contend")
        edited(root, FACTORY, '{LinkModelKind::kWifi, "wifi"},', '{LinkModelKind::kWifi, "wifi"}, {LinkModelKind::kLte, "lte"},',
               ["docs/network_model.md: lte: network.model accepts it",
                "docs/config.md: network.model: its row does not name the model `lte`"], "a new model")
        edited(root, FACTORY, "kind == LinkModelKind::kWifi;", "kind == LinkModelKind::kWifi || kind == LinkModelKind::kRadio;",
               ["docs/network_model.md: radio: its contention cell says 'no: robots in range",
                "says it does contend: begin the cell with yes"], "the radio made to contend")
        edited(root, CONFIG_DOC, "`csma` (ns-3's CSMA", "csma (ns-3's CSMA",
               ["docs/config.md: network.model: its row does not name the model `csma`"], "config.md's model row")

        # 4. Nothing to read.
        edited(root, "experiments/config/config.cpp", "ExperimentConfig ReadExperiment(", "ExperimentConfig ReadAll(",
               ["check_docs: experiments/config/*.cpp: no ReadExperiment"], "no root reader", want_code=2)
        edited(root, FACTORY, "return kind == LinkModelKind::kCsma ||", "return kind != LinkModelKind::kIdeal && kind == LinkModelKind::kCsma ||",
               ["check_docs: net_models/helper/link_factory.cpp: Contends() is not"], "Contends() unreadable", want_code=2)
        edited(root, FACTORY, '{LinkModelKind::kIdeal, "ideal"},', "",
               ["docs/network_model.md: ideal: a row under 'Link models at a glance', but network.model accepts no such model"],
               "a model gone")
        code, err = run(root)
        assert code == 0, f"the copy after the changes were undone: exit {code}\n{err}"
    print("check_docs: the repository passes; 7 doc changes and 7 code changes are refused, 2 unreadable ones exit 2")


if __name__ == "__main__":
    main()
