// loads.png: the press load against the stroke, one curve per load surface,
// drawn by gnuplot (Debian gnuplot-nox, installed by tools/setup).
#pragma once
#include "anvil/scene/RunState.h"

#include <string>
#include <vector>

namespace anvil::io {

/// Writes `directory`/loads.png from `loads`: the press load of the whole
/// part (|Fz| of the model times `copies`, the symmetry model's copies) in kN
/// against the press stroke (the largest die or plate stroke of the row, so
/// a fixed die plots against the press travel too), titled `title`. Returns
/// an empty string, or why no plot was written (gnuplot missing or
/// failing): a missing plot does not fail a run.
std::string write_load_plot(const std::string& directory, const std::string& title,
                            const std::vector<std::string>& surfaces, const std::vector<scene::LoadRecord>& loads,
                            int copies);

} // namespace anvil::io
