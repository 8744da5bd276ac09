#include "anvil/fem/DofMap.h"

#include <algorithm>

namespace anvil::fem {

DofMap::DofMap(std::vector<char> prescribed)
    : prescribed_(std::move(prescribed)),
      free_count_(static_cast<int>(std::count(prescribed_.begin(), prescribed_.end(), 0))) {}

} // namespace anvil::fem
