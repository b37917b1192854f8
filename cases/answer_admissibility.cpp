#include "cases/answer_admissibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cases/film_admissibility.h"

namespace thinlayer {

namespace {

bool is_layer(const std::string& body) { return body == "layer" || body.rfind("layer-", 0) == 0; }

}  // namespace

AnswerAdmissibility answer_admissibility(const SceneRecord& r) {
  AnswerAdmissibility a;
  a.limit = r.text.count("mode") && r.text.at("mode") == "limit";
  const std::size_t bodies = r.body_names.size();
  std::vector<Eigen::Vector2d> lo(bodies, Eigen::Vector2d::Constant(INFINITY)), hi(bodies, Eigen::Vector2d::Constant(-INFINITY));
  std::vector<double> u_max(bodies, 0.0);
  for (Eigen::Index c = 0; c < r.cells.rows(); ++c) {
    const int b = r.cell_body.at(c);
    for (Eigen::Index k = 0; k < r.cells.cols(); ++k) {
      const int node = r.cells(c, k);
      if (node < 0) continue;
      const Eigen::Vector2d x = r.nodes.row(node).transpose();
      lo[b] = lo[b].cwiseMin(x);
      hi[b] = hi[b].cwiseMax(x);
      u_max[b] = std::max(u_max[b], r.u.row(node).norm());
    }
  }
  for (std::size_t b = 0; b < bodies; ++b) {
    if (is_layer(r.body_names[b]) || !(hi[b].x() >= lo[b].x())) continue;
    const double size = (hi[b] - lo[b]).maxCoeff();
    const double fraction = size > 0 ? u_max[b] / size : 0.0;
    if (fraction >= a.displacement_over_size) {
      a.displacement_over_size = fraction;
      a.body = r.body_names[b];
      a.displacement = u_max[b];
      a.size = size;
    }
  }
  if (a.limit)
    for (const InterfaceFields& f : r.interfaces) {
      const Eigen::VectorXd h = element_sizes_along(f);
      for (Eigen::Index k = 0; k < f.jump_T.size(); ++k)
        if (h[k] > 0 && std::abs(f.jump_T[k]) / h[k] > a.slip_over_h) {
          a.slip_over_h = std::abs(f.jump_T[k]) / h[k];
          a.slip_where = f.name + " node " + std::to_string(k);
        }
    }
  return a;
}

void record_answer_admissibility(SceneRecord& r) {
  const AnswerAdmissibility a = answer_admissibility(r);
  r.numbers["displacement_over_size"] = a.displacement_over_size;
  r.text["displacement_body"] = a.body;
  r.numbers["displacement_max"] = a.displacement;
  r.numbers["displacement_body_size"] = a.size;
  if (a.limit) {
    r.numbers["slip_over_h"] = a.slip_over_h;
    r.text["slip_where"] = a.slip_where;
  }
}

std::string displacement_warning_line(const SceneRecord& r) {
  if (!r.numbers.count("displacement_over_size") || r.numbers.at("displacement_over_size") <= displacement_warning) return "";
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "warning: body '%s' moves %.3g mm, %.3g times its size (%.3g mm): the model is linear and assumes small "
                "displacements (warned above %g %% of a body's size); hold the joint as it is held (a support left free?)",
                r.text.at("displacement_body").c_str(), r.numbers.at("displacement_max"),
                r.numbers.at("displacement_over_size"), r.numbers.at("displacement_body_size"), 100 * displacement_warning);
  return buf;
}

std::string limit_slip_warning_line(const SceneRecord& r) {
  if (!r.numbers.count("slip_over_h") || r.numbers.at("slip_over_h") <= film_slip_warning) return "";
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "warning: the bondline slips %.3g elements along S (%s): the node-to-node pairing of the interface needs "
                "slips below one element (the layer mode's rule, SPEC 1.5)",
                r.numbers.at("slip_over_h"), r.text.count("slip_where") ? r.text.at("slip_where").c_str() : "-");
  return buf;
}

}  // namespace thinlayer
