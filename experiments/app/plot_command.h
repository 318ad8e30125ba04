#pragma once
// `dvpr plot DIR`: redraws DIR's figures from its CSV files, writing only inside DIR: a `figures`
// or `figures/data` that is a symbolic link is refused, naming it, before anything is drawn; what
// it adds is recorded in DIR's manifest (a later `dvpr run` into DIR then knows it as dvpr's).
#include <filesystem>
#include <ostream>
#include <vector>

namespace dvpr {

// Throws std::runtime_error, one line naming the path at fault. Returns the figures drawn.
std::vector<std::filesystem::path> PlotFolder(const std::filesystem::path& dir, std::ostream& err);

}  // namespace dvpr
