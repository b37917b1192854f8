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
  for (Eigen::Index c = 0; c < r.cells.rows(); ++c) {
    const std::string& body = r.body_names.at(r.cell_body.at(c));
    if (is_layer(body)) continue;
    const double strain = principal_strain(r, static_cast<int>(c));
    if (strain > a.strain_max) a.strain_max = strain, a.strain_body = body;
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
  r.numbers["strain_max"] = a.strain_max;
  r.text["strain_body"] = a.strain_body;
  if (a.limit) {
    r.numbers["slip_over_h"] = a.slip_over_h;
    r.text["slip_where"] = a.slip_where;
  }
}

std::string displacement_warning_line(const SceneRecord& r) {
  if (!r.numbers.count("displacement_over_size") || r.numbers.at("displacement_over_size") <= displacement_warning) return "";
  const double moves = r.numbers.at("displacement_over_size");
  const double strain = r.numbers.count("strain_max") ? r.numbers.at("strain_max") : 0.0;
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "warning: body '%s' moves %.3g mm, %.3g times its size (%.3g mm): the model is linear and assumes small "
                "displacements (warned above %g %% of a body's size)",
                r.text.at("displacement_body").c_str(), r.numbers.at("displacement_max"), moves,
                r.numbers.at("displacement_body_size"), 100 * displacement_warning);
  std::string line = buf;
  if (moves >= mechanism_ratio * strain) {  // a soft motion, not a large load: near-singular for it
    std::snprintf(buf, sizeof buf,
                  "; it moves %.3g times more than it strains (largest strain %.3g): a motion held by little, a rigid "
                  "one or a bending — hold the joint as it is held (a support left free?)",
                  strain > 0 ? moves / strain : INFINITY, strain);
    line += buf;
  }
  return line;
}

std::string strain_warning_line(const SceneRecord& r) {
  const double adherent = r.numbers.count("strain_max") ? r.numbers.at("strain_max") : 0.0;
  const double glue = r.numbers.count("glue_strain_max") ? r.numbers.at("glue_strain_max") : 0.0;
  if (adherent <= small_strain_warning && glue <= small_strain_warning) return "";
  std::string where;
  char buf[200];
  if (glue > small_strain_warning) {
    std::snprintf(buf, sizeof buf, "the glue strains %.3g", glue);
    where = buf;
  }
  if (adherent > small_strain_warning) {
    std::snprintf(buf, sizeof buf, "%sbody '%s' strains %.3g", where.empty() ? "" : " and ",
                  r.text.count("strain_body") ? r.text.at("strain_body").c_str() : "-", adherent);
    where += buf;
  }
  std::snprintf(buf, sizeof buf, " at its peak (largest principal strain): the load is beyond small strain (warned above %g); "
                "the model is linear, its answer that of a linear model at this load, not the joint's",
                small_strain_warning);
  return "warning: " + where + buf;
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
