#include "core/solvers/first_order_layer.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

double LayerAtThickness::plane_lambda() const {
  return plane == PlaneHypothesis::Strain ? lambda : 2 * lambda * mu / (lambda + 2 * mu);
}

namespace {

// What the limit answer lets the layer hold at a node: its normal direction wherever the node is
// not open, its tangential direction where it sticks or is bonded (a slide's tangential force is
// friction's, f |σ_N|, and a frictionless node carries none).
bool holds_normal(Active a) { return a != Active::Gap; }
bool holds_tangential(Active a) { return a == Active::Stick || a == Active::Bonded; }
bool slides(Active a) { return a == Active::SlidePositive || a == Active::SlideNegative; }

using Row8 = Eigen::Matrix<double, 1, 8>;

// Δm·e = ½ (u⁺ + u⁻)_k+1·e − ½ (u⁺ + u⁻)_k·e as a row over v = [u⁺_k, u⁻_k, u⁺_k+1, u⁻_k+1] (x, y each).
Row8 mean_step(const Eigen::Vector2d& e) {
  Row8 r;
  r << -0.5 * e.x(), -0.5 * e.y(), -0.5 * e.x(), -0.5 * e.y(), 0.5 * e.x(), 0.5 * e.y(), 0.5 * e.x(), 0.5 * e.y();
  return r;
}

class LoadBuilder {
 public:
  LoadBuilder(const ContactProblem& problem, const Eigen::VectorXd& u_full) : problem_(problem), u_(u_full) {
    load_.body_forces = Eigen::VectorXd::Zero(u_full.size());
    load_.row_values = Eigen::VectorXd::Zero(2 * problem.num_nodes());
    load_.plus_force.assign(problem.num_nodes(), Eigen::Vector2d::Zero());
    load_.minus_force.assign(problem.num_nodes(), Eigen::Vector2d::Zero());
  }

  Eigen::Vector2d displacement(int dof_x) const {
    return dof_x < 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(u_[dof_x], u_[dof_x + 1]);
  }
  Eigen::Vector2d mean(int k) const {  // m = (u⁺ + u⁻)/2 at node k
    const InterfaceNode& n = problem_.node(k);
    return 0.5 * (displacement(n.plus_dof_x) + displacement(n.minus_dof_x));
  }
  // A force on one side of node k (global problem numbering).
  void add(int k, bool plus, const Eigen::Vector2d& f) {
    const InterfaceNode& n = problem_.node(k);
    (plus ? load_.plus_force : load_.minus_force)[k] += f;  // the face's traction, a foundation's too
    const int dof = plus ? n.plus_dof_x : n.minus_dof_x;
    if (dof < 0) return;  // the rigid foundation takes it
    load_.body_forces.segment<2>(dof) += f;
  }
  void add_row(int row, double value) { load_.row_values[row] += value; }
  FirstOrderLoad take() { return std::move(load_); }

 private:
  const ContactProblem& problem_;
  const Eigen::VectorXd& u_;
  FirstOrderLoad load_;
};

// The unit vector along the bondline's chain at node k of an interface running over [k0, k0 + m):
// ±t (t = n turned clockwise), the sign of the chain's direction there.
Eigen::Vector2d chain_direction(const ContactProblem& problem, int k, int k0, int m) {
  const InterfaceNode& n = problem.node(k);
  const Eigen::Vector2d along = problem.node(std::min(k + 1, k0 + m - 1)).x - problem.node(std::max(k - 1, k0)).x;
  return along.dot(n.tangent()) >= 0 ? n.tangent() : Eigen::Vector2d(-n.tangent());
}

// The spring's misfit at node k, row e (0: normal, 1: tangential): the layer's stiffness K_layer
// against the law's K_law, both per unit length of bondline.
void spring_misfit(LoadBuilder& b, const ContactProblem& problem, int k, int row, double K_layer, double K_law,
                   bool bilateral, Active status, const Eigen::VectorXd& r) {
  const InterfaceNode& n = problem.node(k);
  const Eigen::Vector2d e = row == 0 ? n.normal : n.tangent();
  const double j = (b.displacement(n.plus_dof_x) - b.displacement(n.minus_dof_x)).dot(e);  // (u⁺ − u⁻)·e, mm
  if (std::isinf(K_law)) {
    // A rigid row allows no jump; the layer's compliance 1/(K_layer ℓ) is what it leaves out:
    // d = B u + C r + ΔC r = 0, so B δu + C δr = −ΔC r₀ (on the rows the answer holds).
    const bool held = row == 0 ? holds_normal(status) : holds_tangential(status);
    if (held && K_layer > 0) b.add_row(2 * k + row, -r[2 * k + row] / (K_layer * n.length));
    return;
  }
  bool carries;
  if (K_law > 0) carries = row == 0 ? holds_normal(status) : holds_tangential(status);
  else if (bilateral) carries = true;                      // a bonded layer carries both ways
  else carries = row == 0 ? j < 0 : holds_normal(status);  // unilateral: pressed; shear where closed
  if (!carries) return;
  const double dK = K_layer - K_law;  // stress unit per mm
  const Eigen::Vector2d f = -dK * n.length * j * e;  // −∂/∂u⁺ of ½ ΔK ℓ j²
  b.add(k, true, f);
  b.add(k, false, -f);
}

// The eigen-jump at node k: the spring acts on (j_n + t ν* ∂_s m_s, j_s + t ∂_s m_n) (the header's
// squares), so the law's jump equation d = [u] − e + C r = 0 takes e on the right-hand side, with
// ∂_s m at the node from the segments on either side whose nodes are both held (their Δm over
// their lengths). On the rows the answer makes jump equations (MixedSystem::solve_again: a slide's
// normal row, and friction follows; a stick's or a bond's both rows; a rigid law's too, whose jump
// is then the eigen-jump itself).
void eigen_jump(LoadBuilder& b, const ContactProblem& problem, int k, int k0, int m, const LayerAtThickness& layer,
                const std::vector<Active>& statuses) {
  if (!holds_normal(statuses[k])) return;
  const InterfaceNode& n = problem.node(k);
  const Eigen::Vector2d es = chain_direction(problem, k, k0, m);
  // Σ ±(m_o − m_k) over Σ |x_o − x_k|, the sign that of (x_o − x_k)·es: (m_k+1 − m_k−1)/(h₁ + h₂)
  // between two held neighbours, the one segment's difference quotient at an end.
  Eigen::Vector2d step = Eigen::Vector2d::Zero();
  double length = 0;
  for (int other : {k - 1, k + 1}) {
    if (other < k0 || other >= k0 + m || !holds_normal(statuses[other])) continue;
    const Eigen::Vector2d dx = problem.node(other).x - n.x;
    step += (dx.dot(es) >= 0 ? 1.0 : -1.0) * (b.mean(other) - b.mean(k));
    length += dx.norm();
  }
  if (!(length > 0)) return;
  const Eigen::Vector2d gradient = step / length;  // ∂_s m along es
  const double lambda = layer.plane_lambda(), mu = layer.mu, t = layer.thickness;
  const double nu_star = lambda / (lambda + 2 * mu);
  // [u]_N = −j_n: the effective jump [u]_N − t ν* ∂_s m_s; [u]_T = t·j: [u]_T + (es·t) t ∂_s m_n.
  b.add_row(2 * k, t * nu_star * gradient.dot(es));
  if (holds_tangential(statuses[k])) b.add_row(2 * k + 1, -es.dot(n.tangent()) * t * gradient.dot(n.normal));
}

// The force the squares put on the mean m over the segment k, k+1: ∂/∂m of ∫ t [σ_nn ν* ∂_s m_s +
// σ_sn ∂_s m_n] ds with the layer's stress σ = the limit answer's traction (the bracket of each square
// is −σ/K at first order), mean over the segment; and the membrane (t/2) E* (∂_s m_s)² where the
// layer's in-plane strain is the adherents' (both nodes stick or are bonded).
// Its gradient over v = [u⁺_k, u⁻_k, u⁺_k+1, u⁻_k+1]; zero where a node of the segment is open.
Row8 segment_gradient(const LoadBuilder& b, const ContactProblem& problem, int k, const LayerAtThickness& layer,
                      const std::vector<Active>& statuses, const Eigen::VectorXd& r) {
  const InterfaceNode &n0 = problem.node(k), &n1 = problem.node(k + 1);
  if (!holds_normal(statuses[k]) || !holds_normal(statuses[k + 1])) return Row8::Zero();
  const double h = (n1.x - n0.x).norm();
  if (!(h > 0)) return Row8::Zero();
  const Eigen::Vector2d es = (n1.x - n0.x) / h;
  Eigen::Vector2d en(-es.y(), es.x());
  if (en.dot(n0.normal + n1.normal) < 0) en = -en;  // minus → plus, as the nodes' normals
  // The layer's stress from the nodal tractions (force on plus = −n σ_N + t σ_T = −σ_layer n):
  // σ_nn = σ_N, σ_sn = −σ_T (es·t), the mean of the segment's two nodes.
  double sigma_nn = 0, sigma_sn = 0;
  for (int i : {k, k + 1}) {
    const InterfaceNode& n = problem.node(i);
    sigma_nn += 0.5 * r[2 * i] / n.length;
    sigma_sn -= 0.5 * (r[2 * i + 1] / n.length) * es.dot(n.tangent());
  }
  Eigen::Matrix<double, 8, 1> v;
  const int dofs[4] = {n0.plus_dof_x, n0.minus_dof_x, n1.plus_dof_x, n1.minus_dof_x};
  for (int i = 0; i < 4; ++i) v.segment<2>(2 * i) = b.displacement(dofs[i]);
  const Row8 C = mean_step(es), D = mean_step(en);
  const double lambda = layer.plane_lambda(), mu = layer.mu, t = layer.thickness;
  const double nu_star = lambda / (lambda + 2 * mu);
  const double membrane = 4 * mu * (lambda + mu) / (lambda + 2 * mu);  // E*: the membrane's normal stress free
  Row8 gradient = t * (nu_star * sigma_nn * C + sigma_sn * D);
  if (holds_tangential(statuses[k]) && holds_tangential(statuses[k + 1])) gradient += (t / h) * membrane * (C * v) * C;
  return gradient;
}

// A segment gradient as forces on its two nodes' sides.
void add_segment_forces(LoadBuilder& b, int k, const Row8& gradient) {
  b.add(k, true, -gradient.segment<2>(0).transpose());
  b.add(k, false, -gradient.segment<2>(2).transpose());
  b.add(k + 1, true, -gradient.segment<2>(4).transpose());
  b.add(k + 1, false, -gradient.segment<2>(6).transpose());
}

// The free end of a bondline at node `end` (its first or last node; `step` +1 or −1 runs inward): the
// layer's end face carries no traction, and its traction on the faces falls short of the spring's
// over an end zone of a few t. Its resultants are the end cell's deficits α_N t σ_N and α_T t σ_T
// (core/solvers/layer_end_cell.h; σ the limit's traction at the end). Spread over the nodes as the
// profile e^(−x/(α t)) of the same resultant (x the arc length from the end): each node gets what
// falls within its tributary length, so that the plus face's traction is not a spike at the end node
// where the mesh is finer than the zone. Where the end slides, its tangential traction is friction's
// and falls with the normal one (the same fraction).
void end_deficit(LoadBuilder& b, const ContactProblem& problem, int end, int step, int count,
                 const LayerAtThickness& layer, const std::vector<Active>& statuses, const Eigen::VectorXd& r) {
  const InterfaceNode& e = problem.node(end);
  const double sigma[2] = {r[2 * end] / e.length, r[2 * end + 1] / e.length};
  const Active status = statuses[end];
  const double zone[2] = {layer.end_deficit_N * layer.thickness,
                          (slides(status) ? layer.end_deficit_N : layer.end_deficit_T) * layer.thickness};
  const bool held[2] = {holds_normal(status), holds_tangential(status) || slides(status)};
  double a = 0;  // arc length from the end to the start of node j's tributary interval
  for (int i = 0, j = end; i < count; ++i, j += step) {
    const InterfaceNode& n = problem.node(j);
    const double b_end = a + n.length;  // its tributary interval [a, a + ℓ_j]
    double dr[2] = {0, 0};
    for (int c = 0; c < 2; ++c)
      if (held[c] && zone[c] > 0) dr[c] = -sigma[c] * zone[c] * (std::exp(-a / zone[c]) - std::exp(-b_end / zone[c]));
    const Eigen::Vector2d f = -n.normal * dr[0] + n.tangent() * dr[1];  // on the plus side, as Bᵀ r
    b.add(j, true, f);
    b.add(j, false, -f);
    a = b_end;
    if (a > 12 * std::max(zone[0], zone[1])) break;  // e^-12: nothing left
  }
}

}  // namespace

FirstOrderLoad first_order_layer_load(const ContactProblem& problem, const std::vector<LayerAtThickness>& layers,
                                      const Eigen::VectorXd& u_full, const Eigen::VectorXd& r,
                                      const std::vector<Active>& statuses) {
  const std::vector<Interface>& interfaces = problem.interfaces();
  if (layers.size() != interfaces.size()) throw std::invalid_argument("first_order_layer_load: one layer per interface");
  if (r.size() != 2 * problem.num_nodes() || static_cast<int>(statuses.size()) != problem.num_nodes())
    throw std::invalid_argument("first_order_layer_load: r and the statuses must fit the problem");
  LoadBuilder b(problem, u_full);
  int k0 = 0;
  for (std::size_t i = 0; i < interfaces.size(); ++i) {
    const int m = static_cast<int>(interfaces[i].nodes.size());
    const LayerAtThickness& layer = layers[i];
    if (layer.thickness > 0) {
      if (!(layer.mu > 0) || !(layer.lambda + layer.mu > 0))
        throw std::invalid_argument("first_order_layer_load: a layer needs mu > 0 and lambda + mu > 0");
      const InterfaceLaw& law = interfaces[i].law;
      // The layer's own spring, seen in the plane (plane stress: λ*), against the law's.
      const double K_N = (layer.plane_lambda() + 2 * layer.mu) / layer.thickness, K_T = layer.K_T();
      for (int k = k0; k < k0 + m; ++k) {
        spring_misfit(b, problem, k, 0, K_N, law.K_N(), law.bilateral, statuses[k], r);
        spring_misfit(b, problem, k, 1, K_T, law.K_T(), law.bilateral, statuses[k], r);
        eigen_jump(b, problem, k, k0, m, layer, statuses);
      }
      for (int k = k0; k + 1 < k0 + m; ++k) add_segment_forces(b, k, segment_gradient(b, problem, k, layer, statuses, r));
      if (layer.free_ends) {
        end_deficit(b, problem, k0, +1, m, layer, statuses, r);
        if (m > 1) end_deficit(b, problem, k0 + m - 1, -1, m, layer, statuses, r);
      } else if (m > 1) {
        // Held ends: the layer goes on into a support, which takes the force the segments leave at
        // the end nodes (their stress's part at that node, as if the next segment were there).
        const Row8 first = segment_gradient(b, problem, k0, layer, statuses, r);
        const Row8 last = segment_gradient(b, problem, k0 + m - 2, layer, statuses, r);
        for (int c = 0; c < 2; ++c) {
          b.add(k0, c == 0, first.segment<2>(2 * c).transpose());
          b.add(k0 + m - 1, c == 0, last.segment<2>(4 + 2 * c).transpose());
        }
      }
    }
    k0 += m;
  }
  return b.take();
}

}  // namespace thinlayer
