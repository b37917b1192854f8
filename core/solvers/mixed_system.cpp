#include "core/solvers/mixed_system.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// A placeholder value that keeps an entry in the pattern (setFromTriplets keeps what it is given).
constexpr double structural = 1.0;

bool carries_normal(const InterfaceLaw& law) { return law.normal_active(); }
bool carries_tangential(const InterfaceLaw& law) {
  return law.bilateral ? law.K_T() > 0 : law.normal_active() && law.tangential_active();
}

// Which of a node's two rows is an equation d = 0 (true) and which a force condition.
std::pair<bool, bool> jump_rows(Active s, const InterfaceLaw& law) {
  switch (s) {
    case Active::Gap: return {false, false};
    case Active::Bonded: return {carries_normal(law), carries_tangential(law)};
    case Active::Stick: return {true, true};
    case Active::SlidePositive:
    case Active::SlideNegative:
    case Active::Frictionless: return {true, false};
  }
  return {false, false};
}

}  // namespace

MixedSystem::MixedSystem(const ContactProblem& problem) : problem_(problem) {
  const LinearSystem& system = problem.system();
  const int n = system.num_free();
  // The basis y: every free DOF that is not a band's, nodally, then each band's z.
  std::vector<int> in_band(n, -1);
  const std::vector<FloatingBand>& bands = system.floating_bands();
  for (size_t b = 0; b < bands.size(); ++b)
    for (int dof : bands[b].free_dof) in_band[dof] = static_cast<int>(b);
  std::vector<int> nodal_y(n, -1);
  Triplets p, k;
  std::vector<double> F;
  for (int i = 0; i < n; ++i)
    if (in_band[i] < 0) {
      nodal_y[i] = ny_++;
      free_of_nodal_y_.push_back(i);
      p.emplace_back(i, nodal_y[i], 1.0);
      F.push_back(system.F()[i]);
    }
  for (int c = 0; c < system.K().outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(system.K(), c); it; ++it)
      if (nodal_y[it.row()] >= 0 && nodal_y[it.col()] >= 0) k.emplace_back(nodal_y[it.row()], nodal_y[it.col()], it.value());
  for (const FloatingBand& band : bands) {
    const BandLayout& L = band.layout;
    layouts_.push_back(L);
    band_free_dof_.push_back(band.free_dof);
    const int offset = ny_;
    bands_.emplace_back(offset, L.size());
    for (int i = 0; i < L.columns; ++i)
      for (int j = 0; j <= L.across; ++j)
        for (int c = 0; c < 2; ++c) {  // u(i, j) = t_i + v_(i, j)
          const int free = band.free_dof[2 * L.node(i, j) + c];
          p.emplace_back(free, offset + L.t(i) + c, 1.0);
          if (j > 0) p.emplace_back(free, offset + L.v(i, j) + c, 1.0);
        }
    for (int c = 0; c < band.K.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(band.K, c); it; ++it)
        k.emplace_back(offset + it.row(), offset + it.col(), it.value());
    for (int z = 0; z < L.size(); ++z) F.push_back(band.F[z]);
    ny_ += L.size();
  }
  P_.resize(n, ny_);
  P_.setFromTriplets(p.begin(), p.end());
  K_y_.resize(ny_, ny_);
  K_y_.setFromTriplets(k.begin(), k.end());
  F_y_ = Eigen::Map<const Eigen::VectorXd>(F.data(), static_cast<Eigen::Index>(F.size()));
  const Eigen::SparseMatrix<double> B = problem.B() * P_;  // 2m × ny
  B_y_ = B;

  // The pattern: K, −Bᵀ, and every entry a status row may need (B's row, the diagonal, the slide
  // coupling of the tangential row to r_N).
  const int m2 = static_cast<int>(B.rows());
  Triplets a = k;
  for (int c = 0; c < B.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) {
      a.emplace_back(it.col(), ny_ + it.row(), -it.value());
      a.emplace_back(ny_ + it.row(), it.col(), structural);
    }
  for (int row = 0; row < m2; ++row) a.emplace_back(ny_ + row, ny_ + row, structural);
  for (int node = 0; 2 * node < m2; ++node) a.emplace_back(ny_ + 2 * node + 1, ny_ + 2 * node, structural);
  A_.resize(ny_ + m2, ny_ + m2);
  A_.setFromTriplets(a.begin(), a.end());
  A_.makeCompressed();
  // Where each status-row value lives.
  for (int c = 0; c < A_.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A_, c); it; ++it) {
      if (it.row() < ny_) continue;
      const int row = static_cast<int>(it.row()) - ny_;
      const int position = static_cast<int>(&it.valueRef() - A_.valuePtr());
      if (c < ny_) status_entries_.push_back({position, row, Role::JumpCoefficient, B.coeff(row, c)});
      else if (c - ny_ == row) status_entries_.push_back({position, row, Role::Diagonal});
      else status_entries_.push_back({position, row, Role::SlideCoupling});
    }
}

void MixedSystem::fill(const std::vector<RowCondition>& rows, Eigen::VectorXd& rhs) {
  const int m2 = 2 * problem_.num_nodes();
  if (static_cast<int>(rows.size()) != m2) throw std::invalid_argument("MixedSystem: one condition per interface row");
  rhs = Eigen::VectorXd::Zero(ny_ + m2);
  rhs.head(ny_) = F_y_;
  jump_rows_.assign(m2, false);
  for (int row = 0; row < m2; ++row) {
    jump_rows_[row] = rows[row].jump;
    rhs[ny_ + row] = rows[row].jump ? rows[row].force - problem_.jump_offset()[row] : rows[row].force;
  }
  double* values = A_.valuePtr();
  for (const Spring& s : springs_) {
    values[s.position] = s.base + s.rho;
    rhs[s.y] += s.rho * s.anchor;
  }
  for (const StatusEntry& e : status_entries_) {
    const bool jump = rows[e.row].jump;
    switch (e.role) {
      case Role::JumpCoefficient:
        values[e.position] = jump ? e.b : 0.0;
        break;
      case Role::Diagonal: {  // d = g + C r: the compliance on a jump row; 1·r on a force row
        const double C = problem_.compliance()[e.row];
        values[e.position] = jump ? (std::isfinite(C) ? C : 0.0) + rows[e.row].compliance : 1.0;
        break;
      }
      case Role::SlideCoupling:  // the tangential row's r_N: a Coulomb slide's ±f
        values[e.position] = jump ? 0.0 : rows[e.row].coupling;
        break;
    }
  }
}

std::vector<RowCondition> MixedSystem::row_conditions(const std::vector<Active>& statuses) const {
  std::vector<RowCondition> rows(2 * problem_.num_nodes());
  for (int node = 0; node < problem_.num_nodes(); ++node) {
    const auto [normal, tangential] = jump_rows(statuses[node], problem_.law(node));
    rows[2 * node].jump = normal;
    rows[2 * node + 1].jump = tangential;
    // SlidePositive: r_T + f r_N = 0; SlideNegative: r_T − f r_N = 0.
    const double f = problem_.law(node).friction;
    if (statuses[node] == Active::SlidePositive) rows[2 * node + 1].coupling = f;
    if (statuses[node] == Active::SlideNegative) rows[2 * node + 1].coupling = -f;
  }
  return rows;
}

Eigen::VectorXd MixedSystem::unknowns(const Eigen::VectorXd& u_free) const {
  Eigen::VectorXd y(ny_);
  for (size_t j = 0; j < free_of_nodal_y_.size(); ++j) y[j] = u_free[free_of_nodal_y_[j]];
  for (size_t b = 0; b < bands_.size(); ++b) {
    const BandLayout& L = layouts_[b];
    const int offset = bands_[b].first;
    for (int i = 0; i < L.columns; ++i)
      for (int c = 0; c < 2; ++c) {
        const double foot = u_free[band_free_dof_[b][2 * L.node(i, 0) + c]];
        y[offset + L.t(i) + c] = foot;
        for (int j = 1; j <= L.across; ++j) y[offset + L.v(i, j) + c] = u_free[band_free_dof_[b][2 * L.node(i, j) + c]] - foot;
      }
  }
  return y;
}

std::vector<Eigen::VectorXd> MixedSystem::band_coordinates(const Eigen::VectorXd& y) const {
  std::vector<Eigen::VectorXd> z;
  for (const auto& [offset, size] : bands_) z.push_back(y.segment(offset, size));
  return z;
}

int MixedSystem::band_translation(int band, int column, int component) const {
  return bands_.at(band).first + layouts_.at(band).t(column) + component;
}

void MixedSystem::set_springs(const std::vector<int>& y_index, const Eigen::VectorXd& rho,
                              const Eigen::VectorXd& anchor) {
  clear_springs();
  for (size_t j = 0; j < y_index.size(); ++j) {
    const int y = y_index[j];
    int position = -1;  // the diagonal entry of column y (K's pattern holds every diagonal)
    for (int q = A_.outerIndexPtr()[y]; q < A_.outerIndexPtr()[y + 1]; ++q)
      if (A_.innerIndexPtr()[q] == y) position = q;
    if (position < 0) throw std::logic_error("MixedSystem::set_springs: no diagonal entry at that unknown");
    springs_.push_back({position, y, A_.valuePtr()[position], rho[j], anchor[j]});
    A_.valuePtr()[position] += rho[j];
  }
}

Eigen::VectorXd MixedSystem::row_stiffness() const {
  Eigen::VectorXd diagonal = A_.diagonal().head(ny_);  // K's, springs included (they live in A)
  Eigen::VectorXd kappa(B_y_.rows());
  for (int row = 0; row < B_y_.rows(); ++row) {
    double compliance = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B_y_, row); it; ++it)
      compliance += it.value() * it.value() / diagonal[it.col()];
    const double C = problem_.compliance()[row];
    if (std::isfinite(C)) compliance += C;
    kappa[row] = compliance > 0 ? 1.0 / compliance : 0.0;
  }
  return kappa;
}

void MixedSystem::clear_springs() {
  for (const Spring& s : springs_) A_.valuePtr()[s.position] = s.base;
  springs_.clear();
}

MixedSystem::Answer MixedSystem::solve(const std::vector<Active>& statuses) {
  return solve(row_conditions(statuses));
}

MixedSystem::Answer MixedSystem::solve(const std::vector<RowCondition>& rows) {
  Eigen::VectorXd rhs;
  fill(rows, rhs);
  return factor_and_solve(rhs);
}

MixedSystem::Answer MixedSystem::factor_and_solve(const Eigen::VectorXd& rhs) {
  Answer answer;
  answer.singular = singular_ = !lu_.factor(A_);
  answer.rcond = lu_.rcond();
  factored_ = true;
  const Eigen::VectorXd x = lu_.solve(rhs);
  const Eigen::VectorXd y = x.head(ny_);
  answer.u = P_ * y;
  answer.y = y;
  answer.r = x.tail(2 * problem_.num_nodes());
  answer.band_z = band_coordinates(y);
  return answer;
}

MixedSystem::Answer MixedSystem::solve_again(const Eigen::VectorXd& body_forces, const Eigen::VectorXd& row_values) const {
  if (!factored_) throw std::logic_error("MixedSystem::solve_again before any solve()");
  const int m2 = 2 * problem_.num_nodes();
  if (body_forces.size() != P_.rows() || row_values.size() != m2)
    throw std::invalid_argument("MixedSystem::solve_again: the right-hand side does not fit the problem");
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(ny_ + m2);
  rhs.head(ny_) = P_.transpose() * body_forces;  // a band's nodal forces in its column basis: Pᵀ f
  for (int row = 0; row < m2; ++row)
    if (jump_rows_[row]) rhs[ny_ + row] = row_values[row];
  Answer answer;
  answer.singular = singular_;
  answer.rcond = lu_.rcond();
  const Eigen::VectorXd x = lu_.solve(rhs);
  const Eigen::VectorXd y = x.head(ny_);
  answer.u = P_ * y;
  answer.r = x.tail(m2);
  for (const auto& [offset, size] : bands_) answer.band_z.push_back(y.segment(offset, size));
  return answer;
}

}  // namespace thinlayer
