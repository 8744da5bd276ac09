// A case as a chain of operations (docs/chains.md): heat, transfer, upset,
// finish, trim, cool, each from the part the one before left. A case
// without `operations` is a chain of one.
#pragma once
#include "anvil/scene/Case.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace anvil::scene {

enum class OperationKind { forge, transfer, dwell, cool, trim };

/// Where the part goes before an operation, in this order: flipped about a
/// horizontal axis through its centre, turned about z, moved, rested.
struct Placement {
  bool flip = false;
  double turn = 0.0;                              ///< deg about the press axis z
  Eigen::Vector3d move = Eigen::Vector3d::Zero(); ///< mm
  bool rest = false;                              ///< lowered along z onto the lowest die
  bool moves() const { return flip || turn != 0.0 || move != Eigen::Vector3d::Zero() || rest; }
};

/// The cut of a trim operation: the part inside it is kept.
struct TrimSpec {
  std::vector<Eigen::Vector2d> line; ///< mm, a closed line in the plane normal to z, extruded along z
  std::string stl_file;              ///< or a closed surface, outward normals
};

struct Operation {
  std::string name;
  OperationKind kind = OperationKind::forge;
  /// The case this operation runs: the top-level keys with the operation's
  /// own sections over them (a list replaced, a map key by key).
  Case input;
  Placement place;
  TrimSpec trim;
  std::string source; ///< "file:line" of the operation
};

struct Chain {
  std::string path; ///< the case file
  /// One without a name when the case has no `operations` (then it runs as
  /// it always did, into its own folder).
  std::vector<Operation> operations;
  bool is_chain() const { return !operations.front().name.empty(); }
};

/// "forge", "transfer", "dwell", "cool", "trim".
const char* to_string(OperationKind kind);

/// Reads and checks a case file that may hold `operations` (read_case's
/// overrides apply to the whole file). Throws InputError naming file, line
/// and key.
Chain read_chain(const std::string& path, const std::vector<std::string>& overrides = {});

} // namespace anvil::scene
