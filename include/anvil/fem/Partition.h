// How the processes of a run share one mesh's system (mpirun -n N; the mesh
// itself is on every process, docs/design.md §2). The elements are cut into N parts
// by recursive coordinate bisection of their centroids: a part is a compact
// block of the body, so few nodes lie between parts. A node belongs to the
// lowest part among its elements, so each process owns nodes of its own
// elements only; the nodes are numbered part by part, so each process owns
// a contiguous block of rows of the distributed matrix (4 per node, DofMap).
// One process: every element, the mesh's own numbering.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <vector>

namespace anvil::fem {

struct Partition {
  int processes = 1;
  int process = 0;
  std::vector<int> elements; ///< this process's elements, ascending
  std::vector<int> number;   ///< per node: its index in the distributed system (rows 4k … 4k + 3)
  std::vector<int> node;     ///< per index: the node (number's inverse)
  int first = 0, end = 0;    ///< the indices this process owns: [first, end)

  bool distributed() const { return processes > 1; }
  bool owns(int mesh_node) const {
    const int k = number[mesh_node];
    return k >= first && k < end;
  }
  int owned_count() const { return end - first; }
};

/// The part of process `process` of `processes` (every process computes the
/// same partition from the same mesh).
Partition partition_mesh(const mesh::TetMesh& mesh, int processes, int process);

} // namespace anvil::fem
