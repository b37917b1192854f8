#include "cases/scene/load_path.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "core/fem/linear_system.h"
#include "core/linalg/box_qp.h"
#include "core/solvers/bonded_solve.h"

namespace thinlayer {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string number(double x, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << x;
  return s.str();
}

// An interface law holds two bodies together as one: bilateral, stiff both ways.
bool joins(const InterfaceLaw& law) { return law.bilateral && law.K_N() > 0 && law.K_T() > 0; }
// It can carry a shear: a bilateral law with K_T > 0, or a contact law with K_T > 0 and f > 0.
bool shears(const InterfaceLaw& law) { return law.K_T() > 0 && (law.bilateral || law.friction > 0); }
bool is_layer(const std::string& body) { return body == "layer" || body.rfind("layer-", 0) == 0; }

// Groups of bodies joined by bilateral interfaces (union-find); -1 for a foundation side.
std::vector<int> held_groups(const Model& model, const std::vector<Interface>& interfaces) {
  std::vector<int> parent(model.bodies.size());
  for (std::size_t b = 0; b < parent.size(); ++b) parent[b] = static_cast<int>(b);
  std::function<int(int)> root = [&](int b) { return parent[b] == b ? b : parent[b] = root(parent[b]); };
  for (const Interface& i : interfaces)
    if (joins(i.law))
      for (const InterfaceNode& n : i.nodes)
        if (!n.on_foundation()) parent[root(n.plus_body)] = root(n.minus_body);
  std::vector<int> group(parent.size());
  for (std::size_t b = 0; b < parent.size(); ++b) group[b] = root(static_cast<int>(b));
  return group;
}

struct Group {
  std::vector<int> bodies;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double size = 1;                       // mm: the largest extent of its meshes
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // the loads' resultant, force per mm
  double moment = 0;                     // about `centre`, force · mm per mm
  std::string name;                      // its bodies other than layers, or its layers
};

Group make_group(const Model& model, const std::vector<int>& bodies) {
  Group g;
  g.bodies = bodies;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  int count = 0;
  for (int b : bodies) {
    const Mesh& m = model.bodies[b].mesh;
    for (int k = 0; k < m.num_nodes(); ++k) {
      const Eigen::Vector2d x = m.nodes.row(k).transpose();
      g.centre += x;
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
      ++count;
    }
  }
  g.centre /= std::max(count, 1);
  g.size = std::max((hi - lo).maxCoeff(), 1e-300);
  const std::set<int> in(bodies.begin(), bodies.end());
  for (const EdgeTraction& t : model.tractions) {
    if (!in.count(t.body)) continue;
    const Mesh& m = model.bodies[t.body].mesh;
    for (const auto& e : t.edges) {
      const Eigen::Vector2d a = m.nodes.row(e[0]).transpose(), b = m.nodes.row(e[1]).transpose();
      const Eigen::Vector2d f = (b - a).norm() * t.traction;
      g.force += f;
      g.moment += cross(0.5 * (a + b) - g.centre, f);
    }
  }
  for (const NodalForce& f : model.nodal_forces) {
    if (!in.count(f.body)) continue;
    g.force += f.force;
    g.moment += cross(model.bodies[f.body].mesh.nodes.row(f.node).transpose() - g.centre, f.force);
  }
  std::string adherents, layers;
  for (int b : bodies) {
    std::string& list = is_layer(model.bodies[b].name) ? layers : adherents;
    list += (list.empty() ? "'" : ", '") + model.bodies[b].name + "'";
  }
  g.name = adherents.empty() ? layers : adherents;
  return g;
}

// +1: the group is the node's plus side; −1: its minus side; 0: both or neither.
int side(const InterfaceNode& n, const std::set<int>& in) {
  const bool plus = in.count(n.plus_body) > 0, minus = !n.on_foundation() && in.count(n.minus_body) > 0;
  return plus == minus ? 0 : plus ? 1 : -1;
}

// What an interface can put on a body, in words.
std::string carries(const Interface& i) {
  const InterfaceLaw& law = i.law;
  std::string s = i.name + ": ";
  s += law.K_N() == 0 ? "no normal force" : law.bilateral ? "pushes and pulls" : "pushes only (contact)";
  if (law.K_T() == 0) s += ", no shear (mu_bar = 0)";
  else if (!law.bilateral && law.friction == 0) s += ", no shear (friction 0)";
  else if (!law.bilateral) s += ", shear up to friction " + number(law.friction) + " x its normal force";
  return s;
}

// Question 1: the loads against the cone of the forces the interfaces can put on the group.
// Residual of min ‖G a + b‖, a ≥ 0 (b = the loads; the moment scaled by the group's size),
// relative to ‖b‖.
double unbalanced(const Group& g, const std::vector<Interface>& interfaces, const std::set<int>& in) {
  std::vector<Eigen::Vector3d> generators;
  auto add = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& f) {
    generators.emplace_back(f.x(), f.y(), cross(x - g.centre, f) / g.size);
  };
  for (const Interface& i : interfaces) {
    std::vector<const InterfaceNode*> nodes;
    for (const InterfaceNode& n : i.nodes)
      if (side(n, in) != 0) nodes.push_back(&n);
    // At most ~64 nodes an interface, its ends always: the cone of a distributed force's resultant
    // and moment is spanned by its points' (a straight bondline's by its two ends).
    const std::size_t stride = std::max<std::size_t>(1, nodes.size() / 64);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (k % stride != 0 && k + 1 != nodes.size()) continue;
      const InterfaceNode& n = *nodes[k];
      const double s = side(n, in);
      const Eigen::Vector2d normal = s * n.normal, tangent = n.tangent();
      if (i.law.K_N() > 0) {
        add(n.x, normal);                        // a push away from the other side
        if (i.law.bilateral) add(n.x, -normal);  // and a pull
      }
      if (shears(i.law)) {
        add(n.x, tangent);
        add(n.x, -tangent);
      }
    }
  }
  const Eigen::Vector3d b(g.force.x(), g.force.y(), g.moment / g.size);
  if (generators.empty()) return 1.0;
  Eigen::MatrixXd G(3, generators.size());
  for (std::size_t j = 0; j < generators.size(); ++j) G.col(static_cast<Eigen::Index>(j)) = generators[j];
  Eigen::MatrixXd A = G.transpose() * G;
  // A tiny ridge makes the least-squares strictly convex (GᵀG has rank 3); it moves the residual by
  // about its square root times ‖b‖, far below the 1e-6 the check asks.
  A.diagonal().array() += 1e-14 * std::max(A.diagonal().maxCoeff(), 1e-300);
  const Eigen::VectorXd c = G.transpose() * b;
  Eigen::VectorXd a = Eigen::VectorXd::Zero(G.cols());
  solve_box_qp(A, c, Eigen::VectorXd::Zero(G.cols()), Eigen::VectorXd::Constant(G.cols(), INFINITY), a, 20000);
  return (G * a + b).norm() / b.norm();
}

std::string no_path_line(const Group& g, const std::vector<Interface>& interfaces, const std::set<int>& in,
                         const std::string& force_unit) {
  std::ostringstream s;
  s << "body " << g.name << " is loaded with (" << number(g.force.x()) << ", " << number(g.force.y()) << ") " << force_unit
    << "/mm";
  if (g.force.norm() <= 1e-9 * std::abs(g.moment) / g.size)  // a pure moment (a force's moment depends on the point)
    s << " and a moment " << number(g.moment) << " " << force_unit << " mm/mm";
  s << ", has no support, and nothing its interfaces can carry balances that load:";
  std::set<std::string> seen;
  for (const Interface& i : interfaces)
    for (const InterfaceNode& n : i.nodes)
      if (side(n, in) != 0) {
        if (seen.insert(i.name).second) s << (seen.size() == 1 ? " " : "; ") << carries(i);
        break;
      }
  if (seen.empty()) s << " it touches no interface";
  s << " (the load has no path to a support)";
  return s.str();
}

// The scene with every interface held stuck: each law bilateral with its own stiffnesses (a
// contact law without friction keeps no shear).
std::vector<Interface> stuck(const std::vector<Interface>& interfaces) {
  std::vector<Interface> out = interfaces;
  for (Interface& i : out)
    if (!i.law.bilateral)
      i.law = InterfaceLaw::make_bilateral(i.law.lambda_bar, i.law.friction > 0 ? i.law.mu_bar : 0.0);
  return out;
}

}  // namespace

const FrictionHold* LoadPath::exceeded() const {
  for (const FrictionHold& h : friction)
    if (h.exceeded()) return &h;
  return nullptr;
}

LoadPath check_load_path(const Model& model, const std::vector<Interface>& interfaces, const std::string& force_unit) {
  LoadPath out;
  const std::vector<int> group_of = held_groups(model, interfaces);
  std::map<int, std::vector<int>> members;
  for (std::size_t b = 0; b < group_of.size(); ++b) members[group_of[b]].push_back(static_cast<int>(b));
  struct Held {
    Group group;
    std::set<int> in;
  };
  std::vector<Held> by_friction;
  for (const auto& [root, bodies] : members) {
    const bool supported = std::any_of(bodies.begin(), bodies.end(), [&](int b) { return !model.bodies[b].floating; });
    if (supported) continue;
    Held h{make_group(model, bodies), std::set<int>(bodies.begin(), bodies.end())};
    const double scale = h.group.force.norm() + std::abs(h.group.moment) / h.group.size;
    if (!(scale > 0)) continue;  // unloaded (a layer): whatever holds it, nothing needs a path
    if (unbalanced(h.group, interfaces, h.in) > 1e-6) {
      out.no_path = no_path_line(h.group, interfaces, h.in, force_unit);
      return out;
    }
    // Held by contact and friction alone: no interface of the group is bilateral.
    bool contact_alone = true, touches = false;
    for (const Interface& i : interfaces)
      for (const InterfaceNode& n : i.nodes)
        if (side(n, h.in) != 0) {
          touches = true;
          contact_alone = contact_alone && !i.law.bilateral;
          break;
        }
    if (touches && contact_alone) by_friction.push_back(std::move(h));
  }
  if (by_friction.empty()) return out;

  // The normal forces: the scene held stuck, one sparse solve.
  const LinearSystem system(model);
  const ContactProblem problem(system, stuck(interfaces));
  const SolveReport held = solve_bonded(problem);
  out.capacity_estimated = held.converged;
  if (!held.converged) out.capacity_note = "the stuck joint's solve did not converge (" + held.message + ")";
  for (const Held& h : by_friction) {
    FrictionHold f;
    f.bodies = h.group.name;
    Eigen::Vector2d shear = Eigen::Vector2d::Zero();
    std::set<std::string> coefficients;
    bool pressed = false;
    int k = 0;
    for (const Interface& i : interfaces) {
      double N = 0;
      bool touches = false;
      for (const InterfaceNode& n : i.nodes) {
        const int s = side(n, h.in);
        if (s != 0 && held.r.size() > 2 * k + 1) {
          touches = true;
          N -= held.r[2 * k];                               // r_N < 0: compression
          shear += s * held.r[2 * k + 1] * n.tangent();     // the shear the interface puts on the group
        }
        ++k;
      }
      if (!touches) continue;
      pressed = pressed || N > 0;
      f.normal += std::max(N, 0.0);
      f.capacity += i.law.friction * std::max(N, 0.0);
      coefficients.insert(number(i.law.friction));
    }
    f.load = shear.norm();
    f.scale = h.group.force.norm();
    f.opens = !pressed;
    for (const std::string& c : coefficients) f.friction += (f.friction.empty() ? "" : " / ") + c;
    if (out.capacity_estimated) out.friction.push_back(f);
  }
  return out;
}

std::string friction_line(const FrictionHold& h, const std::string& force_unit) {
  const std::string unit = " " + force_unit + "/mm";
  std::ostringstream s;
  if (h.opens) {
    s << "body " << h.bodies << " is held by contact alone and none of its contacts is pressed (the joint held stuck "
      << "pulls every one apart, one linear solve): they open, and nothing holds its load of " << number(h.scale) << unit;
    return s.str();
  }
  s << "body " << h.bodies << " is held by " << (h.load > 0 ? "friction" : "contact") << " alone: its load along the bondlines, " << number(h.load) << unit << ", "
    << (h.exceeded() ? "exceeds" : "is within") << " f x its normal force, " << h.friction << " x " << number(h.normal, 5)
    << " = " << number(h.capacity) << unit
    << " (the normal force of the joint held stuck, one linear solve)" << (h.exceeded() ? ": friction cannot hold it" : "");
  return s.str();
}

}  // namespace thinlayer
