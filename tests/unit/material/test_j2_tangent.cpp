// Every law's tangent in J2 form (2η P + β e⊗e) is the derivative of its
// stress: central differences of s(ε) against the form, for each law.
#include "test_common.h"

#include "anvil/material/Material.h"

#include <memory>

using namespace anvil;

namespace {

/// The J2 tangent as a 6×6 (Mandel) matrix at strain ε.
material::Mat6 tangent_matrix(const material::Vec6& strain, const material::J2Tangent& t) {
  const material::Vec6 e = material::deviator(strain);
  return t.two_eta * material::deviatoric_projector() + t.beta * e * e.transpose();
}

} // namespace

TEST_CASE("each law's J2 tangent is the derivative of its stress", "[unit]") {
  const material::LinearElastic elastic(210000.0, 0.3);
  material::HanselSpittel::Coefficients c;
  c.A = 1500.0, c.m1 = -0.0025, c.m2 = 0.2, c.m3 = 0.13, c.m4 = -0.05, c.m7 = -0.5;
  std::vector<std::pair<std::string, std::unique_ptr<material::Material>>> laws;
  laws.emplace_back("Newtonian", std::make_unique<material::NortonHoff>(10.0, 1.0, 0.0));
  laws.emplace_back("Norton-Hoff m 0.15", std::make_unique<material::NortonHoff>(10.0, 0.15, 1e-3));
  laws.emplace_back("Hansel-Spittel", std::make_unique<material::HanselSpittel>(c, 0.01, 1e-4));
  laws.emplace_back("linear elastic", std::make_unique<material::LinearElastic>(210000.0, 0.3));
  laws.emplace_back("elastic in velocity form", std::make_unique<material::IncrementalElastic>(elastic, 0.01));
  material::PointState state;
  state.equivalent_strain = 0.4;
  state.temperature = 1100.0;
  state.elastic_stress << 12.0, -3.0, 5.0, 2.0, -1.0, 4.0;
  const material::Vec6 strain(0.3, -0.5, 0.1, 0.4, -0.2, 0.25); // 1/s, or - for the elastic law
  for (const auto& [name, law] : laws) {
    INFO(name);
    material::Vec6 stress;
    material::J2Tangent tangent;
    law->deviatoric_stress(strain, state, stress, tangent);
    const material::Mat6 analytic = tangent_matrix(strain, tangent);
    material::Mat6 fd;
    for (int j = 0; j < 6; ++j) {
      const double h = 1e-6;
      material::Vec6 plus = strain, minus = strain, s_plus, s_minus;
      plus[j] += h;
      minus[j] -= h;
      material::J2Tangent ignored;
      law->deviatoric_stress(plus, state, s_plus, ignored);
      law->deviatoric_stress(minus, state, s_minus, ignored);
      fd.col(j) = (s_plus - s_minus) / (2.0 * h);
    }
    INFO("max |analytic - fd| " << (analytic - fd).cwiseAbs().maxCoeff() << ", max |analytic| "
                                << analytic.cwiseAbs().maxCoeff());
    // Central differences with h = 1e-6 on rates of order 0.5: truncation
    // O(h²) and round-off 1e-16·|s|/h, both below 1e-7 of the tangent.
    CHECK((analytic - fd).cwiseAbs().maxCoeff() <= 1e-7 * analytic.cwiseAbs().maxCoeff());
  }
}
