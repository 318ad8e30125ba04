// Names, paths and result-folder fields that hold shell and gnuplot syntax (quotes, apostrophes,
// backquotes, $(...), ';', newlines, bytes that are not UTF-8) go through `dvpr run`, `dvpr plot`
// and `dvpr replay` as text: a canary command (touch PWNED) never runs, every figure is drawn,
// the scripts hold the names single-quoted and the replay page holds them JSON-escaped. dvpr is
// started without a shell (DvprArgv), so the test itself interprets nothing either. And a gnuplot
// that fails or writes a PNG cut short fails the run before its folder is committed.
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/app/cli_test_support.h"
#include "tests/test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

// Every figure is drawn for this config: 1700 frames of KITTI 00 hold its first revisit (so the
// relative AUC exists), two robot counts, the static protocol and the simulation, a strategy
// beyond the paper's two, point-to-point and a shared medium. About 6 s under the sanitizers.
std::string SweepConfig(const std::string& name_yaml) {
  return "name: " + name_yaml + "\nseed: 2\ndataset: {dim: 16, frames: 1700}\ntraining: {synthetic: {samples: 300}}\n"
         "robots: [2, 3]\nruns: 1\nprotocols: [paper, sim]\nstrategies: [decentralized, broadcast, multi_probe_2]\n"
         "evaluation: {suppression_frames: 250}\nnetwork: {model: [point_to_point, shared_medium]}\n"
         "outputs: {figures: true, messages: true}\n";
}

// Two network variants: the per-network figures once each (figures_traffic.h), named by it.
const std::vector<std::string> kFigures = {
    "confusion_matrix.png", "descriptor_dims.png", "loop_closures-net0-point-to-point-10-mbit-s-2-ms.png",
    "loop_closures-net1-shared-medium-10-mbit-s-2-ms.png", "place_recognition_bytes.png", "pr_curves.png",
    "relative_auc_balance.png", "robot_load-net0-point-to-point-10-mbit-s-2-ms.png",
    "robot_load-net1-shared-medium-10-mbit-s-2-ms.png", "saturation.png", "strategy_sweep.png", "strategy_tradeoff.png",
    "traffic_by_role-net0-point-to-point-10-mbit-s-2-ms.png", "traffic_by_role-net1-shared-medium-10-mbit-s-2-ms.png",
    "traffic_matrix-net0-point-to-point-10-mbit-s-2-ms.png", "traffic_matrix-net1-shared-medium-10-mbit-s-2-ms.png"};

// The canary of every injected command (relative: dvpr and gnuplot run inside dir_).
constexpr const char* kCanary = "PWNED";

class HostileNamesTest : public CliTest {
 protected:
  path Write(const path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  // No file named PWNED anywhere under dir_ (the commands would have run in dir_ or in a
  // figures/data folder inside it).
  void ExpectNoCanary() {
    for (const auto& e : fs::recursive_directory_iterator(dir_)) {
      EXPECT_NE(e.path().filename().string(), kCanary) << e.path();
    }
  }
  // Every figure of kFigures in out/figures, each a whole PNG (signature first, IEND last).
  void ExpectFigures(const path& out) {
    std::vector<std::string> pngs;
    for (const std::string& name : Names(out / "figures")) {
      if (name.ends_with(".png")) pngs.push_back(name);
    }
    EXPECT_EQ(pngs, kFigures);
    for (const std::string& name : pngs) {
      const std::string png = Slurp(out / "figures" / name);
      ASSERT_GT(png.size(), 20u) << name;
      EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << name;
      EXPECT_EQ(png.substr(png.size() - 8), std::string("IEND\xae\x42\x60\x82", 8)) << name;
    }
  }
  // A clean run of the config, its figures drawn unless `figures` is false.
  path CleanRun(bool figures = true) {
    const path cfg = Write(dir_ / "plain.yaml", SweepConfig("plain"));
    const Result r = DvprArgv({"run", cfg.string(), "--quiet", "--out", Out().string(), "--set",
                               figures ? "outputs.figures=true" : "outputs.figures=false"});
    EXPECT_EQ(r.status, 0) << r.err;
    return Out();
  }
};

// A CSV line's fields (dvpr's CSVs quote nothing) and back.
std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> f;
  std::size_t start = 0;
  for (std::size_t comma = line.find(','); comma != std::string::npos; comma = line.find(',', start)) {
    f.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
  f.push_back(line.substr(start));
  return f;
}
std::string Join(const std::vector<std::string>& f) {
  std::string line;
  for (std::size_t i = 0; i < f.size(); ++i) line += (i ? "," : "") + f[i];
  return line;
}

// Whether every `c` of a gnuplot script lies inside a single-quoted string, where gnuplot does
// no backquote or macro expansion ('' inside one is a quote; # outside strings starts a comment).
bool OnlySingleQuoted(const std::string& script, char c) {
  char in = 0;  // 0, '\'' or '"'
  for (std::size_t i = 0; i < script.size(); ++i) {
    const char x = script[i];
    if (x == '\n') {
      in = 0;
    } else if (in == '\'') {
      if (x == '\'' && i + 1 < script.size() && script[i + 1] == '\'') {
        ++i;
      } else if (x == '\'') {
        in = 0;
      }
    } else if (x == c) {
      return false;
    } else if (in == '"') {
      if (x == '\\') ++i;
      if (x == '"') in = 0;
    } else if (x == '\'' || x == '"') {
      in = x;
    } else if (x == '#') {
      while (i + 1 < script.size() && script[i + 1] != '\n') ++i;
    }
  }
  return true;
}

TEST(HostileNamesScanner, FindsWhatIsNotSingleQuoted) {
  EXPECT_TRUE(OnlySingleQuoted("set title 'a `x` it''s `y`' # `z`\nplot 'b`'\n", '`'));
  EXPECT_FALSE(OnlySingleQuoted("set title \"a `x`\"\n", '`'));
  EXPECT_FALSE(OnlySingleQuoted("set title 'it''s' . `x`\n", '`'));
  EXPECT_FALSE(OnlySingleQuoted("set title 'a\nb `x`'\n", '`'));  // a string never spans lines
}

// `dvpr run` with a config name, a config path and an --out path full of syntax, then `dvpr
// replay` of the folder (its config name, and strategy names edited into messages.csv) to a
// --out path of the same kind.
TEST_F(HostileNamesTest, RunAndReplayTakeNamesAndPathsAsText) {
  const path cfg = Write(dir_ / "cfg john's `touch PWNED` $(touch PWNED); touch PWNED\n\xff.yaml",
                         SweepConfig("\"it's \\\"q\\\" `touch PWNED` $(touch PWNED); touch PWNED; ' \xc3\xa9\""));
  const path out = dir_ / "john's out `touch PWNED` $(touch PWNED); touch PWNED; '\n\xff \"q\"";
  const Result r = DvprArgv({"run", cfg.string(), "--quiet", "--out", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  ExpectFigures(out);
  ExpectNoCanary();
  // The names of messages.csv's broadcast rows become a script end, a comment start, a command,
  // U+2028 and a byte that is not UTF-8.
  std::istringstream csv(Slurp(out / "messages.csv"));
  std::string edited, line;
  while (std::getline(csv, line)) {
    for (std::size_t at = line.find(",broadcast,"); at != std::string::npos; at = line.find(",broadcast,", at + 1)) {
      line.replace(at, 11, ",</script><!-- `touch PWNED` \xe2\x80\xa8 \xff,");
    }
    edited += line + "\n";
  }
  Write(out / "messages.csv", edited);
  const path page = dir_ / "page it's `touch PWNED` $(touch PWNED);\n\xff.html";
  const Result replay = DvprArgv({"replay", out.string(), "--out", page.string()});
  ASSERT_EQ(replay.status, 0) << replay.err;
  const std::string html = Slurp(page);
  EXPECT_NE(html.find("{\"name\":\"it's \\\"q\\\" `touch PWNED` $(touch PWNED); touch PWNED; ' \\u00e9\","),
            std::string::npos);
  EXPECT_NE(html.find("{\"name\":\"\\u003c/script\\u003e\\u003c!-- `touch PWNED` \\u2028 \\ufffd\","),
            std::string::npos);
  EXPECT_EQ(html.find("</script><!--"), std::string::npos);
  // What replay prints is one line: the config name as given (valid UTF-8 kept), the strategy's
  // byte 0xFF and the page path's newline and 0xFF shown as escapes.
  const std::string said = Stdout();
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
  EXPECT_EQ(said.rfind("replay of it's \"q\" `touch PWNED` $(touch PWNED); touch PWNED; ' \xc3\xa9: ", 0), 0u) << said;
  EXPECT_NE(said.find("</script><!-- `touch PWNED` \xe2\x80\xa8 \\xFF"), std::string::npos) << said;
  EXPECT_NE(said.find("page it's `touch PWNED` $(touch PWNED);\\n\\xFF.html ("), std::string::npos) << said;
  ExpectNoCanary();
}

// A terminal control sequence (ESC), a tab and a byte that is not UTF-8 in a path and in a
// strategy name of messages.csv reach the terminal as visible escapes, in dvpr replay's line
// and in the error line.
TEST_F(HostileNamesTest, TheTerminalSeesEscapesNotControlCharacters) {
  const Result missing = DvprArgv({"run", (dir_ / "x\x1b[2J\ty\xff.yaml").string()});
  EXPECT_EQ(missing.status, 1);
  EXPECT_EQ(missing.err, "dvpr: error: " + dir_.string() + "/x\\x1B[2J\\ty\\xFF.yaml: cannot read the config file\n");
  // config.yaml's name may hold none of these (the config reader refuses them), a path and
  // messages.csv's strategy names may.
  const path out = CleanRun(false);
  std::string csv = Slurp(out / "messages.csv");
  for (std::size_t at = csv.find(",broadcast,"); at != std::string::npos; at = csv.find(",broadcast,", at + 1)) {
    csv.replace(at, 11, ",b\x1b[31mc\td,");
  }
  Write(out / "messages.csv", csv);
  const Result replay = DvprArgv({"replay", out.string(), "--out", (dir_ / "page\x1b]0;t\x07.html").string()});
  ASSERT_EQ(replay.status, 0) << replay.err;
  const std::string said = Stdout();
  EXPECT_EQ(said.rfind("replay of plain: ", 0), 0u) << said;
  EXPECT_NE(said.find("decentralized vs b\\x1B[31mc\\td vs multi_probe_2, "), std::string::npos) << said;
  EXPECT_NE(said.find("/page\\x1B]0;t\\x07.html ("), std::string::npos) << said;
  EXPECT_EQ(said.find('\x1b'), std::string::npos) << said;
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
}

// A robot outside the team in messages.csv: one error line naming file, line and column.
TEST_F(HostileNamesTest, ReplayRefusesARobotOutsideTheTeam) {
  const path out = CleanRun(false);
  std::istringstream csv(Slurp(out / "messages.csv"));
  std::string header, line, edited, robots;
  std::getline(csv, header);
  const std::vector<std::string> columns = Fields(header);
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  edited = header + "\n";
  int number = 1, changed = 0;
  while (std::getline(csv, line)) {
    ++number;
    if (changed == 0 && line.rfind("sim,", 0) == 0) {  // the first sim row: the run replayed
      std::vector<std::string> f = Fields(line);
      robots = f.at(column("robots"));
      f.at(column("dst")) = "99";
      line = Join(f);
      changed = number;
    }
    edited += line + "\n";
  }
  ASSERT_NE(changed, 0);
  Write(out / "messages.csv", edited);
  const auto before = SnapshotFolder(out);
  const Result r = DvprArgv({"replay", out.string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dvpr: error: " + (out / "messages.csv").string() + ": line " + std::to_string(changed) +
                       ": dst: expected a robot of the team of " + robots + " (0 to " +
                       std::to_string(std::stoi(robots) - 1) + "), got 99\n");
  EXPECT_EQ(SnapshotFolder(out), before);
}

// `dvpr plot` of a folder whose runs.csv names a strategy with syntax in it: drawn, nothing runs,
// the scripts hold the name single-quoted. A network model and a loss model edited the same way
// are not the config's variant: refused in one line (the bytes shown as text), nothing written.
TEST_F(HostileNamesTest, PlotQuotesTheFieldsOfAnEditedRunsCsv) {
  const path out = CleanRun();
  const std::string strategy = "mp `touch PWNED` $(touch PWNED); it's \"x\" @m \t|\xff|\r|";
  const std::string model = "p2p `touch PWNED` 'm' \x1b\xc3";
  const std::string loss = "$(touch PWNED) \"l\"";
  const std::string clean = Slurp(out / "runs.csv");
  const auto edit = [&](bool network) {
    std::istringstream csv(clean);
    std::string edited, line;
    std::getline(csv, line);
    edited = line + "\n";
    while (std::getline(csv, line)) {
      // runs.csv: strategy is field 1, network_model 18, loss 21 (result_summary.cpp).
      std::vector<std::string> f = Fields(line);
      if (f.at(1) == "multi_probe_2") f[1] = strategy;
      if (network && f.at(18) == "point_to_point") {
        f[18] = model;
        f[21] = loss;
      }
      edited += Join(f) + "\n";
    }
    Write(out / "runs.csv", edited);
  };
  edit(true);
  const auto before = SnapshotFolder(out);
  const Result refused = DvprArgv({"plot", out.string()});
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find(": network variant 0 is 'p2p `touch PWNED` 'm' \\x1B\\xC3 10 Mbit/s 2 ms $(touch PWNED) "
                             "\"l\" loss' here but 'point-to-point 10 Mbit/s 2 ms' in the config (is config.yaml the "
                             "one of this run?)\n"),
            std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_EQ(SnapshotFolder(out), before);
  ExpectNoCanary();
  edit(false);
  const Result r = DvprArgv({"plot", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  ExpectFigures(out);
  ExpectNoCanary();
  // Worked by hand: quotes doubled, the tab, CR and the bytes that are not UTF-8 shown as text.
  const std::string quoted = "'mp `touch PWNED` $(touch PWNED); it''s \"x\" @m \\t|\\xFF|\\r|'";
  const path data = out / "figures" / "data";
  for (const char* gp : {"traffic_by_role-net0-point-to-point-10-mbit-s-2-ms.gp", "strategy_sweep.gp",
                         "strategy_tradeoff.gp"}) {
    EXPECT_NE(Slurp(data / gp).find(quoted), std::string::npos) << gp;
  }
  for (const std::string& name : Names(data)) {
    if (!name.ends_with(".gp")) continue;
    const std::string script = Slurp(data / name);
    EXPECT_TRUE(OnlySingleQuoted(script, '`')) << name;
    EXPECT_TRUE(OnlySingleQuoted(script, '@')) << name;
  }
}

// Stand-ins for gnuplot on PATH: one that fails, one that exits 0 with a PNG cut after its
// signature. `dvpr run` fails before its folder is committed (the earlier one stays as it was);
// `dvpr plot` fails and keeps the earlier PNGs.
TEST_F(HostileNamesTest, AFailingGnuplotFailsTheRunAndThePlot) {
  const path out = CleanRun();
  const auto committed = SnapshotFolder(out);
  const path bin = dir_ / "bin";
  fs::create_directories(bin);
  const auto around = Names(dir_);
  Write(bin / "gnuplot", "#!/bin/sh\necho 'line 1: no such terminal' >&2\nexit 1\n");
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  const std::string fake_path = bin.string() + ":/usr/bin:/bin";
  Result r = DvprArgv({"run", (dir_ / "plain.yaml").string(), "--quiet", "--out", Out().string(), "--set",
                       "outputs.figures=true"}, fake_path);
  EXPECT_EQ(r.status, 1);
  // The run's folder goes with the error: no log is named, and the earlier results stay.
  EXPECT_EQ(r.err, "dvpr: error: figure confusion_matrix.png: gnuplot failed (exit status 1): line 1: no such "
                   "terminal (and 15 more figures); nothing was written to " + Out().string() +
                       " (its earlier results are as they were)\n");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(SnapshotFolder(out), committed);
  EXPECT_EQ(Names(dir_), around);  // no temporary folder left
  r = DvprArgv({"plot", out.string()}, fake_path);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dvpr: error: figure confusion_matrix.png: gnuplot failed (exit status 1): line 1: no such "
                   "terminal; its log: " + (out / "figures" / "data" / "confusion_matrix.log").string() +
                       " (and 15 more figures)\n");
  Write(bin / "gnuplot", "#!/bin/sh\nprintf '\\211PNG\\r\\n\\032\\n'\n");
  r = DvprArgv({"plot", out.string()}, fake_path);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dvpr: error: figure confusion_matrix.png: gnuplot exited 0 but wrote no whole PNG (8 bytes); its log: " +
                       (out / "figures" / "data" / "confusion_matrix.log").string() + " (and 15 more figures)\n");
  for (const std::string& png : kFigures) {
    EXPECT_EQ(Slurp(out / "figures" / png), committed.at("figures/" + png)) << png;
  }
}

}  // namespace
}  // namespace dvpr::testing_support
