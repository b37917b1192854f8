// The mesh size estimate that bounds a scene before gmsh meshes it (cases/scene/mesh_estimate.h):
// within a factor 2 of the mesh gmsh then makes, for both element types and both ways of
// giving the sizes.
#include <gtest/gtest.h>

#include <gmsh.h>

#include <filesystem>
#include <fstream>

#include "cases/scene/mesh_estimate.h"
#include "cases/scene/scene_mesh.h"
#include "core/mesh/gmsh_session.h"

namespace {

using namespace thinlayer;

SceneSpec lap_joint(ElementType element, bool mesh_size, double h_interface = 0.5, double h_far = 2.0) {
  SceneSpec s = read_scene_spec(std::string(THINLAYER_CASES_DIR) + "/lap_joint/lap_joint.json");
  s.element = element;
  if (mesh_size) s.h_interface = h_interface, s.h_far = h_far;
  else s.h_interface.reset(), s.h_far.reset();
  return s;
}

double estimate(const SceneSpec& s) {
  GmshModelScope scope("estimate");
  gmsh::open(s.geometry);
  return estimated_mesh_nodes(s);
}

int actual(const SceneSpec& s) {
  int nodes = 0;
  for (const Mesh& m : load_scene_meshes(s).bodies) nodes += m.num_nodes();
  return nodes;
}

TEST(MeshEstimate, WithinAFactorTwoOfTheMeshGmshMakes) {
  for (ElementType element : {ElementType::Q1, ElementType::P1})
    for (bool mesh_size : {true, false})
      for (double h : {0.5, 0.1}) {
        const SceneSpec s = lap_joint(element, mesh_size, h, 4 * h);
        const double e = estimate(s);
        const int n = actual(s);
        SCOPED_TRACE(std::string(to_string(element)) + (mesh_size ? " mesh_size h " + std::to_string(h) : " own sizes"));
        std::printf("%s %s h %.2f: estimate %.0f, actual %d (ratio %.2f)\n", to_string(element),
                    mesh_size ? "mesh_size" : "own sizes", h, e, n, e / n);
        EXPECT_GT(e, n / 2.0);
        EXPECT_LT(e, 2.0 * n);
        if (!mesh_size) break;  // the .geo's own sizes do not depend on h
      }
}

}  // namespace
