#include "anvil/fem/DofMap.h"

namespace anvil::fem {

DofMap::DofMap(const std::vector<char>& prescribed) : free_index_(prescribed.size(), -1) {
  for (std::size_t d = 0; d < prescribed.size(); ++d)
    if (!prescribed[d]) free_index_[d] = free_count_++;
}

} // namespace anvil::fem
