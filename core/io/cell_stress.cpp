#include "core/io/cell_stress.h"

#include "core/fem/element_p1.h"
#include "core/fem/element_q1.h"

namespace thinlayer {

Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> cell_stresses(const Model& model,
                                                                        const Eigen::VectorXd& u_full) {
  int num_cells = 0;
  for (const Body& b : model.bodies) num_cells += b.mesh.num_cells();
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> stress(num_cells, 3);
  int node_offset = 0, cell = 0;
  for (const Body& b : model.bodies) {
    const Eigen::Matrix3d D = b.material.D();
    auto u_of = [&](int node, int a) { return u_full[2 * (node_offset + node) + a]; };
    for (const auto& q : b.mesh.quads) {
      Coords4 xy;
      Eigen::Matrix<double, 8, 1> ue;
      for (int a = 0; a < 4; ++a) {
        xy.row(a) = b.mesh.nodes.row(q[a]);
        ue.segment<2>(2 * a) << u_of(q[a], 0), u_of(q[a], 1);
      }
      double detJ = 0;
      stress.row(cell++) = (D * (q1_strain_matrix(xy, 0.0, 0.0, detJ) * ue)).transpose();
    }
    for (const auto& t : b.mesh.triangles) {
      Coords3 xy;
      Eigen::Matrix<double, 6, 1> ue;
      for (int a = 0; a < 3; ++a) {
        xy.row(a) = b.mesh.nodes.row(t[a]);
        ue.segment<2>(2 * a) << u_of(t[a], 0), u_of(t[a], 1);
      }
      double area = 0;
      stress.row(cell++) = (D * (p1_strain_matrix(xy, area) * ue)).transpose();
    }
    node_offset += b.mesh.num_nodes();
  }
  return stress;
}

}  // namespace thinlayer
