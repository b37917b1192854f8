#include "studies/drivers/joint_closed_forms.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "studies/tools/bondline_fields.h"
#include "studies/tools/closed_forms.h"
#include "studies/tools/lap_beam.h"

namespace thinlayer {

namespace {

// E' of a body: its Young's modulus, over 1 − ν² in plane strain (a plate's membrane stiffness).
double membrane_modulus(const SceneSpec& spec, int body) {
  const double l = spec.bodies[body].lambda, m = spec.bodies[body].mu;
  const double E = m * (3 * l + 2 * m) / (l + m), nu = l / (2 * (l + m));
  return spec.plane == PlaneHypothesis::Strain ? E / (1 - nu * nu) : E;
}

// A body's extent across a direction n (mm): its thickness across a straight bondline.
double extent(const Mesh& m, const Eigen::Vector2d& n) {
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < m.num_nodes(); ++k) {
    const double y = n.dot(m.nodes.row(k).transpose());
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return hi - lo;
}

// A strip lying along a straight bondline: its area fills most of its bounding box in the bondline's
// frame (a lap's or double lap's adherent: 1; a scarf's strip, cut across it: about 0.2).
bool strip_along(const Mesh& m, const Eigen::Vector2d& n) {
  const Eigen::Vector2d t(n.y(), -n.x());
  double area = 0;
  auto add = [&](const auto& cell) {
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const Eigen::Vector2d a = m.nodes.row(cell[k]).transpose(), b = m.nodes.row(cell[(k + 1) % cell.size()]).transpose();
      area += 0.5 * (a.x() * b.y() - b.x() * a.y());
    }
  };
  for (const auto& q : m.quads) add(q);
  for (const auto& tr : m.triangles) add(tr);
  return std::abs(area) > 0.8 * extent(m, n) * extent(m, t);
}

bool straight(const Interface& S) {
  for (const InterfaceNode& n : S.nodes)
    if ((n.normal - S.nodes.front().normal).norm() > 1e-9) return false;
  return true;
}

bool balanced(double a, double b) { return std::abs(a - b) <= 0.05 * std::max(a, b); }

// The single lap as a beam frame (studies/tools/lap_beam.h), in the bondline's frame: s along it
// from its first node, n across. Its supports and loads from the scene's model; each must act at an
// adherent's free end, along or across the bondline (a bondline along x or y).
struct SceneLap {
  LapBeam beam;
  std::string why_not;
  std::string ends[2];  // what lies beyond each end of the overlap (s = 0, s = its length)
  int body[2] = {-1, -1};
};

SceneLap scene_lap(const SceneFileBulk& bulk, const Interface& S) {
  SceneLap out;
  const Model& model = bulk.model();
  const Eigen::Vector2d x0 = S.nodes.front().x, t = (S.nodes.back().x - x0).normalized(), n(-t.y(), t.x());
  auto frame = [&](const Eigen::Vector2d& x) { return Eigen::Vector2d((x - x0).dot(t), (x - x0).dot(n)); };
  const double length = (S.nodes.back().x - x0).norm();
  out.beam.overlap_start = 0;
  out.beam.overlap_end = length;
  // The component of x/y along s and n: the bondline must lie along x or y.
  int along = -1;
  for (int c = 0; c < 2; ++c)
    if (std::abs(std::abs(t[c]) - 1) < 1e-9) along = c;
  if (along < 0) {
    out.why_not = "the bondline lies along neither x nor y (the beam model reads supports along it)";
    return out;
  }
  const double sign_s = t[along], sign_n = n[1 - along];
  const std::set<int> lap = {S.nodes.front().plus_body, S.nodes.front().minus_body};
  for (int b : lap) {
    double lo = INFINITY, hi = -INFINITY, nlo = INFINITY, nhi = -INFINITY;
    const Mesh& m = bulk.meshes().bodies[b];
    for (int k = 0; k < m.num_nodes(); ++k) {
      const Eigen::Vector2d p = frame(m.nodes.row(k).transpose());
      lo = std::min(lo, p.x()), hi = std::max(hi, p.x()), nlo = std::min(nlo, p.y()), nhi = std::max(nhi, p.y());
    }
    const double tol = 1e-6 * length;
    const int arm = lo < -tol && std::abs(hi - length) <= tol ? 0 : hi > length + tol && std::abs(lo) <= tol ? 1 : -1;
    if (arm < 0 || out.body[arm] >= 0) {
      out.why_not = "the adherents do not run on from opposite ends of the overlap, flush at the other";
      return out;
    }
    out.body[arm] = b;
    out.beam.arms[arm] = {arm == 0 ? lo : hi, 0.5 * (nlo + nhi), nhi - nlo, 0};
  }
  // What acts on each arm, grouped as given (a support's condition, a load), at its own point.
  auto arm_of = [&](int body) { return body == out.body[0] ? 0 : body == out.body[1] ? 1 : -1; };
  auto at_end = [&](int arm, const Eigen::Vector2d& p) {
    return std::abs(p.x() - out.beam.arms[arm].outer) <= out.beam.arms[arm].thickness;
  };
  std::map<std::pair<std::string, int>, LapEnd> supports;
  std::map<std::pair<std::string, int>, std::pair<double, double>> spread;  // across n, along s
  for (const DirichletCondition& d : model.dirichlet) {
    const int arm = arm_of(d.body);
    if (arm < 0 || d.nodes.empty()) continue;
    LapEnd& e = supports[{d.name, d.body}];
    e.arm = arm;
    double nlo = INFINITY, nhi = -INFINITY, slo = INFINITY, shi = -INFINITY;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int k : d.nodes) {
      const Eigen::Vector2d p = frame(model.bodies[d.body].mesh.nodes.row(k).transpose());
      centre += p / d.nodes.size();
      nlo = std::min(nlo, p.y()), nhi = std::max(nhi, p.y()), slo = std::min(slo, p.x()), shi = std::max(shi, p.x());
    }
    e.at = centre;
    const bool on_s = d.component == along;
    (on_s ? e.holds_s : e.holds_n) = true;
    (on_s ? e.value.x() : e.value.y()) = (on_s ? sign_s : sign_n) * d.value;
    // The rotation: a component held at two points apart across it.
    const double across = on_s ? nhi - nlo : shi - slo;
    if (across > 0.1 * out.beam.arms[arm].thickness) e.holds_rotation = true;
  }
  for (auto& [key, e] : supports) {
    if (!at_end(e.arm, e.at)) {
      out.why_not = "support '" + key.first + "' holds an adherent away from its end (the beam model takes end supports)";
      return out;
    }
    out.beam.ends.push_back(e);
  }
  auto add_load = [&](int body, const Eigen::Vector2d& x, const Eigen::Vector2d& F, const std::string& name) {
    const int arm = arm_of(body);
    if (arm < 0) return true;
    LapEnd e;
    e.arm = arm;
    e.at = frame(x);
    e.force = Eigen::Vector2d(F.dot(t), F.dot(n));
    if (!at_end(arm, e.at)) {
      out.why_not = "load '" + name + "' acts away from an adherent's end (the beam model takes end loads)";
      return false;
    }
    out.beam.ends.push_back(e);
    return true;
  };
  for (const EdgeTraction& tr : model.tractions)
    for (const auto& edge : tr.edges) {
      const Mesh& m = model.bodies[tr.body].mesh;
      const Eigen::Vector2d a = m.nodes.row(edge[0]).transpose(), b = m.nodes.row(edge[1]).transpose();
      if (!add_load(tr.body, 0.5 * (a + b), (b - a).norm() * tr.traction, tr.name)) return out;
    }
  for (const NodalForce& f : model.nodal_forces)
    if (!add_load(f.body, model.bodies[f.body].mesh.nodes.row(f.node).transpose(), f.force, f.name)) return out;
  for (int arm = 0; arm < 2; ++arm) {
    std::string held;
    for (const auto& [key, e] : supports)
      if (e.arm == arm) held += (held.empty() ? "" : ", ") + key.first;
    const Eigen::Vector2d p = x0 + (arm == 0 ? 0.0 : length) * t;
    std::ostringstream s;
    s << "(" << p.x() << ", " << p.y() << "): '" << bulk.spec().bodies[out.body[arm]].name << "' runs on to "
      << (held.empty() ? "its loaded end" : held);
    out.ends[arm] = s.str();
  }
  return out;
}

}  // namespace

JointClosedForms joint_closed_forms(const SceneFileBulk& bulk, const SceneRecord& limit) {
  JointClosedForms out;
  const SceneSpec& spec = bulk.spec();
  const std::vector<Interface> S = bulk.limit_interfaces(0, false);
  for (const SceneInterfaceSpec& i : spec.interfaces)
    if (!i.glue) {
      out.why_not = "a bondline gives no engineer's glue (E, nu, t): the closed forms need the glue's G and E";
      return out;
    }
  for (const Interface& s : S)
    if (!straight(s)) {
      out.why_not = "a bondline is not straight";
      return out;
    }
  const std::vector<BondlineField> fields = bondline_fields(bulk, limit);
  auto force_through = [&](std::size_t i) {  // Σ σ_T ℓ, with its sign
    double P = 0;
    for (std::size_t k = 0; k < fields[i].s.size(); ++k) P += fields[i].sigma_T[k] * fields[i].length[k];
    return P;
  };
  const Eigen::Vector2d n = S.front().nodes.front().normal;
  auto curves = [&](std::size_t i, double E1t1, double E2t2, const LapBending* bending, double t, double E) {
    const SceneGlueSpec& glue = *spec.interfaces[i].glue;
    const LameModuli g = lame_from_young(glue.E, glue.nu);
    ClosedFormCurves c;
    c.bondline = spec.interfaces[i].name;  // "" in the one-bondline form (its results: interface/S)
    c.s = fields[i].s;
    const double signed_P = force_through(i), sign = signed_P < 0 ? -1.0 : 1.0;
    c.P = std::abs(signed_P);
    c.length = c.s.back() - c.s.front();
    const Volkersen v{c.length, c.P, E1t1, E2t2, g.mu, glue.thickness};
    c.omega = v.omega();
    for (double s : c.s) c.volkersen_shear.push_back(sign * v.shear(s - c.s.front()));
    if (bending) {
      GolandReissner gr{c.length / 2, c.P, E, t, g.mu, glue.E, glue.thickness};
      c.k_nonlinear = gr.k_nonlinear();  // GR's own at this P: shown second, labelled
      // The linear statics of the joint's own supports (lap_beam.h); GR's formula takes one k for
      // both ends: their mean, the asymmetry said beside it.
      gr.k_given = 0.5 * (bending->k[0] + bending->k[1]);
      gr.k_prime_given = 0.5 * (bending->k_prime[0] + bending->k_prime[1]);
      c.k_ends[0] = bending->k[0];
      c.k_ends[1] = bending->k[1];
      c.k_prime = gr.k_prime();
      c.k = gr.k();
      c.beta = gr.beta();
      c.lambda = gr.lambda();
      for (double s : c.s) {
        const double x = s - c.s.front() - c.length / 2;
        c.gr_shear.push_back(sign * gr.shear(x));
        c.gr_peel.push_back(gr.peel(x));
      }
    }
    return c;
  };
  for (const Interface& s : S)
    for (const int b : {s.nodes.front().plus_body, s.nodes.front().minus_body})
      if (!strip_along(bulk.meshes().bodies[b], n)) {
        out.why_not = "adherent '" + spec.bodies[b].name + "' is no strip along the bondlines (a scarf, a plug ...): no lap";
        return out;
      }
  if (S.size() == 1) {
    const int p = S[0].nodes.front().plus_body, m = S[0].nodes.front().minus_body;
    const double tp = extent(bulk.meshes().bodies[p], n), tm = extent(bulk.meshes().bodies[m], n);
    const double Ep = membrane_modulus(spec, p), Em = membrane_modulus(spec, m);
    if (!balanced(Ep * tp, Em * tm)) {
      out.why_not = "a single lap of unbalanced adherents (E' t " + std::to_string(Ep * tp) + " and " + std::to_string(Em * tm) +
                    " N/mm): the closed forms here are written for equal ones";
      return out;
    }
    out.joint = "single lap";
    SceneLap lap = scene_lap(bulk, S[0]);
    LapBending bending;
    if (lap.why_not.empty()) {
      for (int arm = 0; arm < 2; ++arm) lap.beam.arms[arm].E = membrane_modulus(spec, lap.body[arm]);
      bending = lap_bending(lap.beam);
      if (!bending.solved) lap.why_not = bending.why_not;
    }
    ClosedFormCurves c = curves(0, Em * tm, Ep * tp, bending.solved ? &bending : nullptr, 0.5 * (tp + tm), 0.5 * (Ep + Em));
    c.t_1 = tm;
    c.t_2 = tp;
    c.start = lap.ends[0];
    c.end = lap.ends[1];
    if (!bending.solved) c.gr_why_not = "Goland-Reissner not drawn: its bending factor from linear statics needs " + lap.why_not;
    out.bondlines.push_back(std::move(c));
  } else if (S.size() == 2) {
    const Eigen::Vector2d n2 = S[1].nodes.front().normal;
    if (std::abs(std::abs(n.dot(n2)) - 1) > 1e-9) {
      out.why_not = "two bondlines that are not parallel";
      return out;
    }
    const std::set<int> a = {S[0].nodes.front().plus_body, S[0].nodes.front().minus_body};
    const std::set<int> b = {S[1].nodes.front().plus_body, S[1].nodes.front().minus_body};
    std::vector<int> shared;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
    if (shared.size() != 1) {
      out.why_not = "two bondlines that do not share one adherent";
      return out;
    }
    const int inner = shared.front();
    const double ti = extent(bulk.meshes().bodies[inner], n), Ei = membrane_modulus(spec, inner);
    for (std::size_t i = 0; i < 2; ++i) {
      const int outer = *(i == 0 ? a : b).begin() == inner ? *std::next((i == 0 ? a : b).begin()) : *(i == 0 ? a : b).begin();
      const double to = extent(bulk.meshes().bodies[outer], n), Eo = membrane_modulus(spec, outer);
      if (!balanced(Eo * to, Ei * ti / 2)) {
        out.bondlines.clear();
        out.why_not = "a double lap whose outer strip is not as stiff as half the inner one (E' t " + std::to_string(Eo * to) +
                      " against " + std::to_string(Ei * ti / 2) + " N/mm): the closed forms here are written for balanced ones";
        return out;
      }
      ClosedFormCurves c = curves(i, Ei * ti / 2, Eo * to, nullptr, 0, 0);
      c.t_1 = ti / 2;
      c.t_2 = to;
      out.bondlines.push_back(std::move(c));
    }
    out.joint = "double lap";
  } else {
    out.why_not = "more than two bondlines";
    return out;
  }
  out.assumptions = out.joint == "single lap"
                        ? "Volkersen (shear lag, no bending) and Goland-Reissner (the bending of the eccentric load, "
                          "identical adherents, one factor k for both ends) with k and k' from linear statics of the "
                          "joint's own supports (a beam frame: the model is linear, so k does not depend on the load); "
                          "plane-strain E' = E/(1-nu^2); P = the shear the limit law carries"
                        : "Volkersen (shear lag, no bending) on each bondline, the inner strip's half against the outer "
                          "strip; Goland-Reissner's bending is not drawn (the outer strips' bending is not modelled "
                          "here); plane-strain E' = E/(1-nu^2); P = the shear the limit law carries on that bondline";
  return out;
}

void write_joint_closed_forms(H5Writer& out, const std::string& group, const JointClosedForms& f,
                              const std::string& stress, const std::string& force) {
  out.attr(group, "joint", f.joint);
  out.attr(group, "why_not", f.why_not);
  out.attr(group, "assumptions", f.assumptions);
  out.attr(group, "description", std::string("the classical closed forms beside the computed bondline curves "
                                             "(studies/tools/closed_forms.h)"));
  for (const ClosedFormCurves& c : f.bondlines) {
    const std::string g = group + "/" + (c.bondline.empty() ? std::string("S") : c.bondline);
    out.dataset(g + "/s", c.s);
    out.attr(g + "/s", "units", std::string("mm"));
    out.dataset(g + "/volkersen_shear", c.volkersen_shear);
    out.attr(g + "/volkersen_shear", "units", stress);
    if (!c.gr_shear.empty()) {
      out.dataset(g + "/goland_reissner_shear", c.gr_shear);
      out.attr(g + "/goland_reissner_shear", "units", stress);
      out.dataset(g + "/goland_reissner_peel", c.gr_peel);
      out.attr(g + "/goland_reissner_peel", "units", stress);
      out.attr(g, "k", c.k);
      out.attr(g, "k_start", c.k_ends[0]);
      out.attr(g, "k_end", c.k_ends[1]);
      out.attr(g, "k_prime", c.k_prime);
      out.attr(g, "k_nonlinear", c.k_nonlinear);
      out.attr(g, "beta", c.beta);
      out.attr(g, "lambda", c.lambda);
    }
    out.attr(g, "P", c.P);
    out.attr(g, "P_units", force + "/mm");
    out.attr(g, "overlap", c.length);
    out.attr(g, "omega", c.omega);
    out.attr(g, "t_1", c.t_1);
    out.attr(g, "t_2", c.t_2);
    out.attr(g, "start", c.start);
    out.attr(g, "end", c.end);
    out.attr(g, "goland_reissner_why_not", c.gr_why_not);
  }
}

}  // namespace thinlayer
