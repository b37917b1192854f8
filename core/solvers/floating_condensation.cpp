#include "core/solvers/floating_condensation.h"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Dense>

#include "core/linalg/sparse_block.h"

namespace thinlayer {

namespace {

Eigen::VectorXd take(const Eigen::VectorXd& v, const std::vector<int>& idx) {
  Eigen::VectorXd out(idx.size());
  for (size_t i = 0; i < idx.size(); ++i) out[i] = v[idx[i]];
  return out;
}

}  // namespace

void FloatingCondensation::condense(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& F,
                                    const std::vector<int>& kept) {
  kept_ = kept;
  std::vector<bool> is_kept(K.rows(), false);
  for (int k : kept) is_kept[k] = true;
  for (int z = 0; z < K.rows(); ++z)
    if (!is_kept[z]) interior_.push_back(z);
  S_ = Eigen::MatrixXd(sparse_block(K, kept_, kept_));
  f_ = take(F, kept_);
  if (!interior_.empty()) {
    // The interior with x held is an ordinary supported problem: factor it (CHOLMOD).
    interior_factor_ = std::make_shared<SparseCholesky>(sparse_block(K, interior_, interior_));
    K_ix_ = sparse_block(K, interior_, kept_);
    F_i_ = take(F, interior_);
    const Eigen::MatrixXd Y = interior_factor_->solve(Eigen::MatrixXd(K_ix_));  // K_ii⁻¹ K_ix
    S_ -= K_ix_.transpose() * Y;
    f_ -= K_ix_.transpose() * interior_factor_->solve(F_i_);
  }
  S_ = 0.5 * (S_ + S_.transpose()).eval();
}

FloatingCondensation FloatingCondensation::band(const FloatingBand& band, const std::vector<bool>& on_interface) {
  FloatingCondensation out;
  out.is_band_ = true;
  out.layout_ = band.layout;
  out.body_dofs_ = band.free_dof;
  const BandLayout& L = band.layout;
  // x is the whole column basis z: its stiffness is banded (a column couples with its two
  // neighbours), so the solvers keep it sparse rather than condense the interior, which would
  // fill S.
  std::vector<int> kept(L.size());
  for (int z = 0; z < L.size(); ++z) kept[z] = z;
  out.condense(band.K, band.F, kept);
  // The face DOFs the interfaces touch, and w = T x: the minus face is t, the plus face t + v.
  for (int node = 0; node < L.columns * (L.across + 1); ++node)
    for (int c = 0; c < 2; ++c) {
      const int free = band.free_dof[2 * node + c];
      if (!on_interface[free]) continue;
      const int level = L.level_of(node);
      if (level != 0 && level != L.across)
        throw std::logic_error("floating band: an interface touches a node inside the layer");
      out.face_dofs_.push_back(free);
    }
  std::sort(out.face_dofs_.begin(), out.face_dofs_.end());
  std::vector<Eigen::Triplet<double>> t;
  for (size_t k = 0; k < out.face_dofs_.size(); ++k) {
    const auto at = std::find(band.free_dof.begin(), band.free_dof.end(), out.face_dofs_[k]);
    const int nodal = static_cast<int>(at - band.free_dof.begin()), node = nodal / 2, c = nodal % 2;
    const int i = L.column_of(node);
    t.emplace_back(static_cast<int>(k), L.t(i) + c, 1.0);
    if (L.level_of(node) == L.across) t.emplace_back(static_cast<int>(k), L.v(i, L.across) + c, 1.0);
  }
  out.T_.resize(static_cast<Eigen::Index>(out.face_dofs_.size()), out.size());
  out.T_.setFromTriplets(t.begin(), t.end());
  return out;
}

FloatingCondensation FloatingCondensation::nodal(const LinearSystem& system, const std::vector<int>& body_dofs,
                                                 const std::vector<bool>& on_interface) {
  FloatingCondensation out;
  out.body_dofs_ = body_dofs;
  std::vector<int> kept;  // positions in body_dofs
  for (size_t a = 0; a < body_dofs.size(); ++a)
    if (on_interface[body_dofs[a]]) {
      kept.push_back(static_cast<int>(a));
      out.face_dofs_.push_back(body_dofs[a]);
    }
  const Eigen::SparseMatrix<double> K = sparse_block(system.K(), body_dofs, body_dofs);
  out.condense(K, take(system.F(), body_dofs), kept);
  out.T_.resize(static_cast<Eigen::Index>(kept.size()), static_cast<Eigen::Index>(kept.size()));
  out.T_.setIdentity();
  return out;
}

void FloatingCondensation::displacement(const Eigen::VectorXd& x, Eigen::VectorXd& u) const {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(kept_.size() + interior_.size()));
  for (size_t k = 0; k < kept_.size(); ++k) z[kept_[k]] = x[k];
  if (interior_factor_) {
    // Interior DOFs carry no interface force: K_ii z_i = F_i − K_ix x.
    const Eigen::VectorXd z_i = interior_factor_->solve(Eigen::VectorXd(F_i_ - K_ix_ * x));
    for (size_t k = 0; k < interior_.size(); ++k) z[interior_[k]] = z_i[k];
  }
  const Eigen::VectorXd body = is_band_ ? nodal_displacements(z, layout_) : z;
  for (size_t k = 0; k < body_dofs_.size(); ++k) u[body_dofs_[k]] = body[k];
}

Eigen::MatrixXd FloatingCondensation::selection(LayerSelection face) const {
  if (!is_band_) return Eigen::MatrixXd::Identity(size(), size());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(size(), size());
  for (int i = 0; i < layout_.columns; ++i)
    for (int c = 0; c < 2; ++c) {
      // The held displacement: t (minus face) or t + v (plus face), as e·x.
      const int t = layout_.t(i) + c, v = layout_.v(i, layout_.across) + c;
      P(t, t) = 1;
      if (face == LayerSelection::PlusFace) P(t, v) = P(v, t) = P(v, v) = 1;
    }
  return P;
}

double FloatingCondensation::rcond() const { return interior_factor_ ? interior_factor_->rcond() : 1.0; }

}  // namespace thinlayer
