// The frames `anvil render` draws: spread over a run's series, or the end
// of each operation of a chain (docs/chains.md), each with the loads of the
// run it belongs to, for its caption.
#pragma once
#include "anvil/io/RunResults.h"

#include <memory>
#include <string>
#include <vector>

namespace anvil::render {

/// A run's press loads on its first load surface; none where the folder
/// has no loads.csv (a chain's folder has none: its operations' do).
struct RunLoads {
  std::string surface;
  std::vector<io::LoadRow> rows;
};

struct Shot {
  io::SeriesEntry frame; ///< its parts named from the folder drawn
  std::shared_ptr<const RunLoads> loads;
};

/// `count` frames of the series in `directory`, evenly spread, the last one always included.
std::vector<Shot> spread_frames(const std::string& directory, int count);

/// The last frame of each operation of the chain in `directory` (its
/// NN-name folders), read from the operation's own series: in the chain's,
/// a trim's frame takes the place of the stroke's last.
std::vector<Shot> operation_ends(const std::string& directory);

} // namespace anvil::render
