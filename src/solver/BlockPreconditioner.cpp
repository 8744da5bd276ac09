#include "anvil/solver/BlockPreconditioner.h"

#include <cmath>

namespace anvil::solver {

void BlockPreconditioner::set_components(std::vector<char> component) {
  component_ = std::move(component);
  for (auto& list : index_)
    list.clear();
  for (std::size_t i = 0; i < component_.size(); ++i)
    index_[component_[i]].push_back(static_cast<long>(i));
  for (auto& factor : velocity_factor_)
    factor.reset();
}

BlockPreconditioner& BlockPreconditioner::factorize(const fem::SparseMatrix& a) {
  std::vector<long> position(component_.size()); // index within its component block
  for (const auto& list : index_)
    for (std::size_t k = 0; k < list.size(); ++k)
      position[list[k]] = static_cast<long>(k);
  std::array<std::vector<Eigen::Triplet<double, long>>, 3> entries;
  pressure_diagonal_inverse_.resize(static_cast<long>(index_[3].size()));
  double largest_pressure_diagonal = 0.0;
  for (long row = 0; row < a.outerSize(); ++row) {
    const int c = component_[row];
    for (fem::SparseMatrix::InnerIterator it(a, row); it; ++it) {
      if (component_[it.col()] != c) continue;
      if (c < 3)
        entries[c].emplace_back(position[row], position[it.col()], it.value());
      else if (it.col() == row) {
        pressure_diagonal_inverse_[position[row]] = std::abs(it.value());
        largest_pressure_diagonal = std::max(largest_pressure_diagonal, std::abs(it.value()));
      }
    }
  }
  for (long k = 0; k < pressure_diagonal_inverse_.size(); ++k) // a zero diagonal (none expected) is floored
    pressure_diagonal_inverse_[k] = 1.0 / std::max(pressure_diagonal_inverse_[k], 1e-12 * largest_pressure_diagonal);
  info_ = Eigen::Success;
  for (int c = 0; c < 3; ++c) {
    const long n = static_cast<long>(index_[c].size());
    Block block(n, n);
    block.setFromTriplets(entries[c].begin(), entries[c].end());
    if (!velocity_factor_[c]) {
      velocity_factor_[c] = std::make_unique<Cholesky>();
      velocity_factor_[c]->analyzePattern(block);
    }
    velocity_factor_[c]->factorize(block);
    if (velocity_factor_[c]->info() != Eigen::Success) info_ = Eigen::NumericalIssue;
  }
  return *this;
}

Eigen::VectorXd BlockPreconditioner::solve(const Eigen::VectorXd& r) const {
  Eigen::VectorXd z(r.size());
  for (int c = 0; c < 3; ++c) {
    const auto& list = index_[c];
    Eigen::VectorXd block(static_cast<long>(list.size()));
    for (std::size_t k = 0; k < list.size(); ++k)
      block[static_cast<long>(k)] = r[list[k]];
    const Eigen::VectorXd solved = velocity_factor_[c]->solve(block);
    for (std::size_t k = 0; k < list.size(); ++k)
      z[list[k]] = solved[static_cast<long>(k)];
  }
  for (std::size_t k = 0; k < index_[3].size(); ++k)
    z[index_[3][k]] = r[index_[3][k]] * pressure_diagonal_inverse_[static_cast<long>(k)];
  return z;
}

} // namespace anvil::solver
