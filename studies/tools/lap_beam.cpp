#include "studies/tools/lap_beam.h"

#include <cmath>

#include <Eigen/Dense>

namespace thinlayer {

namespace {

using Matrix3 = Eigen::Matrix3d;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// A plane frame element along s (DOFs u_s, u_n, θ at each end, θ counter-clockwise in (s, n)).
Matrix6 frame_element(double L, double EA, double EI) {
  Matrix6 k = Matrix6::Zero();
  const double a = EA / L, b = 12 * EI / (L * L * L), c = 6 * EI / (L * L), d = 4 * EI / L, e = 2 * EI / L;
  k(0, 0) = k(3, 3) = a;
  k(0, 3) = k(3, 0) = -a;
  k(1, 1) = k(4, 4) = b;
  k(1, 4) = k(4, 1) = -b;
  k(1, 2) = k(2, 1) = k(1, 5) = k(5, 1) = c;
  k(4, 2) = k(2, 4) = k(4, 5) = k(5, 4) = -c;
  k(2, 2) = k(5, 5) = d;
  k(2, 5) = k(5, 2) = e;
  return k;
}

// The DOFs of a point (ds, dn) away from a node, rigidly linked to it: u_p = T u_node.
Matrix3 rigid_link(double ds, double dn) {
  Matrix3 T = Matrix3::Identity();
  T(0, 2) = -dn;
  T(1, 2) = ds;
  return T;
}

}  // namespace

LapBending lap_bending(const LapBeam& beam) {
  LapBending out;
  const LapArm& a0 = beam.arms[0];
  const LapArm& a1 = beam.arms[1];
  const double s1 = beam.overlap_start, s2 = beam.overlap_end;
  if (!(a0.outer < s1) || !(s1 < s2) || !(s2 < a1.outer)) {
    out.why_not = "the adherents do not run on from opposite ends of the overlap";
    return out;
  }
  // The overlap: both adherents as one beam on the mid-plane of the two.
  const double lo = std::min(a0.axis - a0.thickness / 2, a1.axis - a1.thickness / 2);
  const double hi = std::max(a0.axis + a0.thickness / 2, a1.axis + a1.thickness / 2);
  const double n_o = 0.5 * (lo + hi), h_o = a0.thickness + a1.thickness, E_o = 0.5 * (a0.E + a1.E);
  // Master nodes: 0 arm 0's end (its axis), 1 and 2 the overlap's ends (its axis), 3 arm 1's end.
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(12, 12);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
  auto add = [&](const Matrix6& k, int node_a, const Matrix3& Ta, int node_b, const Matrix3& Tb) {
    Eigen::Matrix<double, 6, 12> P = Eigen::Matrix<double, 6, 12>::Zero();
    P.block<3, 3>(0, 3 * node_a) = Ta;
    P.block<3, 3>(3, 3 * node_b) = Tb;
    K += P.transpose() * k * P;
  };
  auto beam_of = [](const LapArm& arm, double L) {
    return frame_element(L, arm.E * arm.thickness, arm.E * arm.thickness * arm.thickness * arm.thickness / 12);
  };
  const Matrix6 k_arm0 = beam_of(a0, s1 - a0.outer), k_arm1 = beam_of(a1, a1.outer - s2);
  const Matrix3 I = Matrix3::Identity(), T1 = rigid_link(0, a0.axis - n_o), T2 = rigid_link(0, a1.axis - n_o);
  add(k_arm0, 0, I, 1, T1);
  add(frame_element(s2 - s1, E_o * h_o, E_o * h_o * h_o * h_o / 12), 1, I, 2, I);
  add(k_arm1, 2, T2, 3, I);
  // Supports as constraint rows, loads as nodal forces, each at its own point.
  std::vector<Eigen::VectorXd> rows;
  std::vector<double> values;
  for (const LapEnd& e : beam.ends) {
    const LapArm& arm = beam.arms[e.arm];
    const int node = e.arm == 0 ? 0 : 3;
    const Matrix3 T = rigid_link(e.at.x() - arm.outer, e.at.y() - arm.axis);
    for (int c = 0; c < 3; ++c) {
      const bool held = c == 0 ? e.holds_s : c == 1 ? e.holds_n : e.holds_rotation;
      if (!held) continue;
      Eigen::VectorXd row = Eigen::VectorXd::Zero(12);
      row.segment<3>(3 * node) = T.row(c).transpose();
      rows.push_back(row);
      values.push_back(c < 2 ? e.value[c] : 0.0);
    }
    f.segment<3>(3 * node) += T.transpose() * Eigen::Vector3d(e.force.x(), e.force.y(), 0);
  }
  const int m = static_cast<int>(rows.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(12 + m, 12 + m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(12 + m);
  A.topLeftCorner(12, 12) = K;
  rhs.head(12) = f;
  for (int r = 0; r < m; ++r) {
    A.block(12 + r, 0, 1, 12) = rows[r].transpose();
    A.block(0, 12 + r, 12, 1) = rows[r];
    rhs[12 + r] = values[r];
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (lu.rank() < A.rows()) {
    out.why_not = "the supports leave the joint's beam model free (a mechanism)";
    return out;
  }
  const Eigen::VectorXd u = lu.solve(rhs).head(12);
  // Each arm's end forces; at the overlap end the internal moment and shear of the arm.
  auto end_forces = [&](const Matrix6& k, int node_a, const Matrix3& Ta, int node_b, const Matrix3& Tb) {
    Eigen::Matrix<double, 6, 1> ue;
    ue << Ta * u.segment<3>(3 * node_a), Tb * u.segment<3>(3 * node_b);
    return Eigen::Matrix<double, 6, 1>(k * ue);
  };
  const auto f0 = end_forces(k_arm0, 0, I, 1, T1), f1 = end_forces(k_arm1, 2, T2, 3, I);
  // Arm 0 meets the overlap at its second end, arm 1 at its first: the internal moment there is
  // f0[5] and −f1[2], the axial tension f0[3] and −f1[0], the shear f0[4] and −f1[1].
  const double N0 = f0[3], N1 = -f1[0];
  out.N = 0.5 * (N0 + N1);
  if (!(std::abs(out.N) > 0)) {
    out.why_not = "no axial force through the joint";
    return out;
  }
  const double c = 0.5 * (s2 - s1);
  out.k[0] = -f0[5] / (N0 * (n_o - a0.axis));
  out.k[1] = f1[2] / (N1 * (n_o - a1.axis));
  out.k_prime[0] = f0[4] * c / (N0 * a0.thickness);
  out.k_prime[1] = -f1[1] * c / (N1 * a1.thickness);
  out.solved = true;
  return out;
}

}  // namespace thinlayer
