#include "anvil/fem/Assembler.h"

#include "anvil/core/error.h"
#include "anvil/core/processes.h"
#include "anvil/fem/tet_quadrature.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace anvil::fem {
namespace {

/// Chunks of `size` consecutive elements, coloured greedily (each takes the
/// lowest colour not used at its nodes) so that no two chunks of a colour
/// share a node. Empty when more than 512 colours would be needed.
std::vector<std::vector<ElementChunk>> colour_chunks(const std::vector<mesh::Tet>& tets, int node_count, int size) {
  constexpr int kWords = 8; // up to 512 colours
  std::vector<std::uint64_t> used(static_cast<std::size_t>(node_count) * kWords, 0);
  std::vector<std::vector<ElementChunk>> colours;
  const int count = static_cast<int>(tets.size());
  for (int first = 0; first < count; first += size) {
    const int end = std::min(first + size, count);
    int colour = -1;
    for (int w = 0; w < kWords && colour < 0; ++w) {
      std::uint64_t taken = 0;
      for (int e = first; e < end; ++e)
        for (int v : tets[e])
          taken |= used[static_cast<std::size_t>(v) * kWords + w];
      if (~taken != 0) colour = 64 * w + __builtin_ctzll(~taken);
    }
    if (colour < 0) return {};
    for (int e = first; e < end; ++e)
      for (int v : tets[e])
        used[static_cast<std::size_t>(v) * kWords + colour / 64] |= std::uint64_t{1} << (colour % 64);
    if (colour >= static_cast<int>(colours.size())) colours.resize(static_cast<std::size_t>(colour) + 1);
    colours[colour].push_back({first, end});
  }
  return colours;
}

/// The largest chunks that still leave every thread work in each colour: a
/// chunk's elements share nodes, so their matrix rows stay in cache while it
/// is assembled. A mesh whose element order has no locality falls back to
/// single elements (then it is the classic element colouring).
std::vector<std::vector<ElementChunk>> chunk_colouring(const std::vector<mesh::Tet>& tets, int node_count) {
  constexpr int kChunksPerColour = 16; // a few per thread, for load balance
  for (int size : {256, 64, 16, 4}) {
    std::vector<std::vector<ElementChunk>> colours = colour_chunks(tets, node_count, size);
    const std::size_t chunks = (tets.size() + size - 1) / size;
    if (!colours.empty() && chunks >= kChunksPerColour * colours.size()) return colours;
  }
  std::vector<std::vector<ElementChunk>> colours = colour_chunks(tets, node_count, 1);
  ANVIL_ASSERT(!colours.empty() || tets.empty());
  return colours;
}

std::vector<mesh::Tet> part_elements(const mesh::TetMesh& mesh, const Partition& partition) {
  std::vector<mesh::Tet> tets;
  tets.reserve(partition.elements.size());
  for (int e : partition.elements)
    tets.push_back(mesh.tets[e]);
  return tets;
}

void sort_unique(std::vector<std::vector<int>>& lists) {
  for (auto& n : lists) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
}

} // namespace

Assembler::Assembler(const mesh::TetMesh& mesh, DofMap dofs, const Partition& partition)
    : dofs_(std::move(dofs)), partition_(partition), tets_(part_elements(mesh, partition)),
      colours_(chunk_colouring(tets_, mesh.node_count())), bubble_condensation_(tets_.size()), bad_(tets_.size(), 0),
      bubble_sq_(tets_.size(), 0.0), element_blocks_(tets_.size()), element_neighbours_(mesh.nodes.size()) {
  ANVIL_ASSERT(dofs_.dof_count() == kDofsPerNode * mesh.node_count());
  for (const mesh::Tet& t : tets_)
    for (int a : t)
      for (int b : t)
        element_neighbours_[a].push_back(b);
  sort_unique(element_neighbours_);
  neighbours_ = element_neighbours_;
  build_pattern();
}

bool Assembler::set_couplings(const std::vector<std::pair<int, int>>& couplings) {
  if (couplings == couplings_) return false;
  couplings_ = couplings;
  neighbours_ = element_neighbours_;
  for (const auto& [a, b] : couplings)
    neighbours_[a].push_back(b), neighbours_[b].push_back(a);
  sort_unique(neighbours_);
  build_pattern();
  return true;
}

void Assembler::build_pattern() {
  // Every row of node b holds the 4 columns of each neighbour of b, in node order.
  long nnz = 0;
  for (const auto& n : neighbours_)
    nnz += 16 * static_cast<long>(n.size());
  if (nnz > std::numeric_limits<int>::max())
    throw RunError("the system has " + std::to_string(nnz) +
                   " matrix entries, more than the 32-bit indices of this build hold (2^31 - 1)");
  const int rows = dofs_.dof_count();
  std::vector<int> outer(static_cast<std::size_t>(rows) + 1, 0), inner;
  inner.reserve(static_cast<std::size_t>(nnz));
  for (std::size_t node = 0; node < neighbours_.size(); ++node)
    for (int d = 0; d < kDofsPerNode; ++d) {
      for (int other : neighbours_[node])
        for (int c = 0; c < kDofsPerNode; ++c)
          inner.push_back(kDofsPerNode * other + c);
      outer[kDofsPerNode * node + d + 1] = static_cast<int>(inner.size());
    }
  std::vector<double> zeros(inner.size(), 0.0);
  tangent_ = Eigen::Map<const SparseMatrix>(rows, rows, static_cast<int>(inner.size()), outer.data(), inner.data(),
                                            zeros.data());
  tangent_.makeCompressed();
  // A node of no element of this process's part (another part's, coupled by
  // contact) has no diagonal entry here.
  diagonal_.resize(static_cast<std::size_t>(rows));
  for (int dof = 0; dof < rows; ++dof) {
    const int node = dof / kDofsPerNode;
    diagonal_[dof] = std::binary_search(element_neighbours_[node].begin(), element_neighbours_[node].end(), node)
                         ? entry(node, dof % kDofsPerNode, node, dof % kDofsPerNode)
                         : -1;
  }
  constrained_entries_.clear();
  for (int row = 0; row < rows; ++row)
    for (int k = tangent_.outerIndexPtr()[row]; k < tangent_.outerIndexPtr()[row + 1]; ++k)
      if (dofs_.prescribed(row) || dofs_.prescribed(tangent_.innerIndexPtr()[k])) constrained_entries_.push_back(k);
  for (std::size_t e = 0; e < element_blocks_.size(); ++e)
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a)
        element_blocks_[e][4 * b + a] = entry(tets_[e][b], 0, tets_[e][a], 0);
}

int Assembler::entry(int row_node, int d, int col_node, int c) const {
  const std::vector<int>& n = neighbours_[row_node];
  const auto it = std::lower_bound(n.begin(), n.end(), col_node);
  ANVIL_ASSERT(it != n.end() && *it == col_node);
  return tangent_.outerIndexPtr()[kDofsPerNode * row_node + d] + kDofsPerNode * static_cast<int>(it - n.begin()) + c;
}

void Assembler::add_velocity_block(int row_node, int col_node, const Eigen::Matrix3d& block) {
  const int first = entry(row_node, 0, col_node, 0);
  const int row_length = kDofsPerNode * static_cast<int>(neighbours_[row_node].size());
  double* values = tangent_.valuePtr();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      values[first + i * row_length + j] += block(i, j);
}

void Assembler::keep_element_tangent() {
  element_tangent_.assign(tangent_.valuePtr(), tangent_.valuePtr() + tangent_.nonZeros());
}

void Assembler::restore_element_tangent() {
  ANVIL_ASSERT(element_tangent_.size() == static_cast<std::size_t>(tangent_.nonZeros()));
  std::copy(element_tangent_.begin(), element_tangent_.end(), tangent_.valuePtr());
}

void Assembler::finish_tangent() {
  // Prescribed rows and columns out, then the mean free diagonal per kind on them.
  double* values = tangent_.valuePtr();
  for (int k : constrained_entries_)
    values[k] = 0.0;
  // Each part's diagonal entries of a kind have one sign (K's are positive,
  // −C's negative), so the sum of their magnitudes over the processes is
  // that of the summed diagonal.
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  for (int dof = 0; dof < dofs_.dof_count(); ++dof) {
    if (dofs_.prescribed(dof)) continue;
    const int kind = dof % kDofsPerNode == 3;
    if (diagonal_[dof] >= 0) sum[kind] += std::abs(tangent_.valuePtr()[diagonal_[dof]]);
    ++count[kind];
  }
  processes::sum(sum);
  for (int dof = 0; dof < dofs_.dof_count(); ++dof) {
    if (!dofs_.prescribed(dof) || !partition_.owns(dof / kDofsPerNode)) continue;
    const int kind = dof % kDofsPerNode == 3;
    tangent_.valuePtr()[diagonal_[dof]] = count[kind] > 0 && sum[kind] > 0.0 ? sum[kind] / count[kind] : 1.0;
  }
}

AssemblyResult Assembler::assemble(const mesh::TetMesh& mesh, const ElementLaws& laws,
                                   const std::vector<material::PointState>& states, const BodyUnknowns& unknowns,
                                   const Eigen::VectorXd& nodal_forces, const BodyForce& body_force,
                                   bool with_tangent) {
  ANVIL_ASSERT(mesh.tets.size() == partition_.number.size() || !partition_.distributed());
  AssemblyResult result;
  result.residual = -nodal_forces;
  if (partition_.distributed()) // the external forces once: on the process owning the node
    for (int node = 0; node < mesh.node_count(); ++node)
      if (!partition_.owns(node)) result.residual.segment<kDofsPerNode>(kDofsPerNode * node).setZero();
  if (with_tangent) {
    std::fill(tangent_.valuePtr(), tangent_.valuePtr() + tangent_.nonZeros(), 0.0);
    pressure_mass_.setZero(mesh.node_count());
  }
  std::fill(bad_.begin(), bad_.end(), 0);
  double* values = tangent_.valuePtr();
  const std::size_t points = tet_quadrature(quadrature_degree_).size();
  if (dual_) dual_trial_.resize(points * tets_.size());
  for (const std::vector<ElementChunk>& colour : colours_) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, colour.size(), 1), [&](const auto& range) {
      MiniElementInput in;
      MiniElementSystem system;
      ElementDual dual;
      for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk)
        for (int k = colour[chunk].first; k < colour[chunk].end; ++k) {
          const int e = partition_.elements[k];
          const mesh::Tet& t = mesh.tets[e];
          for (int a = 0; a < 4; ++a) {
            in.vertices[a] = mesh.nodes[t[a]];
            in.nodal_velocity[a] = unknowns.nodal.segment<3>(kDofsPerNode * t[a]);
            in.nodal_pressure[a] = unknowns.nodal[kDofsPerNode * t[a] + 3];
          }
          in.bubble_velocity = unknowns.bubble.segment<3>(3 * e);
          in.state = states.empty() ? material::PointState{} : states[e];
          in.tangent_sensitivity_floor = tangent_sensitivity_floor_;
          in.quadrature_degree = quadrature_degree_;
          if (dual_) {
            for (int a = 0; a < 4; ++a)
              dual.nodal_velocity[a] = dual_at_.nodal.segment<3>(kDofsPerNode * t[a]);
            dual.bubble_velocity = dual_at_.bubble.segment<3>(3 * e);
            dual.step = dual_step_;
            dual.last = dual_last_.empty() ? nullptr : dual_last_.data() + points * k;
            dual.trial = dual_trial_.data() + points * k;
            in.dual = &dual;
          }
          if (!mini_element(in, *laws[e], with_tangent, body_force, system)) {
            bad_[k] = 1;
            bubble_sq_[k] = 0.0;
            continue;
          }
          bubble_sq_[k] = system.bubble_residual_sq;
          bubble_condensation_[k].leftCols<16>() = system.bubble_gain;
          bubble_condensation_[k].col(16) = system.bubble_residual_solved;
          for (int a = 0; a < 4; ++a)
            result.residual.segment<4>(kDofsPerNode * t[a]) += system.residual.segment<4>(4 * a);
          if (!with_tangent) continue;
          if (system.viscosity > 0.0)
            for (int a = 0; a < 4; ++a)
              pressure_mass_[t[a]] += 0.25 * system.volume / system.viscosity;
          // Every entry, prescribed ones too: finish_tangent() takes those out.
          const std::array<int, 16>& blocks = element_blocks_[k];
          for (int b = 0; b < 4; ++b) {
            const int row_length = kDofsPerNode * static_cast<int>(neighbours_[t[b]].size());
            for (int a = 0; a < 4; ++a) {
              double* block = values + blocks[4 * b + a]; // row 4 t[b], column 4 t[a]
              for (int d = 0; d < 4; ++d)
                for (int c = 0; c < 4; ++c)
                  block[d * row_length + c] += system.tangent(4 * b + d, 4 * a + c);
            }
          }
        }
    });
  }
  for (std::size_t k = 0; k < bad_.size(); ++k) {
    if (bad_[k] && result.bad_element < 0) result.bad_element = partition_.elements[k];
    result.bubble_residual_sq += bubble_sq_[k];
  }
  if (partition_.distributed()) {
    const int none = mesh.tet_count();
    const int bad = processes::minimum(result.bad_element < 0 ? none : result.bad_element);
    result.bad_element = bad == none ? -1 : bad;
    processes::sum(std::span(&result.bubble_residual_sq, 1));
    processes::sum({result.residual.data(), static_cast<std::size_t>(result.residual.size())});
    if (with_tangent) processes::sum({pressure_mass_.data(), static_cast<std::size_t>(pressure_mass_.size())});
  }
  return result;
}

void Assembler::start_dual(const BodyUnknowns* at) {
  dual_ = at != nullptr;
  dual_last_.clear();
  dual_step_ = 0.0;
  if (dual_)
    dual_at_ = *at;
  else
    dual_trial_.clear();
}

void Assembler::accept_dual(const BodyUnknowns& at) {
  if (!dual_) return;
  dual_at_ = at;
  dual_last_.swap(dual_trial_);
  dual_step_ = 0.0;
}

void Assembler::bubble_increment(const mesh::TetMesh& mesh, const Eigen::VectorXd& delta,
                                 Eigen::VectorXd& bubble_delta) const {
  if (partition_.distributed())
    bubble_delta.setZero(3 * mesh.tet_count()); // other parts' elements: summed in below
  else
    bubble_delta.resize(3 * mesh.tet_count());
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(tets_.size()), 256), [&](const auto& range) {
    Vec16 local;
    for (int k = range.begin(); k != range.end(); ++k) {
      const int e = partition_.elements[k];
      for (int a = 0; a < 4; ++a)
        local.segment<4>(4 * a) = delta.segment<4>(kDofsPerNode * mesh.tets[e][a]);
      const auto& c = bubble_condensation_[k];
      bubble_delta.segment<3>(3 * e) = -(c.col(16) + c.leftCols<16>() * local);
    }
  });
  if (partition_.distributed()) processes::sum({bubble_delta.data(), static_cast<std::size_t>(bubble_delta.size())});
}

} // namespace anvil::fem
