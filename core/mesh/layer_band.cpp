#include "core/mesh/layer_band.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace thinlayer {

namespace {

using Point = Eigen::Vector2d;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

// Smallest admissible sine of a corner angle of a band cell. Anything below is treated as
// degenerate: such a cell is useless for finite elements whatever its size.
constexpr double kMinCornerSine = 1e-10;

// Whether the corner of a cell between the sides e1 (to the next corner) and e2 (to the
// previous one) is positively oriented, relatively: cross(e1, e2) must exceed
// kMinCornerSine·|e1||e2| plus the error that round-off in coordinates of magnitude `scale`
// can put into it (each side is a difference of two coordinates, off by ~ulp(scale)).
bool corner_positive(const Point& e1, const Point& e2, double scale) {
  const double n1 = e1.norm(), n2 = e2.norm();
  const double roundoff = 8 * std::numeric_limits<double>::epsilon() * scale * (n1 + n2);
  return cross(e1, e2) > kMinCornerSine * n1 * n2 + roundoff;
}

// Throws unless every corner of the counter-clockwise quad (a, b, c, d) is positive.
void check_cell(const std::array<Point, 4>& corners, int segment, int layer) {
  double scale = 0;
  for (const auto& p : corners) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  for (int k = 0; k < 4; ++k) {
    const Point& here = corners[k];
    const Point e1 = corners[(k + 1) % 4] - here;
    const Point e2 = corners[(k + 3) % 4] - here;
    if (!corner_positive(e1, e2, scale))
      throw std::invalid_argument(
          "layer_band: inverted or degenerate cell between face nodes " + std::to_string(segment) +
          " and " + std::to_string(segment + 1) + " (layer " + std::to_string(layer) +
          " from the minus face): the faces cross or fold back there, or a face segment or the "
          "thickness is zero or below the round-off of the coordinates");
  }
}

void validate(const Eigen::Ref<const FacePolyline>& minus_face,
              const Eigen::Ref<const FacePolyline>& plus_face, int elements_across) {
  if (minus_face.rows() != plus_face.rows())
    throw std::invalid_argument("layer_band: the faces have different node counts (" +
                                std::to_string(minus_face.rows()) + " and " +
                                std::to_string(plus_face.rows()) + ")");
  if (minus_face.rows() < 2)
    throw std::invalid_argument("layer_band: each face needs at least 2 nodes (got " +
                                std::to_string(minus_face.rows()) + ")");
  if (elements_across < 2)
    throw std::invalid_argument("layer_band: elements_across must be >= 2 (got " +
                                std::to_string(elements_across) + ")");
  if ((static_cast<double>(minus_face.rows())) * (elements_across + 1.0) >
      std::numeric_limits<int>::max())
    throw std::invalid_argument("layer_band: too many nodes");
  if (!minus_face.allFinite() || !plus_face.allFinite())
    throw std::invalid_argument("layer_band: non-finite face coordinates");
}

// +1 if the band lies on the left of the minus face (walking in node order), -1 if on its
// right: the sign of the band's total signed area, each face quad's area taken from its
// diagonals (differences of nearby points, accurate for thin bands).
int band_side(const Eigen::Ref<const FacePolyline>& minus_face,
              const Eigen::Ref<const FacePolyline>& plus_face) {
  double twice_area = 0;
  for (Eigen::Index i = 0; i + 1 < minus_face.rows(); ++i) {
    const Point d1 = plus_face.row(i + 1).transpose() - minus_face.row(i).transpose();
    const Point d2 = plus_face.row(i).transpose() - minus_face.row(i + 1).transpose();
    twice_area += cross(d1, d2);
  }
  if (!(twice_area != 0))
    throw std::invalid_argument("layer_band: the band has zero total area");
  return twice_area > 0 ? +1 : -1;
}

template <std::size_t N>
double polygon_side(const Mesh& mesh, const std::array<int, N>& cell, std::size_t k) {
  return (mesh.nodes.row(cell[(k + 1) % N]) - mesh.nodes.row(cell[k])).norm();
}

struct QualityAccumulator {
  double min_angle = std::numeric_limits<double>::infinity();
  double max_angle = -std::numeric_limits<double>::infinity();
  double max_aspect = 0;
  double min_jacobian = std::numeric_limits<double>::infinity();

  template <std::size_t N>
  void add(const Mesh& mesh, const std::array<int, N>& cell, double jacobian_scale) {
    double longest = 0, shortest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < N; ++k) {
      const Point here = mesh.nodes.row(cell[k]).transpose();
      const Point e1 = mesh.nodes.row(cell[(k + 1) % N]).transpose() - here;
      const Point e2 = mesh.nodes.row(cell[(k + N - 1) % N]).transpose() - here;
      const double n1 = e1.norm(), n2 = e2.norm();
      // atan2 keeps full relative accuracy for very flat corners.
      double angle = std::atan2(cross(e1, e2), e1.dot(e2));
      if (angle < 0) angle += 2 * std::numbers::pi;  // reflex corner
      const double jacobian = n1 > 0 && n2 > 0 ? jacobian_scale * cross(e1, e2) / (n1 * n2) : 0.0;
      min_angle = std::min(min_angle, angle);
      max_angle = std::max(max_angle, angle);
      min_jacobian = std::min(min_jacobian, jacobian);
      const double side = polygon_side(mesh, cell, k);
      longest = std::max(longest, side);
      shortest = std::min(shortest, side);
    }
    max_aspect = std::max(max_aspect, shortest > 0 ? longest / shortest
                                                   : std::numeric_limits<double>::infinity());
  }
};

}  // namespace

Mesh layer_band(const Eigen::Ref<const FacePolyline>& minus_face,
                const Eigen::Ref<const FacePolyline>& plus_face, int elements_across) {
  validate(minus_face, plus_face, elements_across);
  const int n = static_cast<int>(minus_face.rows());
  const int m = elements_across;
  const int side = band_side(minus_face, plus_face);
  auto id = [m](int i, int j) { return i * (m + 1) + j; };

  Mesh mesh;
  mesh.element = ElementType::Q1;
  mesh.nodes.resize(static_cast<Eigen::Index>(n) * (m + 1), 2);
  for (int i = 0; i < n; ++i) {
    const Point minus = minus_face.row(i).transpose();
    const Point plus = plus_face.row(i).transpose();
    const Point across = plus - minus;
    mesh.nodes.row(id(i, 0)) = minus.transpose();
    for (int j = 1; j < m; ++j)
      mesh.nodes.row(id(i, j)) = (minus + (static_cast<double>(j) / m) * across).transpose();
    mesh.nodes.row(id(i, m)) = plus.transpose();
  }

  mesh.quads.reserve(static_cast<std::size_t>(n - 1) * m);
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j < m; ++j) {
      // Counter-clockwise: along the minus face then across, or across then along.
      const std::array<int, 4> cell =
          side > 0 ? std::array<int, 4>{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}
                   : std::array<int, 4>{id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)};
      std::array<Point, 4> corners;
      for (int k = 0; k < 4; ++k) corners[k] = mesh.nodes.row(cell[k]).transpose();
      check_cell(corners, i, j);
      mesh.quads.push_back(cell);
    }
  }

  std::vector<int> minus_nodes, plus_nodes, first_end, last_end;
  std::vector<std::array<int, 2>> minus_edges, plus_edges;
  for (int i = 0; i < n; ++i) {
    minus_nodes.push_back(id(i, 0));
    plus_nodes.push_back(id(i, m));
  }
  for (int i = 0; i + 1 < n; ++i) {
    // The band is on the left of i -> i+1 along the face it lies left of, and on the right
    // of it along the other face.
    if (side > 0) {
      minus_edges.push_back({id(i, 0), id(i + 1, 0)});
      plus_edges.push_back({id(i + 1, m), id(i, m)});
    } else {
      minus_edges.push_back({id(i + 1, 0), id(i, 0)});
      plus_edges.push_back({id(i, m), id(i + 1, m)});
    }
  }
  for (int j = 0; j <= m; ++j) {
    first_end.push_back(id(0, j));
    last_end.push_back(id(n - 1, j));
  }
  mesh.node_sets["S-"] = std::move(minus_nodes);
  mesh.node_sets["S+"] = std::move(plus_nodes);
  mesh.node_sets["end_first"] = std::move(first_end);
  mesh.node_sets["end_last"] = std::move(last_end);
  mesh.edge_sets["S-"] = std::move(minus_edges);
  mesh.edge_sets["S+"] = std::move(plus_edges);
  return mesh;
}

MeshQuality mesh_quality(const Mesh& mesh) {
  if (mesh.num_cells() == 0) throw std::invalid_argument("mesh_quality: the mesh has no cells");
  QualityAccumulator acc;
  if (mesh.element == ElementType::Q1) {
    for (const auto& q : mesh.quads) acc.add(mesh, q, 1.0);
  } else {
    const double equilateral = 2.0 / std::sqrt(3.0);
    for (const auto& t : mesh.triangles) acc.add(mesh, t, equilateral);
  }
  constexpr double deg = 180.0 / std::numbers::pi;
  return {acc.min_angle * deg, acc.max_angle * deg, acc.max_aspect, acc.min_jacobian,
          mesh.num_cells()};
}

}  // namespace thinlayer
