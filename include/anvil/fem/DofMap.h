// Numbering of a body's nodal unknowns: node i owns dofs 4i, 4i+1, 4i+2
// (velocity x, y, z) and 4i+3 (pressure). Prescribed dofs are removed from
// the linear system; the others get consecutive "free" indices in dof order.
#pragma once
#include <vector>

namespace anvil::fem {

inline constexpr int kDofsPerNode = 4;

class DofMap {
public:
  /// `prescribed[d]` != 0 marks dof d (size 4 × nodes) as prescribed.
  explicit DofMap(const std::vector<char>& prescribed);

  int dof_count() const { return static_cast<int>(free_index_.size()); }
  int free_count() const { return free_count_; }
  /// Free index of dof d, or −1 when d is prescribed.
  int free_index(int dof) const { return free_index_[dof]; }

private:
  std::vector<int> free_index_;
  int free_count_ = 0;
};

} // namespace anvil::fem
