#pragma once
// A node-to-node interface (SPEC §1.4): pairs of matching nodes on its minus and plus sides,
// or nodes of one body facing a rigid foundation (the minus side is then the foundation).
//
// Each interface node carries
//   normal n  — unit normal pointing from the minus side into the plus side;
//   tangent t — n turned clockwise: t = (n_y, -n_x);
//   length    — tributary length: half of each adjacent segment (mm per unit thickness).
// Jumps (SPEC §1.2 signs): [u]_N = n·(u⁻ - u⁺)  (> 0 is interpenetration),
//                          [u]_T = t·(u⁺ - u⁻).
// For the bar on its foundation (plus side = bar, n = (0, 1)): [u]_N = -u₂, [u]_T = u₁.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/fem/model.h"
#include "core/interface/law.h"

namespace thinlayer {

struct InterfaceNode {
  int plus_body = 0, plus_node = 0;
  int minus_body = -1, minus_node = -1;  // -1: rigid foundation
  int plus_dof_x = 0, minus_dof_x = -1;   // global DOF of u₁ in the model (u₂ is the next one)
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();
  double length = 0;

  bool on_foundation() const { return minus_body < 0; }
  Eigen::Vector2d tangent() const { return {normal.y(), -normal.x()}; }
};

struct Interface {
  std::string name;
  InterfaceLaw law;
  std::vector<InterfaceNode> nodes;
};

// Interface between the plus body and a rigid foundation along a boundary polyline of that
// body. `edges` (oriented with the body on the left) give the normals and tributary lengths;
// only `nodes` carry interface terms (e.g. all nodes of AD but the pinned D). At a corner the
// normal is the normalised mean of the two segment normals.
Interface foundation_interface(const std::string& name, const InterfaceLaw& law, const Model& model,
                               int plus_body, const std::vector<int>& nodes,
                               const std::vector<std::array<int, 2>>& edges);

// Interface between two bodies whose meshes have matching node positions along it (within
// `tolerance`, mm). Normals and lengths come from the plus body's edges; each plus node is
// paired with the minus node at the same position, and a missing partner is an error.
Interface paired_interface(const std::string& name, const InterfaceLaw& law, const Model& model,
                           int plus_body, const std::vector<int>& plus_nodes,
                           const std::vector<std::array<int, 2>>& plus_edges, int minus_body,
                           const std::vector<int>& minus_nodes, double tolerance);

}  // namespace thinlayer
