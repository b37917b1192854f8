#include "studies/drivers/refinement_scenes.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <stdexcept>

#include "core/io/bytes.h"
#include "core/io/scene_id_number.h"
#include "core/solvers/solver_revision.h"
#include "studies/drivers/convergence_study.h"
#include "studies/parallel/capped_child.h"
#include "studies/parallel/process_group.h"
#include "studies/parallel/result_bytes.h"
#include "studies/parallel/scene_batch.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

// What a scene costs, s, for the longest-first assignment over the ranks: measured on this machine
// with the solver of 2026-11 (a layer scene about 3 s at h = 0.025, 6–12 s at h/2, 15–90 s at h/4:
// about 3 r² s; a limit scene well under a second at every mesh).
double scene_cost(const RefinementScene& s, int r) { return s.def.mode == "limit" ? 0.5 : 3.0 * r * r; }

std::string store_name(double h, const DovetailSceneDef& d) {
  std::string name = "h" + scene_id_number(h) + "-" + d.law_case + "-" + d.mode;
  if (d.mode == "layer")
    name += "-eps" + scene_id_number(d.eps) + (d.selection == LayerSelection::PlusFace ? "-plus" : "-minus");
  return name;
}

std::optional<DovetailScene> decode(const StoredScene& stored) {
  if (stored.ending != "answered") return std::nullopt;
  DovetailScene scene;
  ByteReader r(stored.scene);
  get(r, scene);
  if (!r.done()) throw std::runtime_error("bytes left over");
  return scene;
}

bool counts_as_answer(const std::string& stop) {
  return stop == to_string(StopCause::Converged) || stop == to_string(StopCause::RoundOffFloor);
}

}  // namespace

int serve_refinement_scene() {
  return serve_capped([](const std::string& bytes) {
    ByteReader r(bytes);
    dovetail::MeshOptions mesh;
    DovetailSceneDef def;
    get(r, mesh.h_interface), get(r, mesh.h_far), get(r, mesh.layer_elements);
    get(r, def.mode), get(r, def.law_case), get(r, def.eps), get(r, def.tolerance), get(r, def.quadrature),
        get(r, def.selection);
    if (!r.done()) throw std::runtime_error("a scene worker's input with bytes left over");
    DovetailLimitBulk bulk(mesh);
    ByteWriter w;
    put(w, solve_dovetail_scene(bulk, def));
    return w.take();
  });
}

ResolvePolicy parse_resolve_policy(const std::string& name) {
  if (name == "stale") return ResolvePolicy::Stale;
  if (name == "failed") return ResolvePolicy::Failed;
  if (name == "all") return ResolvePolicy::All;
  if (name == "none") return ResolvePolicy::None;
  throw std::invalid_argument("--resolve: '" + name + "' is not one of stale, failed, all, none");
}

RefinementScenes::RefinementScenes(const RefinementSceneOptions& options)
    : options_(options), store_(options.store_folder), bulks_(options.refine.size()) {
  // Mesh by mesh, so that the coarser meshes are complete first; on each, the limit scene and both
  // selections of every layer scene, case by case.
  for (int level = 0; level < static_cast<int>(options_.refine.size()); ++level)
    for (char c : options_.cases) {
      auto add = [&](DovetailSceneDef def) { scenes_.push_back({level, def, store_name(h(level), def)}); };
      add(limit_scene(c, options_.tolerance));
      for (LayerSelection selection : {LayerSelection::MinusFace, LayerSelection::PlusFace})
        for (double eps : options_.eps) {
          DovetailSceneDef def = layer_scene(c, eps, options_.tolerance);
          def.selection = selection;
          add(def);
        }
    }
}

double RefinementScenes::h(int level) const { return options_.h / options_.refine.at(level); }

std::string RefinementScenes::mesh_name(int level) const {
  const int r = options_.refine.at(level);
  return r == 1 ? "h" : "h/" + std::to_string(r);
}

dovetail::MeshOptions RefinementScenes::mesh_options(int level) const {
  dovetail::MeshOptions mesh;
  mesh.h_interface = h(level);
  mesh.h_far = std::max(mesh.h_far, mesh.h_interface);
  return mesh;
}

DovetailLimitBulk& RefinementScenes::bulk(int level) {
  if (!bulks_.at(level)) bulks_[level] = std::make_unique<DovetailLimitBulk>(mesh_options(level));
  return *bulks_[level];
}

const RefinementScene& RefinementScenes::find(int level, char law_case, const std::string& mode, double eps,
                                              LayerSelection selection) const {
  for (const RefinementScene& s : scenes_)
    if (s.level == level && s.def.law_case[0] == law_case && s.def.mode == mode &&
        (mode == "limit" || (s.def.eps == eps && s.def.selection == selection)))
      return s;
  throw std::logic_error("refinement: no such scene");
}

bool RefinementScenes::needs_solving(const RefinementScene& s) const {
  std::string damaged;
  const std::optional<StoredScene> stored = store_.read(s.name, &damaged);  // refuses a file that is not the store's
  if (!damaged.empty() && options_.verbose) std::fprintf(stderr, "[refine] %s: solved again\n", damaged.c_str());
  if (options_.resolve == ResolvePolicy::None) return false;
  if (options_.resolve == ResolvePolicy::All || !stored || stored->definition != s.def.definition(mesh_options(s.level))) return true;
  try {
    decode(*stored);  // a scene this binary cannot read back (its layout changed) is solved again
  } catch (const std::exception&) {
    return true;
  }
  if (options_.resolve == ResolvePolicy::Failed) return stored->ending != "answered" || !counts_as_answer(stored->stop);
  return stored->solver != solver_identity(SolverKind::Fast);
}

std::string RefinementScenes::solve_one(const RefinementScene& s, int& done, int mine) {
  const dovetail::MeshOptions mesh = mesh_options(s.level);
  ByteWriter input;
  put(input, mesh.h_interface), put(input, mesh.h_far), put(input, mesh.layer_elements);
  put(input, s.def.mode), put(input, s.def.law_case), put(input, s.def.eps), put(input, s.def.tolerance);
  put(input, s.def.quadrature), put(input, s.def.selection);
  const CappedRun run = run_capped({this_program(), scene_worker_command}, input.take(), options_.scene_cap_s);
  if (run.ending == CappedRun::Ending::Interrupted)  // stopped from outside: nothing to keep, the run ends
    throw std::runtime_error(mesh_name(s.level) + " " + s.def.label() + ": " + run.message);
  StoredScene stored{s.def.definition(mesh), solver_identity(SolverKind::Fast), to_string(run.ending),
                     run.message, "", run.seconds, run.cpu_seconds, run.answer};
  std::optional<DovetailScene> scene = decode(stored);
  if (scene) stored.stop = to_string(scene->report.stop_cause);
  store_.write(s.name, stored);
  const SceneOutcome o = outcome_of(&stored, scene ? &*scene : nullptr);
  std::string line = mesh_name(s.level) + " " + s.def.label() + ": " + o.state;
  if (o.answered() || o.state == "not converged")
    line += " (residual " + sci(o.residual, 1) + ", " + std::to_string(o.iterations) + " steps" +
            (o.state == "not converged" ? ", " + o.detail : "") + ")";
  else
    line += " (" + o.detail + ")";
  char seconds[64];
  std::snprintf(seconds, sizeof seconds, " in %.1f s (%.1f s CPU)", o.seconds, o.cpu_seconds);
  line += seconds;
  ++done;
  if (options_.verbose) {
    const std::string who = spread_ranks() > 1 ? "rank " + std::to_string(rank()) + ": " : "";
    std::fprintf(stderr, "[refine] %s%d/%d %s\n", who.c_str(), done, mine, line.c_str());
    std::fflush(stderr);
  }
  return line;
}

int RefinementScenes::solve() {
  // Rank 0 reads the store and decides; every rank follows its list (they would read the same files,
  // but a rank that starts late could already see a scene another rank has solved).
  // A store file thinlayer did not write is refused before anything is solved, on every rank alike.
  std::string todo(scenes_.size(), '0');
  if (is_root()) try {
      std::error_code error;
      if (std::filesystem::exists(store_.folder(), error) && !std::filesystem::is_directory(store_.folder(), error))
        throw ForeignStoreFile(store_.folder() + ": exists and is not a folder (the scene store goes there)");
      for (std::size_t i = 0; i < scenes_.size(); ++i) todo[i] = needs_solving(scenes_[i]) ? '1' : '0';
    } catch (const ForeignStoreFile& e) {
      todo = std::string("!") + e.what();
    }
  todo = all_gather(is_root() ? todo : std::string()).front();
  if (!todo.empty() && todo[0] == '!') throw StoreRefused(todo.substr(1));
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < scenes_.size(); ++i)
    if (todo[i] == '1') chosen.push_back(i);
  if (options_.verbose && is_root())
    std::fprintf(stderr, "[refine] %zu scenes: %zu in the store %s and reused, %zu to solve (scene cap %g s)\n",
                 scenes_.size(), scenes_.size() - chosen.size(), store_.folder().c_str(), chosen.size(),
                 options_.scene_cap_s);
  std::vector<double> costs;
  for (std::size_t i : chosen) costs.push_back(scene_cost(scenes_[i], options_.refine[scenes_[i].level]));
  const std::vector<int> owner = assign_longest_first(costs, spread_ranks());
  int mine = 0, done = 0;
  for (int o : owner) mine += o == spread_rank();
  // One scene at a time on each rank (a child is forked per scene: no other thread may run then).
  SceneBatch batch("refine", 1, false);
  std::vector<std::string> lines(chosen.size());
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const RefinementScene& s = scenes_[chosen[k]];
    batch.add(mesh_name(s.level) + " " + s.def.label(), costs[k], lines[k],
              [this, i = chosen[k], &done, mine] { return solve_one(scenes_[i], done, mine); });
  }
  batch.run();
  return static_cast<int>(chosen.size());
}

std::optional<DovetailScene> RefinementScenes::load(const RefinementScene& s, SceneOutcome& outcome) const {
  std::optional<StoredScene> stored = store_.read(s.name);
  if (stored && stored->definition != s.def.definition(mesh_options(s.level))) stored.reset();  // another scene's
  std::optional<DovetailScene> scene = stored ? decode(*stored) : std::nullopt;
  outcome = outcome_of(stored ? &*stored : nullptr, scene ? &*scene : nullptr);
  return scene;
}

SceneOutcome outcome_of(const StoredScene* stored, const DovetailScene* scene) {
  SceneOutcome o;
  if (!stored) {
    o.state = "not solved";
    return o;
  }
  o.solver = stored->solver;
  o.seconds = stored->seconds;
  o.cpu_seconds = stored->cpu_seconds;
  if (!scene) {
    o.state = stored->ending;  // "capped", "threw" or "crashed"
    o.detail = stored->message;
    return o;
  }
  const SolveReport& r = scene->report;
  o.state = r.converged ? "converged" : r.stop_cause == StopCause::RoundOffFloor ? "round-off floor" : "not converged";
  o.detail = to_string(r.stop_cause);
  o.method = r.method;
  o.id = scene->record.id;
  o.residual = r.residual.value();
  o.floor = r.residual.floor();
  o.iterations = r.iterations;
  const auto slip = scene->record.numbers.find("film_slip_over_h");
  if (slip != scene->record.numbers.end()) o.film_slip_over_h = slip->second;
  return o;
}

}  // namespace thinlayer
