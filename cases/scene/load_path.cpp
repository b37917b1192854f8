#include "cases/scene/load_path.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/SparseCore>

#include "core/fem/linear_system.h"
#include "core/linalg/least_imbalance.h"
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

// What an interface can put on a body in the friction-unbounded question, in words.
std::string support_words(const Model& model, int body) {
  std::set<std::string> held;
  for (const DirichletCondition& d : model.dirichlet)
    if (d.body == body && !d.nodes.empty()) held.insert(d.name + (d.component == 0 ? " holds u_x" : " holds u_y"));
  if (held.empty()) return "it has no support";
  std::string s;
  for (const std::string& h : held) s += (s.empty() ? "" : ", ") + h;
  return s;
}

// The statics LP (see the header): rows 3 per body (force x, force y, moment / size), columns the
// forces each interface node and each held support component can apply.
struct Statics {
  std::vector<Group> bodies;            // one per model body, loads included
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<bool> free_column;
  int columns = 0;
  Eigen::VectorXd loads;                // b: the loads' rows

  explicit Statics(const Model& model) {
    for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) bodies.push_back(make_group(model, {b}));
    loads = Eigen::VectorXd::Zero(3 * bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b)
      loads.segment<3>(3 * b) << bodies[b].force.x(), bodies[b].force.y(), bodies[b].moment / bodies[b].size;
  }
  // A force f applied at x on body b (and −f on body `other`, if any): one column.
  void add(int body, int other, const Eigen::Vector2d& x, const Eigen::Vector2d& f, bool free) {
    for (const auto& [b, sign] : {std::pair{body, 1.0}, std::pair{other, -1.0}}) {
      if (b < 0) continue;
      const Group& g = bodies[b];
      entries.emplace_back(3 * b, columns, sign * f.x());
      entries.emplace_back(3 * b + 1, columns, sign * f.y());
      entries.emplace_back(3 * b + 2, columns, sign * cross(x - g.centre, f) / g.size);
    }
    free_column.push_back(free);
    ++columns;
  }
  LeastImbalance solve(const Eigen::VectorXd& row_weight = {}) const {
    Eigen::SparseMatrix<double> G(loads.size(), columns);
    G.setFromTriplets(entries.begin(), entries.end());
    return least_imbalance(G, loads, free_column, row_weight);
  }
};

// The least imbalance of every body's balance: with the Coulomb cones (`cones`), or with any shear
// where the law has one (question 1). `where`: weigh a supported body's rows twice an unsupported
// one's, so that of the balances that leave an imbalance the one returned leaves it, where it can,
// on the bodies held by their interfaces alone (which body to name; its total is then weighted).
LeastImbalance statics_imbalance(const Model& model, const std::vector<Interface>& interfaces, bool cones,
                                 bool where = false) {
  Statics st(model);
  for (const Interface& i : interfaces) {
    const InterfaceLaw& law = i.law;
    for (const InterfaceNode& n : i.nodes) {
      const int minus = n.on_foundation() ? -1 : n.minus_body;
      const Eigen::Vector2d normal = n.normal, tangent = n.tangent();  // the push on the plus side: +n
      if (law.bilateral) {
        if (law.K_N() > 0) st.add(n.plus_body, minus, n.x, normal, true);
        if (law.K_T() > 0) st.add(n.plus_body, minus, n.x, tangent, true);
        continue;
      }
      if (!(law.K_N() > 0)) continue;  // an open law: no force (and so no friction either)
      if (!shears(law)) {
        st.add(n.plus_body, minus, n.x, normal, false);
      } else if (cones) {  // the two rays of the 2D Coulomb cone
        st.add(n.plus_body, minus, n.x, normal + law.friction * tangent, false);
        st.add(n.plus_body, minus, n.x, normal - law.friction * tangent, false);
      } else {
        st.add(n.plus_body, minus, n.x, normal, false);
        st.add(n.plus_body, minus, n.x, tangent, true);
      }
    }
  }
  for (const DirichletCondition& d : model.dirichlet)
    for (int node : d.nodes)
      st.add(d.body, -1, model.bodies[d.body].mesh.nodes.row(node).transpose(), Eigen::Vector2d::Unit(d.component), true);
  if (!where) return st.solve();
  Eigen::VectorXd weight(st.loads.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) weight.segment<3>(3 * b).setConstant(model.bodies[b].floating ? 1.0 : 2.0);
  return st.solve(weight);
}

// The bodies that carry the imbalance in a balance of statics_imbalance(..., where = true), the
// largest first.
std::vector<int> unbalanced_bodies(const Model& model, const LeastImbalance& lp) {
  std::vector<std::pair<double, int>> by_size;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const double off = lp.imbalance.segment<3>(3 * b).lpNorm<1>();
    if (off > 1e-9 * lp.imbalance.lpNorm<1>()) by_size.emplace_back(-off, b);
  }
  std::sort(by_size.begin(), by_size.end());
  std::vector<int> out;
  for (const auto& [size, b] : by_size) out.push_back(b);
  return out;
}

std::string loaded_with(const Group& g, const std::string& force_unit) {
  std::ostringstream s;
  s << "body " << g.name << " is loaded with (" << number(g.force.x()) << ", " << number(g.force.y()) << ") " << force_unit
    << "/mm";
  if (g.force.norm() <= 1e-9 * std::abs(g.moment) / g.size)  // a pure moment (a force's moment depends on the point)
    s << " and a moment " << number(g.moment) << " " << force_unit << " mm/mm";
  return s.str();
}

// The interfaces that touch body b, each with what it carries.
std::string interface_words(const std::vector<Interface>& interfaces, int b) {
  std::string s;
  for (const Interface& i : interfaces)
    for (const InterfaceNode& n : i.nodes)
      if (n.plus_body == b || (!n.on_foundation() && n.minus_body == b)) {
        s += (s.empty() ? ": " : "; ") + carries(i);
        break;
      }
  return s.empty() ? ": it touches no interface" : s;
}

// "the least imbalance ... is X N/mm (...)": the number the refusal stands on, and what it sums.
// `least`: the unweighted optimum (the proof); `where`: a balance that leaves it on the bodies
// held by their interfaces alone where it can.
std::string least_imbalance_words(const Model& model, double least, const LeastImbalance& where,
                                  const std::string& force_unit) {
  std::ostringstream s;
  s << "the least imbalance any such forces leave is " << number(least) << " " << force_unit
    << "/mm (summed over every body's force and moment rows, a moment over its body's size; on";
  const std::vector<int> bodies = unbalanced_bodies(model, where);
  for (std::size_t k = 0; k < bodies.size(); ++k) s << (k ? ", '" : " '") << model.bodies[bodies[k]].name << "'";
  s << " in the nearest balance; a linear program, GLPK's exact simplex)";
  return s.str();
}

std::string no_path_line(const Model& model, const std::vector<Interface>& interfaces, double least, const LeastImbalance& where,
                         const std::string& force_unit) {
  const int b = unbalanced_bodies(model, where).front();
  std::ostringstream s;
  s << loaded_with(make_group(model, {b}), force_unit)
    << " and nothing its supports and interfaces can carry balances that load: " << support_words(model, b)
    << "; its interfaces" << interface_words(interfaces, b) << ". Statics, every body's force and moment: "
    << least_imbalance_words(model, least, where, force_unit) << "; the load has no path to a support";
  return s.str();
}

std::string friction_overload_line(const Model& model, const std::vector<Interface>& interfaces, double least, const LeastImbalance& where,
                                   const std::string& force_unit) {
  const int b = unbalanced_bodies(model, where).front();
  std::ostringstream s;
  s << loaded_with(make_group(model, {b}), force_unit) << " and its contacts cannot hold it (its interfaces" << interface_words(interfaces, b) << ")"
    << ". Statics proves that no forces inside the friction cones (|r_T| <= f r_N) balance every body, force and moment: "
    << least_imbalance_words(model, least, where, force_unit) << "; friction cannot hold it";
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

LoadPath check_load_path(const Model& model, const std::vector<Interface>& interfaces, const std::string& force_unit) {
  LoadPath out;
  const Statics loads(model);
  out.loads = loads.loads.lpNorm<1>();
  if (!(out.loads > 0)) return out;  // nothing loaded (displacements imposed): the zero forces balance it
  const double refused = 1e-6 * out.loads;
  const LeastImbalance any_shear = statics_imbalance(model, interfaces, false);
  out.imbalance_any_shear = any_shear.total;
  if (any_shear.total > refused) {
    out.no_path = no_path_line(model, interfaces, any_shear.total, statics_imbalance(model, interfaces, false, true), force_unit);
    return out;
  }
  const LeastImbalance in_cones = statics_imbalance(model, interfaces, true);
  out.imbalance_in_cones = in_cones.total;
  if (in_cones.total > refused)
    out.friction_overload =
        friction_overload_line(model, interfaces, in_cones.total, statics_imbalance(model, interfaces, true, true), force_unit);
  return out;
}

std::vector<FrictionHold> friction_estimate(const Model& model, const std::vector<Interface>& interfaces) {
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
    if (!(h.group.force.norm() + std::abs(h.group.moment) / h.group.size > 0)) continue;  // unloaded (a layer)
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
  std::vector<FrictionHold> out;
  if (by_friction.empty()) return out;

  // The normal forces: the scene held stuck, one sparse solve.
  const LinearSystem system(model);
  const ContactProblem problem(system, stuck(interfaces));
  const SolveReport held = solve_bonded(problem);
  if (!held.converged) return out;
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
    out.push_back(f);
  }
  return out;
}

std::string friction_line(const FrictionHold& h, const std::string& force_unit) {
  const std::string unit = " " + force_unit + "/mm";
  std::ostringstream s;
  if (h.opens) {
    s << "body " << h.bodies << " is held by contact alone and none of its contacts is pressed in the joint held stuck "
      << "(an estimate, one linear solve: it pulls every one apart), so nothing may hold its load of " << number(h.scale)
      << unit;
    return s.str();
  }
  s << "body " << h.bodies << " is held by " << (h.load > 0 ? "friction" : "contact") << " alone: its load along the bondlines, "
    << number(h.load) << unit << ", " << (h.exceeded() ? "exceeds" : "is within") << " f x its normal force in the joint held stuck, "
    << h.friction << " x " << number(h.normal, 5) << " = " << number(h.capacity) << unit
    << " (an estimate, one linear solve: where the joint slides the normal force may differ)";
  return s.str();
}

}  // namespace thinlayer
