#include "experiments/app/plot_command.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include "experiments/config/config.h"
#include "experiments/config/network_variants.h"
#include "experiments/figures/figures.h"
#include "experiments/results/manifest.h"
#include "experiments/results/safe_output.h"

namespace dvpr {

std::vector<std::filesystem::path> PlotFolder(const std::filesystem::path& dir, std::ostream& err) {
  if (!std::filesystem::exists(dir / "runs.csv")) {
    throw std::runtime_error(dir.string() + ": no runs.csv (is this a dvpr run folder?)");
  }
  const OutputDir root = OutputDir::Open(dir);
  const std::vector<std::string> before = ListEntries(root.fd());
  {
    const OutputDir figures = root.Sub("figures");  // refused, naming it, when a link
    figures.Sub("data");
  }
  // The network variants' labels (range, next hop) come from the config that made the folder.
  const std::filesystem::path config_yaml = dir / "config.yaml";
  if (!std::filesystem::is_regular_file(config_yaml)) {
    throw std::runtime_error(config_yaml.string() + ": not found (dvpr plot reads the run's network variants from it)");
  }
  const std::vector<NetworkLabel> networks = VariantLabels(LoadConfig(config_yaml, {}, ConfigFiles::kNamesOnly).network);
  std::vector<std::filesystem::path> drawn = DrawFigures(dir, networks, err);
  const std::vector<std::string> after = ListEntries(root.fd());
  std::vector<std::string> added;
  std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(added));
  AddToManifest(root, added);
  return drawn;
}

}  // namespace dvpr
