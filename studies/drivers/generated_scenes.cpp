#include "studies/drivers/generated_scenes.h"

#include <chrono>

#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "cases/scene/scene_file_scenes.h"
#include "core/io/reference_tables.h"

namespace thinlayer {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double setup_of(const SceneRecord& record) {
  const auto it = record.numbers.find("setup_time_s");
  return it == record.numbers.end() ? 0.0 : it->second;
}

}  // namespace

GeneratedOutcome solve_generated(const GeneratedScene& scene, const SolverOptions& options, const std::string& cases_dir) {
  GeneratedOutcome out;
  out.scene = scene;
  const auto start = std::chrono::steady_clock::now();
  switch (scene.kind) {
    case GeneratedScene::Kind::Dovetail: {
      dovetail::MeshOptions mesh;
      mesh.h_interface = scene.h_interface;
      mesh.layer_elements = scene.layer_elements;
      const DovetailLimitBulk bulk(mesh, scene.friction);
      out.eps = scene.eps;
      out.interface_nodes = dovetail::interface_segments(scene.h_interface).nodes();
      const std::string law_case = scene.law_case ? std::string(1, scene.law_case) : "";
      DovetailScene s = solve_dovetail_layer(bulk, scene.exponents, scene.eps, law_case, SolverKind::Fast, options);
      out.report = std::move(s.report);
      out.record = std::move(s.record);
      break;
    }
    case GeneratedScene::Kind::Bar: {
      bar::MeshOptions mesh;
      mesh.nx = scene.bar_nx;
      mesh.ny = scene.bar_nx;
      mesh.load_scale = scene.load_scale;
      const Table3Row row = load_table3_paper().at(scene.bar_row - 1);
      out.eps = scene.eps;
      out.interface_nodes = scene.bar_nx;
      BarLayerScene s = solve_bar_layer(mesh, row.lambda_bar, row.mu_bar, scene.eps,
                                        "table3-row-" + std::to_string(scene.bar_row), SolverKind::Fast, options,
                                        default_status_tolerance, scene.layer_elements);
      out.report = std::move(s.report);
      out.record = std::move(s.record);
      break;
    }
    case GeneratedScene::Kind::SceneFile: {
      const SceneFileBulk bulk(read_scene_spec(cases_dir + "/" + scene.scene_file));
      out.eps = scene.eps_fraction * bulk.thickest_layer();
      for (const SceneInterfaceNodes& S : bulk.interface_nodes()) out.interface_nodes += static_cast<int>(S.plus.size());
      SceneFileScene s = solve_scene_file_layer(bulk, out.eps, SolverKind::Fast, options);
      out.report = std::move(s.report);
      out.record = std::move(s.record);
      break;
    }
  }
  out.setup_s = setup_of(out.record);
  out.meshing_s = seconds_since(start) - out.report.wall_time_s - out.setup_s;
  return out;
}

}  // namespace thinlayer
