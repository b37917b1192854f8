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
      p.emplace_back(i, nodal_y[i], 1.0);
      F.push_back(system.F()[i]);
    }
  for (int c = 0; c < system.K().outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(system.K(), c); it; ++it)
      if (nodal_y[it.row()] >= 0 && nodal_y[it.col()] >= 0) k.emplace_back(nodal_y[it.row()], nodal_y[it.col()], it.value());
  for (const FloatingBand& band : bands) {
    const BandLayout& L = band.layout;
    layouts_.push_back(L);
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

void MixedSystem::fill(const std::vector<Active>& statuses, Eigen::VectorXd& rhs) {
  const int m2 = 2 * problem_.num_nodes();
  rhs = Eigen::VectorXd::Zero(ny_ + m2);
  rhs.head(ny_) = F_y_;
  std::vector<std::pair<bool, bool>>& jumps = jump_rows_;
  jumps.assign(problem_.num_nodes(), {false, false});
  for (int node = 0; node < problem_.num_nodes(); ++node) {
    jumps[node] = jump_rows(statuses[node], problem_.law(node));
    for (int c = 0; c < 2; ++c)
      if (c == 0 ? jumps[node].first : jumps[node].second) rhs[ny_ + 2 * node + c] = -problem_.jump_offset()[2 * node + c];
  }
  double* values = A_.valuePtr();
  for (const Spring& s : springs_) {
    values[s.position] = s.base + s.rho;
    rhs[s.y] += s.rho * s.anchor;
  }
  for (const StatusEntry& e : status_entries_) {
    const int node = e.row / 2, c = e.row % 2;
    const bool jump = c == 0 ? jumps[node].first : jumps[node].second;
    switch (e.role) {
      case Role::JumpCoefficient:
        values[e.position] = jump ? e.b : 0.0;
        break;
      case Role::Diagonal: {  // d = g + C r: the compliance on a jump row; r = 0 (1·r) on a force row
        const double C = problem_.compliance()[e.row];
        values[e.position] = jump ? (std::isfinite(C) ? C : 0.0) : 1.0;
        break;
      }
      case Role::SlideCoupling: {  // SlidePositive: r_T + f r_N = 0; SlideNegative: r_T − f r_N = 0
        const double f = problem_.law(node).friction;
        values[e.position] = statuses[node] == Active::SlidePositive ? f
                             : statuses[node] == Active::SlideNegative ? -f
                                                                       : 0.0;
        break;
      }
    }
  }
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
  Eigen::VectorXd rhs;
  fill(statuses, rhs);
  Answer answer;
  answer.singular = singular_ = !lu_.factor(A_);
  answer.rcond = lu_.rcond();
  factored_ = true;
  const Eigen::VectorXd x = lu_.solve(rhs, prove_round_off_ ? &answer.at_round_off : nullptr);
  const Eigen::VectorXd y = x.head(ny_);
  answer.u = P_ * y;
  answer.y = y;
  answer.r = x.tail(2 * problem_.num_nodes());
  for (const auto& [offset, size] : bands_) answer.band_z.push_back(y.segment(offset, size));
  return answer;
}

MixedSystem::Answer MixedSystem::solve_again(const Eigen::VectorXd& body_forces, const Eigen::VectorXd& row_values) const {
  if (!factored_) throw std::logic_error("MixedSystem::solve_again before any solve()");
  const int m2 = 2 * problem_.num_nodes();
  if (body_forces.size() != P_.rows() || row_values.size() != m2)
    throw std::invalid_argument("MixedSystem::solve_again: the right-hand side does not fit the problem");
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(ny_ + m2);
  rhs.head(ny_) = P_.transpose() * body_forces;  // a band's nodal forces in its column basis: Pᵀ f
  for (int node = 0; node < problem_.num_nodes(); ++node)
    for (int c = 0; c < 2; ++c)
      if (c == 0 ? jump_rows_[node].first : jump_rows_[node].second) rhs[ny_ + 2 * node + c] = row_values[2 * node + c];
  Answer answer;
  answer.singular = singular_;
  answer.rcond = lu_.rcond();
  const Eigen::VectorXd x = lu_.solve(rhs, prove_round_off_ ? &answer.at_round_off : nullptr);
  const Eigen::VectorXd y = x.head(ny_);
  answer.u = P_ * y;
  answer.r = x.tail(m2);
  for (const auto& [offset, size] : bands_) answer.band_z.push_back(y.segment(offset, size));
  return answer;
}

MixedSystem::NearNull MixedSystem::near_null() const {
  if (!factored_) throw std::logic_error("MixedSystem::near_null before any solve()");
  NearNull out;
  if (singular_) {  // no factors to iterate with: singular to working precision
    out.condition = 1e300;
    return out;
  }
  const SparseLU::NearNull v = lu_.near_null();
  out.condition = v.condition;
  if (v.x.size() == 0) return out;
  out.u = P_ * v.x.head(ny_);
  out.r = v.x.tail(2 * problem_.num_nodes());
  return out;
}

}  // namespace thinlayer
