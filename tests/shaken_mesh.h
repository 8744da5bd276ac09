// A mesh as another process count's round-off would carry it.
#pragma once
#include "anvil/mesh/TetMesh.h"

#include <random>

/// `body` with every coordinate moved by up to `amount` (mm), drawn from `seed`.
inline anvil::mesh::TetMesh shaken(anvil::mesh::TetMesh body, double amount, unsigned seed) {
  std::mt19937 draw(seed);
  std::uniform_real_distribution<double> by(-amount, amount);
  for (anvil::mesh::Point& x : body.nodes)
    for (int k = 0; k < 3; ++k)
      x[k] += by(draw);
  return body;
}
