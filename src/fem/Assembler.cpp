#include "anvil/fem/Assembler.h"

#include "anvil/core/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>

namespace anvil::fem {
namespace {

/// Greedy colouring: each element takes the lowest colour not used at its nodes.
std::vector<std::vector<int>> colour_elements(const mesh::TetMesh& mesh) {
  constexpr int kWords = 8; // up to 512 colours; meshes need a few tens
  std::vector<std::uint64_t> used(static_cast<std::size_t>(mesh.node_count()) * kWords, 0);
  std::vector<std::vector<int>> colours;
  for (int e = 0; e < mesh.tet_count(); ++e) {
    int colour = 0;
    for (int w = 0; w < kWords; ++w) {
      std::uint64_t taken = 0;
      for (int v : mesh.tets[e]) taken |= used[static_cast<std::size_t>(v) * kWords + w];
      if (~taken != 0) {
        colour = 64 * w + __builtin_ctzll(~taken);
        break;
      }
      colour = -1;
    }
    ANVIL_ASSERT(colour >= 0);
    for (int v : mesh.tets[e]) used[static_cast<std::size_t>(v) * kWords + colour / 64] |= std::uint64_t{1} << (colour % 64);
    if (colour >= static_cast<int>(colours.size())) colours.resize(static_cast<std::size_t>(colour) + 1);
    colours[colour].push_back(e);
  }
  return colours;
}

/// Position of (row, col) in a compressed column-major matrix.
long entry_position(const SparseMatrix& m, long row, long col) {
  const long* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const long* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const long* it = std::lower_bound(begin, end, row);
  ANVIL_ASSERT(it != end && *it == row);
  return it - m.innerIndexPtr();
}

} // namespace

Assembler::Assembler(const mesh::TetMesh& mesh, const DofMap& dofs)
    : dofs_(dofs), colours_(colour_elements(mesh)), bubble_condensation_(mesh.tets.size()),
      bad_(mesh.tets.size(), 0), bubble_sq_(mesh.tets.size(), 0.0), neighbours_(mesh.nodes.size()) {
  for (const mesh::Tet& t : mesh.tets)
    for (int a : t)
      for (int b : t) neighbours_[a].push_back(b);
  for (auto& n : neighbours_) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  build_pattern(neighbours_);
}

bool Assembler::set_couplings(const std::vector<std::pair<int, int>>& couplings) {
  if (couplings == couplings_) return false;
  couplings_ = couplings;
  std::vector<std::vector<int>> neighbours = neighbours_;
  for (const auto& [a, b] : couplings) neighbours[a].push_back(b), neighbours[b].push_back(a);
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  build_pattern(neighbours);
  return true;
}

void Assembler::build_pattern(const std::vector<std::vector<int>>& neighbours) {
  // 4×4 blocks of node adjacency, filtered to free dofs.
  long nnz = 0;
  for (const auto& n : neighbours) nnz += 16 * static_cast<long>(n.size());
  const int free = dofs_.free_count();
  std::vector<long> outer(static_cast<std::size_t>(free) + 1, 0);
  std::vector<long> inner;
  inner.reserve(static_cast<std::size_t>(nnz));
  for (std::size_t node = 0; node < neighbours.size(); ++node)
    for (int c = 0; c < kDofsPerNode; ++c) {
      const int col = dofs_.free_index(kDofsPerNode * static_cast<int>(node) + c);
      if (col < 0) continue;
      for (int other : neighbours[node])
        for (int d = 0; d < kDofsPerNode; ++d) {
          const int row = dofs_.free_index(kDofsPerNode * other + d);
          if (row >= 0) inner.push_back(row);
        }
      outer[col + 1] = static_cast<long>(inner.size());
    }
  std::vector<double> zeros(inner.size(), 0.0);
  pattern_ = Eigen::Map<const SparseMatrix>(free, free, static_cast<long>(inner.size()), outer.data(), inner.data(),
                                            zeros.data());
  pattern_.makeCompressed();
}

void Assembler::add_velocity_block(SparseMatrix& tangent, int row_node, int col_node, const Eigen::Matrix3d& block) const {
  for (int j = 0; j < 3; ++j) {
    const int col = dofs_.free_index(kDofsPerNode * col_node + j);
    if (col < 0) continue;
    for (int i = 0; i < 3; ++i)
      if (const int row = dofs_.free_index(kDofsPerNode * row_node + i); row >= 0)
        tangent.valuePtr()[entry_position(tangent, row, col)] += block(i, j);
  }
}

AssemblyResult Assembler::assemble(const mesh::TetMesh& mesh, const ElementLaws& laws,
                                   const std::vector<material::PointState>& states, const BodyUnknowns& unknowns,
                                   const Eigen::VectorXd& nodal_forces, const BodyForce& body_force,
                                   SparseMatrix* tangent) {
  AssemblyResult result;
  result.residual = -nodal_forces;
  if (tangent) {
    if (tangent->nonZeros() != pattern_.nonZeros() || tangent->rows() != pattern_.rows()) *tangent = pattern_;
    std::fill(tangent->valuePtr(), tangent->valuePtr() + tangent->nonZeros(), 0.0);
  }
  std::fill(bad_.begin(), bad_.end(), 0);
  for (const std::vector<int>& colour : colours_) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, colour.size(), 64), [&](const auto& range) {
      MiniElementInput in;
      MiniElementSystem system;
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const int e = colour[i];
        const mesh::Tet& t = mesh.tets[e];
        for (int a = 0; a < 4; ++a) {
          in.vertices[a] = mesh.nodes[t[a]];
          in.nodal_velocity[a] = unknowns.nodal.segment<3>(kDofsPerNode * t[a]);
          in.nodal_pressure[a] = unknowns.nodal[kDofsPerNode * t[a] + 3];
        }
        in.bubble_velocity = unknowns.bubble.segment<3>(3 * e);
        in.state = states.empty() ? material::PointState{} : states[e];
        if (!mini_element(in, *laws[e], tangent != nullptr, body_force, system)) {
          bad_[e] = 1;
          bubble_sq_[e] = 0.0;
          continue;
        }
        bubble_sq_[e] = system.bubble_residual_sq;
        bubble_condensation_[e].leftCols<16>() = system.bubble_gain;
        bubble_condensation_[e].col(16) = system.bubble_residual_solved;
        for (int a = 0; a < 4; ++a)
          result.residual.segment<4>(kDofsPerNode * t[a]) += system.residual.segment<4>(4 * a);
        if (!tangent) continue;
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 4; ++c) {
            const int col = dofs_.free_index(kDofsPerNode * t[a] + c);
            if (col < 0) continue;
            for (int b = 0; b < 4; ++b)
              for (int d = 0; d < 4; ++d) {
                const int row = dofs_.free_index(kDofsPerNode * t[b] + d);
                if (row >= 0) tangent->valuePtr()[entry_position(*tangent, row, col)] += system.tangent(4 * b + d, 4 * a + c);
              }
          }
      }
    });
  }
  for (std::size_t e = 0; e < bad_.size(); ++e) {
    if (bad_[e] && result.bad_element < 0) result.bad_element = static_cast<int>(e);
    result.bubble_residual_sq += bubble_sq_[e];
  }
  return result;
}

void Assembler::bubble_increment(const mesh::TetMesh& mesh, const Eigen::VectorXd& delta,
                                 Eigen::VectorXd& bubble_delta) const {
  bubble_delta.resize(3 * mesh.tet_count());
  tbb::parallel_for(tbb::blocked_range<int>(0, mesh.tet_count(), 256), [&](const auto& range) {
    Vec16 local;
    for (int e = range.begin(); e != range.end(); ++e) {
      for (int a = 0; a < 4; ++a) local.segment<4>(4 * a) = delta.segment<4>(kDofsPerNode * mesh.tets[e][a]);
      const auto& c = bubble_condensation_[e];
      bubble_delta.segment<3>(3 * e) = -(c.col(16) + c.leftCols<16>() * local);
    }
  });
}

} // namespace anvil::fem
