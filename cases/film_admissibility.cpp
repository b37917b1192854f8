#include "cases/film_admissibility.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>

#include "core/fem/element_q1.h"

namespace thinlayer {

namespace {

bool is_layer(const std::string& body) { return body == "layer" || body.rfind("layer-", 0) == 0; }

}  // namespace

Eigen::VectorXd element_sizes_along(const InterfaceFields& f) {
  const Eigen::Index m = f.x.rows();
  Eigen::VectorXd h = Eigen::VectorXd::Zero(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    double sum = 0;
    int segments = 0;
    for (Eigen::Index j : {k - 1, k + 1})
      if (j >= 0 && j < m) {
        sum += (f.x.row(j) - f.x.row(k)).norm();
        ++segments;
      }
    h[k] = segments ? sum / segments : 0.0;
  }
  return h;
}

double principal_strain(const SceneRecord& r, int cell) {
  Eigen::Vector3d e;  // ε11, ε22, γ12
  if (r.cells.cols() == 4 && r.cells(cell, 3) >= 0) {
    Coords4 xy;
    Eigen::Matrix<double, 8, 1> ue;
    for (int a = 0; a < 4; ++a) {
      const int node = r.cells(cell, a);
      xy.row(a) = r.nodes.row(node);
      ue.segment<2>(2 * a) = r.u.row(node).transpose();
    }
    double detJ = 0;
    e = q1_strain_matrix(xy, 0.0, 0.0, detJ) * ue;
  } else {  // a P1 triangle: its gradient is constant
    const int a = r.cells(cell, 0), b = r.cells(cell, 1), c = r.cells(cell, 2);
    Eigen::Matrix2d X, U;
    X << (r.nodes.row(b) - r.nodes.row(a)).transpose(), (r.nodes.row(c) - r.nodes.row(a)).transpose();
    U << (r.u.row(b) - r.u.row(a)).transpose(), (r.u.row(c) - r.u.row(a)).transpose();
    const Eigen::Matrix2d grad = U * X.inverse();  // ∂u_i/∂x_j
    e << grad(0, 0), grad(1, 1), grad(0, 1) + grad(1, 0);
  }
  Eigen::Matrix2d tensor;
  tensor << e[0], 0.5 * e[2], 0.5 * e[2], e[1];
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(tensor, Eigen::EigenvaluesOnly).eigenvalues().cwiseAbs().maxCoeff();
}

FilmAdmissibility film_admissibility(const SceneRecord& r, const LayerFaceRoles& roles) {
  FilmAdmissibility film;
  for (const InterfaceFields& f : r.interfaces) {
    if (roles.bonded_faces.count(f.name)) continue;  // a tied face does not slip
    film.has_contact_face = true;
    const Eigen::VectorXd h = element_sizes_along(f);
    for (Eigen::Index k = 0; k < f.jump_T.size(); ++k) {
      if (!(h[k] > 0)) continue;
      const double slip = std::abs(f.jump_T[k]) / h[k];
      if (slip > film.slip_over_h) {
        film.slip_over_h = slip;
        film.slip_where = f.name + " node " + std::to_string(k);
      }
    }
  }
  if (r.cells.cols() == 4)
    for (Eigen::Index c = 0; c < r.cells.rows(); ++c) {
      const std::string& body = r.body_names.at(r.cell_body.at(c));
      if (!is_layer(body)) continue;
      const double strain = principal_strain(r, static_cast<int>(c));
      if (roles.glued_layers.count(body)) {
        film.has_glue = true;
        film.glue_strain_max = std::max(film.glue_strain_max, strain);
      } else {
        film.has_film = true;
        film.strain_max = std::max(film.strain_max, strain);
      }
    }
  return film;
}

void record_film_admissibility(SceneRecord& record, const LayerFaceRoles& roles) {
  const FilmAdmissibility film = film_admissibility(record, roles);
  if (film.has_contact_face) {
    record.numbers["film_slip_over_h"] = film.slip_over_h;
    if (!film.slip_where.empty()) record.text["film_slip_where"] = film.slip_where;
  }
  if (film.has_film) record.numbers["film_strain_max"] = film.strain_max;
  if (film.has_glue) record.numbers["glue_strain_max"] = film.glue_strain_max;
}

std::string film_line(const SceneRecord& record) {
  const auto& n = record.numbers;
  std::string line;
  char buf[160];
  if (n.count("film_slip_over_h")) {
    std::snprintf(buf, sizeof buf, "film: largest slip %.3g elements along S (contact faces)", n.at("film_slip_over_h"));
    line = buf;
  }
  if (n.count("film_strain_max")) {
    std::snprintf(buf, sizeof buf, "%slargest strain %.3g", line.empty() ? "film: " : ", ", n.at("film_strain_max"));
    line += buf;
  }
  if (n.count("glue_strain_max")) {
    std::snprintf(buf, sizeof buf, "%sglue: linear elastic glue assumed; peak strain %.3g", line.empty() ? "" : "; ",
                  n.at("glue_strain_max"));
    line += buf;
  }
  return line;
}

std::string film_warning(const FilmAdmissibility& film) {
  if (film.admissible()) return "";
  // Only the assumption the answer breaks: a film strained 2 % that did not slide is not "slid".
  std::string what;
  char buf[200];
  if (film.slip_over_h > film_slip_warning) {
    std::snprintf(buf, sizeof buf, "it slid %.3g elements along S (%s; node-to-node pairing needs < %g)",
                  film.slip_over_h, film.slip_where.empty() ? "-" : film.slip_where.c_str(), film_slip_warning);
    what = buf;
  }
  if (film.strain_max > film_strain_warning) {
    std::snprintf(buf, sizeof buf, "its largest strain is %.3g (small strain: < %g)", film.strain_max,
                  film_strain_warning);
    what += (what.empty() ? "" : " and ") + std::string(buf);
  }
  return "warning: the layer's answer is outside the model's assumptions (SPEC 1.5): " + what;
}

std::string film_warning(const SceneRecord& record) {
  FilmAdmissibility film;  // the numbers recorded with the faces' roles
  const auto& n = record.numbers;
  if (n.count("film_slip_over_h")) film.slip_over_h = n.at("film_slip_over_h");
  if (n.count("film_strain_max")) film.strain_max = n.at("film_strain_max");
  if (const auto where = record.text.find("film_slip_where"); where != record.text.end()) film.slip_where = where->second;
  return film_warning(film);
}

}  // namespace thinlayer
