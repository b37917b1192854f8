// Q1 with selective reduced integration (the λ part at the centre), used for thin layers that
// may be nearly incompressible.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "core/fem/element_q1.h"
#include "core/fem/material.h"

namespace thinlayer {
namespace {

Coords4 skewed_cell() {
  Coords4 xy;
  xy << 0.0, 0.0, 1.2, 0.1, 1.4, 0.9, 0.1, 1.1;
  return xy;
}

void split(const Material& m, Eigen::Matrix3d& volumetric, Eigen::Matrix3d& rest) {
  volumetric = Eigen::Matrix3d::Zero();
  volumetric.topLeftCorner<2, 2>().setConstant(m.lambda);
  rest = m.D() - volumetric;
}

TEST(SelectiveIntegration, EqualsFullIntegrationUnderUniformStrain) {
  // Under a uniform strain both rules integrate the energy exactly: K u must agree for a
  // linear displacement field u = A x.
  const Material m{4500, 5400, PlaneHypothesis::Strain};
  Eigen::Matrix3d volumetric, rest;
  split(m, volumetric, rest);
  const Coords4 xy = skewed_cell();
  Eigen::Matrix2d A;
  A << 1e-3, 2e-3, -5e-4, 3e-3;
  Eigen::Matrix<double, 8, 1> u;
  for (int a = 0; a < 4; ++a) u.segment<2>(2 * a) = A * xy.row(a).transpose();
  const Eigen::Matrix<double, 8, 1> full = q1_stiffness(xy, m.D()) * u;
  const Eigen::Matrix<double, 8, 1> selective = q1_stiffness_selective(xy, volumetric, rest) * u;
  EXPECT_LT((full - selective).norm(), 1e-12 * full.norm());
}

TEST(SelectiveIntegration, HasExactlyTheThreeRigidModesAndIsSymmetric) {
  // Only the λ part is under-integrated, so no hourglass mode appears: exactly three
  // zero eigenvalues even when λ ≫ μ.
  const Material m{4.5e6, 5.4, PlaneHypothesis::Strain};
  Eigen::Matrix3d volumetric, rest;
  split(m, volumetric, rest);
  const Matrix8d K = q1_stiffness_selective(skewed_cell(), volumetric, rest);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  const Eigen::SelfAdjointEigenSolver<Matrix8d> eig(K);
  int zeros = 0;
  for (int i = 0; i < 8; ++i) zeros += std::abs(eig.eigenvalues()[i]) < 1e-9 * eig.eigenvalues().maxCoeff();
  EXPECT_EQ(zeros, 3);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-9 * eig.eigenvalues().maxCoeff());
}

TEST(SelectiveIntegration, DoesNotLockInBending) {
  // A nearly incompressible cell bent in-plane (u_x = x y): fully integrated Q1 stores
  // volumetric energy ~λ; the selective rule stores none of it at the centre, where the
  // bending mode is volume preserving.
  const Material m{4.5e6, 5.4, PlaneHypothesis::Strain};
  Eigen::Matrix3d volumetric, rest;
  split(m, volumetric, rest);
  Coords4 xy;
  xy << -1, -1, 1, -1, 1, 1, -1, 1;
  Eigen::Matrix<double, 8, 1> u;
  for (int a = 0; a < 4; ++a) u.segment<2>(2 * a) << xy(a, 0) * xy(a, 1), 0.0;
  const double full = u.dot(q1_stiffness(xy, m.D()) * u);
  const double selective = u.dot(q1_stiffness_selective(xy, volumetric, rest) * u);
  EXPECT_GT(full, 1e3 * selective);
  EXPECT_GT(selective, 0.0);
}

}  // namespace
}  // namespace thinlayer
