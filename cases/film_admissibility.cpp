#include "cases/film_admissibility.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>

#include "core/fem/element_q1.h"

namespace thinlayer {

namespace {

bool is_layer(const std::string& body) { return body == "layer" || body.rfind("layer-", 0) == 0; }

// The element size along S at each node of an interface (a chain in node order): the mean of the
// node's two segments, its one segment at either end.
Eigen::VectorXd element_sizes(const InterfaceFields& f) {
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

// The largest |principal strain| of a Q1 cell at its centre.
double principal_strain(const SceneRecord& r, int cell) {
  Coords4 xy;
  Eigen::Matrix<double, 8, 1> ue;
  for (int a = 0; a < 4; ++a) {
    const int node = r.cells(cell, a);
    xy.row(a) = r.nodes.row(node);
    ue.segment<2>(2 * a) = r.u.row(node).transpose();
  }
  double detJ = 0;
  const Eigen::Vector3d e = q1_strain_matrix(xy, 0.0, 0.0, detJ) * ue;  // ε11, ε22, γ12
  Eigen::Matrix2d tensor;
  tensor << e[0], 0.5 * e[2], 0.5 * e[2], e[1];
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(tensor, Eigen::EigenvaluesOnly).eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

FilmAdmissibility film_admissibility(const SceneRecord& r) {
  FilmAdmissibility film;
  for (const InterfaceFields& f : r.interfaces) {
    const Eigen::VectorXd h = element_sizes(f);
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
    for (Eigen::Index c = 0; c < r.cells.rows(); ++c)
      if (is_layer(r.body_names.at(r.cell_body.at(c))))
        film.strain_max = std::max(film.strain_max, principal_strain(r, static_cast<int>(c)));
  return film;
}

void record_film_admissibility(SceneRecord& record) {
  const FilmAdmissibility film = film_admissibility(record);
  record.numbers["film_slip_over_h"] = film.slip_over_h;
  record.numbers["film_strain_max"] = film.strain_max;
}

std::string film_line(const SceneRecord& record) {
  if (!record.numbers.count("film_slip_over_h")) return "";
  char buf[128];
  std::snprintf(buf, sizeof buf, "film: largest slip %.3g elements along S, largest strain %.3g",
                record.numbers.at("film_slip_over_h"), record.numbers.at("film_strain_max"));
  return buf;
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
  if (!record.numbers.count("film_slip_over_h")) return "";
  return film_warning(film_admissibility(record));
}

}  // namespace thinlayer
