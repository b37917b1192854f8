// The thin-layer solver's scene set (issue 13): every scene a layer solver must pass, solved
// from rest with the default setup, one line per scene — steps, residual (the largest, and
// the floating layer's own), time, why it stopped, combined counts.
//
//   build/thinlayer_scene_set                      # the whole set (about 120 scenes)
//   build/thinlayer_scene_set --only dovetail-layer-e --csv e.csv
// Each dovetail layer scene also prints its time as a multiple of one linear solve of the same
// three-body mesh with the layer bonded (benchmarks/bonded_solve.h; issue 13: goal <= 10x).
//
// The set: the dovetail's 9 limit scenes and 45 layer scenes of `study dovetail`
// (ε = 1e-2 … 1e-4), its nine cases at ε = 1e-6 and 1e-8, the bar's six Table 3 rows in layer
// mode at ε = 1e-2 … 1e-8, and the layer scenes of `study stress` (stiffness contrast; the free
// layer, which must say "singular"). Timing is setup (factorisations, condensation) plus solve;
// meshing excluded. Times are of a shared machine: compare within one run. One BLAS thread, as
// in every study (studies/parallel/blas_threads.h): the same bits, so the same solver paths.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <functional>
#include <string>
#include <vector>

#include "benchmarks/bonded_solve.h"
#include "cases/dovetail/dovetail.h"
#include "core/io/output_target.h"
#include "core/io/reference_tables.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "benchmarks/driver_main.h"

namespace thinlayer {
namespace {

struct Row {
  std::string id, expected;
  int steps = 0;
  double residual = 0, layer_residual = 0, floor = 0, solve_s = 0, setup_s = 0;
  double bonded_s = 0;  // one linear solve of the same mesh with the layer bonded (dovetail layer scenes)
  std::string stop_cause, counts;
};

std::string counts_text(const StatusCount& c) {
  return std::to_string(c.gap) + "/" + std::to_string(c.slide) + "/" + std::to_string(c.stick);
}

Row row_of(const std::string& id, const SceneRecord& record, const SolveReport& report, const StatusCount& counts) {
  Row row;
  row.id = id;
  row.steps = report.iterations;
  row.residual = report.residual.value();
  row.floor = report.residual.floor();
  for (size_t b = 0; b < record.body_names.size(); ++b)
    if (record.body_names[b] == "layer") row.layer_residual = record.residual_per_body[b];
  row.solve_s = report.wall_time_s;
  row.setup_s = record.numbers.count("setup_time_s") ? record.numbers.at("setup_time_s") : 0.0;
  row.stop_cause = to_string(report.stop_cause);
  row.counts = counts_text(counts);
  return row;
}

struct Scene {
  std::string id, expected;  // expected: the stop cause the scene must end with
  std::function<Row()> run;
};

std::string plain(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

// The median of three bonded solves of the dovetail's three-body mesh at ε (meshing and assembly
// excluded, as in the scene's setup and solve times).
double bonded_dovetail_seconds(const DovetailLimitBulk& bulk, double eps) {
  const dovetail::LayerMeshes meshes = dovetail::make_layer_meshes(bulk.meshes(), eps, bulk.options().layer_elements);
  const Model model = dovetail::make_layer_model(meshes, dovetail::exponents_of('d'));
  std::vector<double> t;
  const LinearSystem system(model);  // assembly is not timed: the scene's setup time excludes it too
  const ContactProblem problem(system, dovetail::make_layer_interfaces(model, bulk.friction()));
  for (int run = 0; run < 3; ++run) t.push_back(bonded_solve_seconds(problem));
  std::sort(t.begin(), t.end());
  return t[1];
}

std::vector<Scene> scene_set() {
  std::vector<Scene> scenes;
  static DovetailLimitBulk dovetail_bulk;  // shared by every dovetail scene, as in the study
  const std::string cases = "abcdefghi";
  for (char c : cases) {
    const std::string id = std::string("dovetail-limit-") + c;
    scenes.push_back({id, "converged", [=] {
                        DovetailScene s = solve_dovetail_limit(dovetail_bulk, dovetail::exponents_of(c),
                                                               std::string(1, c), SolverKind::Fast, {});
                        return row_of(id, s.record, s.report, s.limit);
                      }});
  }
  for (double eps : {1e-2, 5e-3, 1e-3, 5e-4, 1e-4, 1e-6, 1e-8})
    for (char c : cases) {
      const std::string id = std::string("dovetail-layer-") + c + "-eps" + plain(eps);
      scenes.push_back({id, "converged", [=] {
                          DovetailScene s = solve_dovetail_layer(dovetail_bulk, dovetail::exponents_of(c), eps,
                                                                 std::string(1, c), SolverKind::Fast, {});
                          Row row = row_of(id, s.record, s.report, s.counts.combined);
                          row.bonded_s = bonded_dovetail_seconds(dovetail_bulk, eps);
                          return row;
                        }});
    }
  const std::vector<Table3Row> rows = load_table3_paper();
  for (double eps : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8})
    for (const Table3Row& row : rows) {
      const std::string id = "bar-layer-row" + std::to_string(row.row) + "-eps" + plain(eps);
      scenes.push_back({id, "converged", [=] {
                          BarLayerScene s = solve_bar_layer({}, row.lambda_bar, row.mu_bar, eps,
                                                            "table3-row-" + std::to_string(row.row), SolverKind::Fast, {});
                          return row_of(id, s.record, s.report, s.counts.combined);
                        }});
    }
  // study stress: the stiffness contrast (λ_ε = c λ_m, μ_ε = c μ_m at ε = 1e-3) and the free layer.
  for (double c : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const std::string id = "stress-contrast-bar-layer-c" + plain(c);
    scenes.push_back({id, "converged", [=] {
                        const double eps = 1e-3;
                        BarLayerScene s = solve_bar_layer({}, c * bar::lambda_m / eps, c * bar::mu_m / eps, eps,
                                                          "contrast", SolverKind::Fast, {});
                        return row_of(id, s.record, s.report, s.counts.combined);
                      }});
  }
  scenes.push_back({"stress-bar-layer-floating", "singular system", [] {
                      bar::MeshOptions lifted;
                      lifted.load_scale = -1;
                      const Table3Row row1 = load_table3_paper().at(0);
                      BarLayerScene s = solve_bar_layer(lifted, row1.lambda_bar, row1.mu_bar, 1e-3, "table3-row-1",
                                                        SolverKind::Fast, {});
                      return row_of("stress-bar-layer-floating", s.record, s.report, s.counts.combined);
                    }});
  return scenes;
}

int run(int argc, char** argv) {
  std::string only, csv;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--only" && i + 1 < argc) only = argv[++i];
    else if (a == "--csv" && i + 1 < argc) csv = argv[++i];
    else {
      std::fprintf(stderr, "usage: thinlayer_scene_set [--only SUBSTRING] [--csv FILE]\n");
      return 2;
    }
  }
  std::ostringstream out;  // the CSV, written atomically at the end (core/io/output_target.h)
  if (!csv.empty()) {
    out << "scene,steps,residual,layer_residual,roundoff_floor,solve_s,setup_s,stop_cause,combined_gap_slide_stick,expected,"
           "bonded_s\n";
  }
  std::printf("%-34s %6s %10s %10s %10s %8s %8s  %-16s %s\n", "scene", "steps", "residual", "layer", "floor", "solve_s",
              "setup_s", "stop", "gap/slide/stick");
  int failures = 0, total = 0;
  for (const Scene& scene : scene_set()) {
    if (!only.empty() && scene.id.find(only) == std::string::npos) continue;
    ++total;
    Row row;
    try {
      row = scene.run();
    } catch (const std::exception& e) {
      row.id = scene.id;
      row.stop_cause = std::string("threw: ") + e.what();
    }
    const bool ok = row.stop_cause == scene.expected;
    failures += ok ? 0 : 1;
    const std::string flag = ok ? "" : "   <-- expected " + scene.expected;
    const std::string ratio =
        row.bonded_s > 0 ? "  x" + plain(std::round(10 * (row.solve_s + row.setup_s) / row.bonded_s) / 10) + " bonded" : "";
    std::printf("%-34s %6d %10.2e %10.2e %10.2e %8.3f %8.3f  %-16s %s%s%s\n", scene.id.c_str(), row.steps, row.residual,
                row.layer_residual, row.floor, row.solve_s, row.setup_s, row.stop_cause.c_str(), row.counts.c_str(),
                ratio.c_str(), flag.c_str());
    std::fflush(stdout);
    if (!csv.empty()) out << scene.id << "," << row.steps << "," << row.residual << "," << row.layer_residual << ","
                 << row.floor << "," << row.solve_s << "," << row.setup_s << "," << row.stop_cause << "," << row.counts << ","
                 << scene.expected << "," << row.bonded_s << "\n";
  }
  std::printf("%d of %d scenes ended as expected\n", total - failures, total);
  if (!csv.empty()) write_text_atomically(csv, out.str());
  return failures ? 1 : 0;
}

}  // namespace
}  // namespace thinlayer

int main(int argc, char** argv) { return thinlayer::run_timing_driver("thinlayer_scene_set", thinlayer::run, argc, argv); }
