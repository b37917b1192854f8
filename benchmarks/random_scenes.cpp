// S5's seeded scene generator through the layer solver (issue 25): one line per seed — what was
// drawn, steps, residual, the round-off floor, time, why it stopped — then the distribution of
// steps and times, the slowest ten, and the stop causes.
//
//   build/thinlayer_random_scenes --seeds 1-200 --csv seeds.csv
//   build/thinlayer_random_scenes --seeds 1-20 --h-min 0.0125      # the CTest sample's meshes
//   build/thinlayer_random_scenes --seeds 1-200 --list             # what each seed draws, no solve
// Each line's scene is printed before its solve starts, so a run stopped by a time limit still
// says which scene it was on.
// Exit status 0 only if every seed converged. Times are of a shared machine: compare within one
// run. One BLAS thread, as in every study.
#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/output_target.h"
#include "studies/drivers/generated_scenes.h"
#include "studies/parallel/blas_threads.h"

namespace thinlayer {
namespace {

struct Row {
  std::string description, stop_cause;
  int steps = 0;
  double residual = 0, floor = 0, solve_s = 0, setup_s = 0;
  bool converged = false;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * (v.size() - 1) + 0.5)];
}

int usage() {
  std::fprintf(stderr, "usage: thinlayer_random_scenes --seeds FIRST-LAST [--h-min H] [--csv FILE] [--list]\n");
  return 2;
}

int run(int argc, char** argv) {
  int first = 1, last = 20;
  GeneratorRanges ranges;
  std::string csv;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seeds" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%d-%d", &first, &last) != 2 || first > last) return usage();
    } else if (a == "--h-min" && i + 1 < argc) {
      ranges.h_min = std::stod(argv[++i]);
      if (!(ranges.h_min > 0 && ranges.h_min <= ranges.h_max)) return usage();
    } else if (a == "--list") {
      list = true;
    } else if (a == "--csv" && i + 1 < argc) {
      csv = argv[++i];
    } else {
      return usage();
    }
  }
  if (list) {
    for (int seed = first; seed <= last; ++seed) std::printf("%s\n", generate_scene(seed, ranges).describe().c_str());
    return 0;
  }
  std::vector<Row> rows;
  std::printf("%-72s %6s %10s %10s %8s %8s  %s\n", "scene", "steps", "residual", "floor", "solve_s", "setup_s", "stop");
  for (int seed = first; seed <= last; ++seed) {
    const GeneratedScene scene = generate_scene(seed, ranges);
    Row row;
    row.description = scene.describe();
    std::printf("%-72s", row.description.c_str());
    std::fflush(stdout);
    try {
      const GeneratedOutcome o = solve_generated(scene, {}, THINLAYER_CASES_DIR);
      row.steps = o.report.iterations;
      row.residual = o.report.residual.value();
      row.floor = o.report.residual.floor();
      row.solve_s = o.report.wall_time_s;
      row.setup_s = o.setup_s;
      row.converged = o.report.converged;
      row.stop_cause = to_string(o.report.stop_cause);
    } catch (const std::exception& e) {
      row.stop_cause = std::string("threw: ") + e.what();
    }
    std::printf(" %6d %10.2e %10.2e %8.3f %8.3f  %s\n", row.steps, row.residual, row.floor,
                row.solve_s, row.setup_s, row.stop_cause.c_str());
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::vector<double> steps, times;
  int converged = 0;
  for (const Row& r : rows) {
    converged += r.converged;
    steps.push_back(r.steps);
    times.push_back(r.solve_s + r.setup_s);
  }
  std::printf("\n%d of %zu seeds converged\n", converged, rows.size());
  std::printf("steps: median %.0f, 90 %% %.0f, max %.0f; setup+solve: median %.3f s, 90 %% %.3f s, max %.3f s\n",
              quantile(steps, 0.5), quantile(steps, 0.9), quantile(steps, 1.0), quantile(times, 0.5),
              quantile(times, 0.9), quantile(times, 1.0));
  std::vector<size_t> order(rows.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return times[a] > times[b]; });
  std::printf("slowest ten:\n");
  for (size_t i = 0; i < std::min<size_t>(10, order.size()); ++i)
    std::printf("  %8.3f s  %s (%s)\n", times[order[i]], rows[order[i]].description.c_str(),
                rows[order[i]].stop_cause.c_str());
  if (!csv.empty()) {
    std::ostringstream out;
    out << "seed_description,converged,steps,residual,roundoff_floor,solve_s,setup_s,stop_cause\n";
    for (const Row& r : rows)
      out << '"' << r.description << "\"," << r.converged << "," << r.steps << "," << r.residual << "," << r.floor << ","
          << r.solve_s << "," << r.setup_s << ",\"" << r.stop_cause << "\"\n";
    write_text_atomically(csv, out.str());
  }
  return converged == static_cast<int>(rows.size()) ? 0 : 1;
}

}  // namespace
}  // namespace thinlayer

int main(int argc, char** argv) {
  thinlayer::use_one_blas_thread();
  return thinlayer::run(argc, argv);
}
