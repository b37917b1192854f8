// The layer band in its column basis (core/fem/column_basis.h): recognised only for a band, the
// same stiffness as the nodal one in another basis, and its film modes accurate where the nodal
// basis loses them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/fem/column_basis.h"
#include "core/fem/linear_system.h"
#include "core/mesh/layer_band.h"
#include "core/mesh/structured_rectangle.h"

namespace thinlayer {
namespace {

// A straight band along x, `columns` columns over a length 1, thickness eps, 2 cells across.
Mesh straight_band(int columns, double eps) {
  FacePolyline minus(columns, 2), plus(columns, 2);
  for (int i = 0; i < columns; ++i) {
    const double x = static_cast<double>(i) / (columns - 1);
    minus.row(i) << x, 0.0;
    plus.row(i) << x, eps;
  }
  return layer_band(minus, plus, 2);
}

// The map T from the column basis z to the nodal displacements: u = T z.
Eigen::MatrixXd basis_map(const BandLayout& layout) {
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(2 * layout.columns * (layout.across + 1), layout.size());
  for (int z = 0; z < layout.size(); ++z) T.col(z) = nodal_displacements(Eigen::VectorXd::Unit(layout.size(), z), layout);
  return T;
}

Eigen::MatrixXd nodal_stiffness(const Mesh& mesh, const Material& material, bool selective) {
  Model model;
  model.bodies.push_back({"layer", mesh, material, true, selective});
  return Eigen::MatrixXd(assemble_stiffness(model));
}

TEST(ColumnBasis, RecognisesALayerBandAndNothingElse) {
  const Mesh band = straight_band(7, 1e-3);
  const std::optional<BandLayout> layout = band_layout(band);
  ASSERT_TRUE(layout.has_value());
  EXPECT_EQ(layout->columns, 7);
  EXPECT_EQ(layout->across, 2);

  RectangleMeshSpec spec;
  spec.nx = 3;
  spec.ny = 2;
  EXPECT_FALSE(band_layout(structured_rectangle(spec)).has_value());  // no S-/S+ sets

  Mesh shuffled = band;
  std::swap(shuffled.quads[0][0], shuffled.quads[3][2]);  // a cell joining columns 0 and 2
  EXPECT_FALSE(band_layout(shuffled).has_value());
}

// On a thick layer (both bases accurate) the column stiffness is Tᵀ K T, to round-off, with
// either integration rule.
TEST(ColumnBasis, IsTheNodalStiffnessInAnotherBasis) {
  const Mesh band = straight_band(6, 0.05);
  const BandLayout layout = *band_layout(band);
  const Material material{45.0, 54.0, PlaneHypothesis::Strain};
  const Eigen::MatrixXd T = basis_map(layout);
  for (bool selective : {false, true}) {
    const Eigen::MatrixXd expected = T.transpose() * nodal_stiffness(band, material, selective) * T;
    const Eigen::MatrixXd column = Eigen::MatrixXd(column_stiffness(band, layout, material, selective));
    EXPECT_LT((column - expected).norm(), 1e-13 * expected.norm()) << "selective " << selective;
  }
}

// Forces go to the column basis by Tᵀ (column_forces) and back by nodal_forces, its exact inverse;
// nodal_force_bound bounds what round-off in column forces becomes in nodal ones.
TEST(ColumnBasis, NodalForcesInvertColumnForces) {
  const Mesh band = straight_band(6, 1e-3);
  const BandLayout layout = *band_layout(band);
  const Eigen::VectorXd f = Eigen::VectorXd::Random(2 * layout.columns * (layout.across + 1));
  const Eigen::VectorXd column = column_forces(f, layout);
  EXPECT_NEAR((column - basis_map(layout).transpose() * f).norm(), 0.0, 1e-14);
  EXPECT_LT((nodal_forces(column, layout) - f).norm(), 1e-14 * f.norm());
  const Eigen::VectorXd bound = nodal_force_bound(column.cwiseAbs(), layout);
  EXPECT_TRUE((bound.array() >= nodal_forces(column, layout).cwiseAbs().array()).all());
  EXPECT_GT(bound.sum(), f.cwiseAbs().sum());  // a foot's bound sums its column's magnitudes
}

// At ε = 1e-8 a film's in-plane stiffness is 1e-16 of its through-thickness one. The column basis
// integrates it directly: a rigid translation costs nothing, and a uniform in-plane stretch
// t_x = a·x costs the membrane energy ½ E' ε a² L (plane strain, the layer free through its
// thickness: E' = 4μ(λ+μ)/(λ+2μ)) once the relative displacements relax. The nodal basis,
// transformed, has round-off of 1e-16 of the through-thickness stiffness in those entries and
// gets the membrane energy wrong by orders of magnitude.
TEST(ColumnBasis, KeepsTheFilmsMembraneStiffnessWhereTheNodalBasisLosesIt) {
  const double eps = 1e-8, lambda = 4500 * eps, mu = 5400 * eps, a = 1e-3;
  const Mesh band = straight_band(11, eps);
  const BandLayout layout = *band_layout(band);
  const Material material{lambda, mu, PlaneHypothesis::Strain};
  const Eigen::MatrixXd K = Eigen::MatrixXd(column_stiffness(band, layout, material, false));

  Eigen::VectorXd translation = Eigen::VectorXd::Zero(layout.size());
  for (int i = 0; i < layout.columns; ++i) translation.segment<2>(layout.t(i)) << 1e-3, -2e-3;
  EXPECT_LT((K * translation).norm(), 1e-16 * K.norm() * translation.norm());

  // The stretch imposed on the translations; the relative displacements minimize the energy.
  std::vector<int> t_dofs, v_dofs;
  for (int i = 0; i < layout.columns; ++i)
    for (int c = 0; c < 2; ++c) t_dofs.push_back(layout.t(i) + c);
  for (int z = 0; z < layout.size(); ++z)
    if (std::find(t_dofs.begin(), t_dofs.end(), z) == t_dofs.end()) v_dofs.push_back(z);
  auto membrane_energy = [&](const Eigen::MatrixXd& stiffness) {
    Eigen::VectorXd z = Eigen::VectorXd::Zero(layout.size());
    for (int i = 0; i < layout.columns; ++i) z[layout.t(i)] = a * band.nodes(layout.node(i, 0), 0);
    Eigen::MatrixXd K_vv(v_dofs.size(), v_dofs.size());
    Eigen::VectorXd rhs(v_dofs.size());
    for (size_t p = 0; p < v_dofs.size(); ++p) {
      rhs[p] = -(stiffness.row(v_dofs[p]) * z)(0);
      for (size_t q = 0; q < v_dofs.size(); ++q) K_vv(p, q) = stiffness(v_dofs[p], v_dofs[q]);
    }
    const Eigen::VectorXd v = K_vv.ldlt().solve(rhs);
    for (size_t p = 0; p < v_dofs.size(); ++p) z[v_dofs[p]] = v[p];
    return 0.5 * z.dot(stiffness * z);
  };
  const double E_plane = 4 * mu * (lambda + mu) / (lambda + 2 * mu);
  const double exact = 0.5 * E_plane * eps * a * a * 1.0;
  EXPECT_NEAR(membrane_energy(K), exact, 1e-6 * exact);

  const Eigen::MatrixXd T = basis_map(layout);
  const Eigen::MatrixXd from_nodal = T.transpose() * nodal_stiffness(band, material, false) * T;
  EXPECT_GT(std::abs(membrane_energy(from_nodal) - exact), 1e-3 * exact)
      << "the nodal basis no longer loses the membrane stiffness: this test no longer shows why the column basis exists";
}

}  // namespace
}  // namespace thinlayer
