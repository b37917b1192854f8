#include "core/solvers/first_order_layer.h"

#include <cmath>
#include <stdexcept>

namespace thinlayer {

double LayerAtThickness::plane_lambda() const {
  return plane == PlaneHypothesis::Strain ? lambda : 2 * lambda * mu / (lambda + 2 * mu);
}

namespace {

// What the limit answer lets the layer hold at a node: its normal direction wherever the node is
// not open, its tangential direction where it sticks or is bonded (a slide's force is set by
// friction, and a frictionless node carries none).
bool holds_normal(Active a) { return a != Active::Gap; }
bool holds_tangential(Active a) { return a == Active::Stick || a == Active::Bonded; }

// The four nodes of a segment's layer cell: plus and minus at each end, x and y each.
struct SegmentDofs {
  int dof_x[4];  // global DOF of u_x: u⁺_k, u⁻_k, u⁺_k+1, u⁻_k+1 (-1: the rigid foundation)
};

using Row8 = Eigen::Matrix<double, 1, 8>;

// Row vectors over v = [u⁺_k, u⁻_k, u⁺_k+1, u⁻_k+1] (x, y each) of
//   j̄·e = ½ (j_k + j_k+1)·e   and   Δm·e = ½ (u⁺ + u⁻)_k+1·e − ½ (u⁺ + u⁻)_k·e.
Row8 mean_jump(const Eigen::Vector2d& e) {
  Row8 r;
  r << 0.5 * e.x(), 0.5 * e.y(), -0.5 * e.x(), -0.5 * e.y(), 0.5 * e.x(), 0.5 * e.y(), -0.5 * e.x(), -0.5 * e.y();
  return r;
}
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
  }

  Eigen::Vector2d displacement(int dof_x) const {
    return dof_x < 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(u_[dof_x], u_[dof_x + 1]);
  }
  // A force on one side of node k (global problem numbering).
  void add(int k, bool plus, const Eigen::Vector2d& f) {
    const InterfaceNode& n = problem_.node(k);
    const int dof = plus ? n.plus_dof_x : n.minus_dof_x;
    if (dof < 0) return;  // the rigid foundation takes it
    load_.body_forces.segment<2>(dof) += f;
    if (plus) load_.plus_force[k] += f;
  }
  void add_row(int row, double value) { load_.row_values[row] += value; }
  FirstOrderLoad take() { return std::move(load_); }

 private:
  const ContactProblem& problem_;
  const Eigen::VectorXd& u_;
  FirstOrderLoad load_;
};

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
  else if (bilateral) carries = true;                                    // a bonded layer carries both ways
  else carries = row == 0 ? j < 0 : holds_normal(status);               // unilateral: pressed; shear where closed
  if (!carries) return;
  const double dK = K_layer - K_law;  // stress unit per mm
  const Eigen::Vector2d f = -dK * n.length * j * e;  // −∂/∂u⁺ of ½ ΔK ℓ j²
  b.add(k, true, f);
  b.add(k, false, -f);
}

// The coupling and membrane terms on the segment between nodes k and k+1 of one interface.
void segment_terms(LoadBuilder& b, const ContactProblem& problem, int k, const LayerAtThickness& layer,
                   const std::vector<Active>& statuses) {
  const InterfaceNode &n0 = problem.node(k), &n1 = problem.node(k + 1);
  const double h = (n1.x - n0.x).norm();
  if (!(h > 0)) return;
  const Eigen::Vector2d es = (n1.x - n0.x) / h;
  Eigen::Vector2d en(-es.y(), es.x());
  if (en.dot(n0.normal + n1.normal) < 0) en = -en;  // minus → plus, as the nodes' normals
  const bool normal = holds_normal(statuses[k]) && holds_normal(statuses[k + 1]);
  const bool tangential = holds_tangential(statuses[k]) && holds_tangential(statuses[k + 1]);
  if (!normal && !tangential) return;
  const SegmentDofs dofs{{n0.plus_dof_x, n0.minus_dof_x, n1.plus_dof_x, n1.minus_dof_x}};
  Eigen::Matrix<double, 8, 1> v;
  for (int i = 0; i < 4; ++i) v.segment<2>(2 * i) = b.displacement(dofs.dof_x[i]);
  const Row8 A = mean_jump(en), Bs = mean_jump(es), C = mean_step(es), D = mean_step(en);
  const double a = A * v, bb = Bs * v, c = C * v, d = D * v;
  const double lambda = layer.plane_lambda(), mu = layer.mu, t = layer.thickness;
  Row8 gradient = Row8::Zero();  // ∂W₁/∂v
  if (normal) gradient += lambda * (c * A + a * C);               // λ j_n ∂_s m_s
  if (tangential) {
    gradient += mu * (d * Bs + bb * D);                            // μ j_s ∂_s m_n
    gradient += (t / h) * ((lambda + 2 * mu) * c * C + mu * d * D);  // (t/2)[(λ+2μ)(∂_s m_s)² + μ(∂_s m_n)²] h
  }
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
// where the mesh is finer than the zone.
void end_deficit(LoadBuilder& b, const ContactProblem& problem, int end, int step, int count,
                 const LayerAtThickness& layer, const std::vector<Active>& statuses, const Eigen::VectorXd& r) {
  const InterfaceNode& e = problem.node(end);
  const double sigma[2] = {r[2 * end] / e.length, r[2 * end + 1] / e.length};
  const bool held[2] = {holds_normal(statuses[end]), holds_tangential(statuses[end])};
  const double zone[2] = {layer.end_deficit_N * layer.thickness, layer.end_deficit_T * layer.thickness};
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
      }
      for (int k = k0; k + 1 < k0 + m; ++k) segment_terms(b, problem, k, layer, statuses);
      end_deficit(b, problem, k0, +1, m, layer, statuses, r);
      if (m > 1) end_deficit(b, problem, k0 + m - 1, -1, m, layer, statuses, r);
    }
    k0 += m;
  }
  return b.take();
}

}  // namespace thinlayer
