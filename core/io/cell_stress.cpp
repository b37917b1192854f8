#include "core/io/cell_stress.h"

#include <array>

#include "core/fem/element_p1.h"
#include "core/fem/element_q1.h"

namespace thinlayer {

namespace {

// A cell's N corners and their displacements (u_x, u_y per corner), read from the whole model's u.
template <int N>
struct CellValues {
  Eigen::Matrix<double, N, 2> xy;
  Eigen::Matrix<double, 2 * N, 1> u;
};

template <int N>
CellValues<N> cell_values(const Mesh& mesh, const std::array<int, N>& corners, const Eigen::VectorXd& u_full,
                          int node_offset) {
  CellValues<N> c;
  for (int a = 0; a < N; ++a) {
    c.xy.row(a) = mesh.nodes.row(corners[a]);
    c.u.template segment<2>(2 * a) = u_full.segment<2>(2 * (node_offset + corners[a]));
  }
  return c;
}

}  // namespace

Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> cell_stresses(const Model& model,
                                                                        const Eigen::VectorXd& u_full) {
  int num_cells = 0;
  for (const Body& b : model.bodies) num_cells += b.mesh.num_cells();
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> stress(num_cells, 3);
  int node_offset = 0, cell = 0;
  for (const Body& b : model.bodies) {
    const Eigen::Matrix3d D = b.material.D();
    for (const auto& q : b.mesh.quads) {
      const CellValues<4> c = cell_values<4>(b.mesh, q, u_full, node_offset);
      double detJ = 0;  // the strain at the cell's centre
      stress.row(cell++) = (D * (q1_strain_matrix(c.xy, 0.0, 0.0, detJ) * c.u)).transpose();
    }
    for (const auto& t : b.mesh.triangles) {
      const CellValues<3> c = cell_values<3>(b.mesh, t, u_full, node_offset);
      double area = 0;
      stress.row(cell++) = (D * (p1_strain_matrix(c.xy, area) * c.u)).transpose();
    }
    node_offset += b.mesh.num_nodes();
  }
  return stress;
}

}  // namespace thinlayer
