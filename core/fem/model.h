#pragma once
// What the finite-element core needs to know about a scene: bodies, supports, loads.
// Loads are tractions in daN/mm² (force per unit length per unit thickness in plane strain) and
// nodal forces in daN per unit thickness.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/fem/material.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

struct Body {
  std::string name;
  Mesh mesh;
  Material material;
  // A floating body has no support of its own: only its interfaces hold it (the thin layer).
  // Its stiffness is singular, so the solvers condense it separately and never factor it.
  bool floating = false;
  // Q1 only: integrate the λ part of the stiffness at the element centre (selective reduced
  // integration), for a nearly incompressible body such as some of the thin layers.
  bool selective_integration = false;
};

// u_component = value on the listed nodes of one body. The name groups the reaction it
// produces ("reactions/<name>" in the output); a DOF fixed by several conditions belongs to
// the first.
struct DirichletCondition {
  std::string name;
  int body = 0;
  std::vector<int> nodes;
  int component = 0;  // 0: u1, 1: u2
  double value = 0;   // mm
};

struct EdgeTraction {
  std::string name;
  int body = 0;
  std::vector<std::array<int, 2>> edges;
  Eigen::Vector2d traction = Eigen::Vector2d::Zero();  // daN/mm²
};

// A force on one node, daN per unit thickness (a resultant given on a point of the body).
struct NodalForce {
  std::string name;
  int body = 0;
  int node = 0;
  Eigen::Vector2d force = Eigen::Vector2d::Zero();
};

struct Model {
  std::vector<Body> bodies;
  std::vector<DirichletCondition> dirichlet;
  std::vector<EdgeTraction> tractions;
  std::vector<NodalForce> nodal_forces;

  // First global DOF of each body: body b, node i, component c -> offset(b) + 2 i + c.
  int dof_offset(int body) const {
    int offset = 0;
    for (int b = 0; b < body; ++b) offset += 2 * bodies[b].mesh.num_nodes();
    return offset;
  }
  int num_dofs() const { return dof_offset(static_cast<int>(bodies.size())); }
};

}  // namespace thinlayer
