// Numbering of a body's nodal unknowns: node i owns dofs 4i, 4i+1, 4i+2
// (velocity x, y, z) and 4i+3 (pressure). The linear system keeps every dof,
// so each node is one 4×4 block (block size 4, as PETSc's multigrid wants);
// a prescribed dof is decoupled there as a scaled identity row and column.
#pragma once
#include <vector>

namespace anvil::fem {

inline constexpr int kDofsPerNode = 4;

class DofMap {
public:
  /// `prescribed[d]` != 0 marks dof d (size 4 × nodes) as prescribed.
  explicit DofMap(std::vector<char> prescribed);

  int dof_count() const { return static_cast<int>(prescribed_.size()); }
  /// Dofs that are unknowns of the problem (not prescribed).
  int free_count() const { return free_count_; }
  bool prescribed(int dof) const { return prescribed_[dof] != 0; }

private:
  std::vector<char> prescribed_;
  int free_count_ = 0;
};

} // namespace anvil::fem
