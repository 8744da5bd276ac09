#include "anvil/solver/BlockPreconditioner.h"

#include <cmath>

namespace anvil::solver {

void BlockPreconditioner::set_pressure_mask(std::vector<char> is_pressure) {
  is_pressure_ = std::move(is_pressure);
  velocity_index_.clear();
  pressure_index_.clear();
  for (std::size_t i = 0; i < is_pressure_.size(); ++i)
    (is_pressure_[i] ? pressure_index_ : velocity_index_).push_back(static_cast<long>(i));
}

BlockPreconditioner& BlockPreconditioner::factorize(const fem::SparseMatrix& a) {
  // Velocity block by index map, pressure block diagonal.
  std::vector<long> block_of(is_pressure_.size());
  for (std::size_t k = 0; k < velocity_index_.size(); ++k) block_of[velocity_index_[k]] = static_cast<long>(k);
  for (std::size_t k = 0; k < pressure_index_.size(); ++k) block_of[pressure_index_[k]] = static_cast<long>(k);
  std::vector<Eigen::Triplet<double, long>> entries;
  entries.reserve(static_cast<std::size_t>(a.nonZeros()));
  pressure_diagonal_inverse_.resize(static_cast<long>(pressure_index_.size()));
  double largest_pressure_diagonal = 0.0;
  for (long col = 0; col < a.outerSize(); ++col)
    for (fem::SparseMatrix::InnerIterator it(a, col); it; ++it) {
      const long row = it.row();
      if (!is_pressure_[row] && !is_pressure_[col]) entries.emplace_back(block_of[row], block_of[col], it.value());
      else if (row == col) {
        pressure_diagonal_inverse_[block_of[row]] = std::abs(it.value());
        largest_pressure_diagonal = std::max(largest_pressure_diagonal, std::abs(it.value()));
      }
    }
  for (long k = 0; k < pressure_diagonal_inverse_.size(); ++k) // a zero diagonal (none expected) is floored
    pressure_diagonal_inverse_[k] = 1.0 / std::max(pressure_diagonal_inverse_[k], 1e-12 * largest_pressure_diagonal);
  const long nv = static_cast<long>(velocity_index_.size());
  fem::SparseMatrix k(nv, nv);
  k.setFromTriplets(entries.begin(), entries.end());
  velocity_factor_.compute(k);
  info_ = velocity_factor_.info();
  return *this;
}

Eigen::VectorXd BlockPreconditioner::solve(const Eigen::VectorXd& r) const {
  Eigen::VectorXd rv(static_cast<long>(velocity_index_.size()));
  for (std::size_t k = 0; k < velocity_index_.size(); ++k) rv[static_cast<long>(k)] = r[velocity_index_[k]];
  const Eigen::VectorXd zv = velocity_factor_.solve(rv);
  Eigen::VectorXd z(r.size());
  for (std::size_t k = 0; k < velocity_index_.size(); ++k) z[velocity_index_[k]] = zv[static_cast<long>(k)];
  for (std::size_t k = 0; k < pressure_index_.size(); ++k)
    z[pressure_index_[k]] = r[pressure_index_[k]] * pressure_diagonal_inverse_[static_cast<long>(k)];
  return z;
}

} // namespace anvil::solver
