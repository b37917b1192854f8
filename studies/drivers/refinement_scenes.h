#pragma once
// The scenes of S2 under mesh refinement (SPEC §3 S2, item 3; `study convergence --refine`): the
// dovetail cases × the rate grid × the meshes h/r along S (r of --refine), each layer scene with both
// selections of the layer (SPEC §1.5), and each case's limit scene on each mesh. They are solved
// over the MPI ranks (studies/parallel/scene_batch.h), one at a time per rank, each in a worker
// process under a wall-time cap (studies/parallel/capped_child.h), and each is kept in the scene
// store the moment it is solved (studies/tools/scene_store.h), so a stopped run starts again where it
// stopped.
//
// Which stored scenes are reused (`--resolve`):
//   stale   (default) a scene stored by this binary's solver revision is reused, whatever its outcome
//           (a scene that ran past its cap is not run again); one stored by another revision, or not
//           stored, is solved;
//   failed  a scene stored with an answer (converged, or at its proven round-off floor) is reused,
//           whichever revision solved it (its SPEC residual is the true one, which no solver's choice
//           enters); every other is solved: after a faster solver lands, this re-runs only what did
//           not converge; after a larger --scene-cap, only what ran past the old one;
//   all     every scene is solved;
//   none    no scene is solved: the tables of the scenes stored so far (a copy of a store under way).
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/dovetail/dovetail_scenes.h"
#include "studies/parallel/process_group.h"
#include "studies/tools/scene_cache.h"
#include "studies/tools/scene_store.h"

namespace thinlayer {

// A scene store that holds a file thinlayer did not write there (SPEC §4: never replaced), found
// before anything is solved: every rank throws it, exit status 2.
struct StoreRefused : ErrorOnEveryRank {
  using ErrorOnEveryRank::ErrorOnEveryRank;
};

enum class ResolvePolicy { Stale, Failed, All, None };
ResolvePolicy parse_resolve_policy(const std::string& name);  // "stale" | "failed" | "all" | "none", else throws

struct RefinementSceneOptions {
  std::string cases = "abcdefghi";
  std::vector<double> eps;           // the rate grid, decreasing (L units)
  std::vector<int> refine = {1, 2, 4};
  double h = 0.025;                  // the studies' spacing along S (L units); mesh r has h / r
  double tolerance = 1e-10;          // SPEC §1.5
  // The wall-time cap of one scene, s. The finest mesh's layer scenes took 15–90 s on this 2-core
  // machine with the solver of 2026-11 (h = 0.00625, 365 S nodes): the cap stops only a scene that
  // has stalled, at ten times the slowest measured.
  double scene_cap_s = 900;
  ResolvePolicy resolve = ResolvePolicy::Stale;
  std::string store_folder;          // the scene store (DIR/scenes)
  bool verbose = true;
};

// One scene of the study.
struct RefinementScene {
  int level = 0;         // index into RefinementSceneOptions::refine
  DovetailSceneDef def;
  std::string name;      // its file in the store, e.g. "h0.0125-d-layer-eps1e-06-plus"
};

// How a scene ended, as the study reports it.
struct SceneOutcome {
  std::string state;     // "converged" | "round-off floor" | "not converged" | "capped" | "threw" | "crashed" | "not solved"
  std::string detail;    // the stop cause or the message of a run without an answer
  std::string solver;    // the solver identity that produced it ("" if not solved)
  std::string method;    // the fast solver's method ("floating-layer ladder", ...)
  std::string id;        // the scene's id under /scenes ("" without an answer)
  double seconds = 0;    // the run's wall time
  double cpu_seconds = 0;  // the run's CPU time (on a loaded machine, what the scene itself took)
  double residual = std::numeric_limits<double>::quiet_NaN(), floor = std::numeric_limits<double>::quiet_NaN();
  double film_slip_over_h = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  bool answered() const { return state == "converged" || state == "round-off floor"; }
};

class RefinementScenes {
 public:
  explicit RefinementScenes(const RefinementSceneOptions& options);

  const RefinementSceneOptions& options() const { return options_; }
  const std::vector<RefinementScene>& scenes() const { return scenes_; }
  // The spacing along S of mesh `level`, and its name ("h", "h/2", "h/4").
  double h(int level) const;
  std::string mesh_name(int level) const;
  dovetail::MeshOptions mesh_options(int level) const;
  DovetailLimitBulk& bulk(int level);  // built on first use

  // Solves the scenes the policy does not reuse, over the ranks; each is in the store once solved.
  // Returns the number solved in this run.
  int solve();

  // A scene as stored (nullopt: not solved, or its run ended without a scene: capped, crashed) and
  // how it ended (a scene that did not converge is returned too: `outcome` says whether it counts).
  std::optional<DovetailScene> load(const RefinementScene& scene, SceneOutcome& outcome) const;
  const RefinementScene& find(int level, char law_case, const std::string& mode, double eps, LayerSelection selection) const;

 private:
  bool needs_solving(const RefinementScene& scene) const;
  std::string solve_one(const RefinementScene& scene, int& done, int mine);

  RefinementSceneOptions options_;
  SceneStore store_;
  std::vector<RefinementScene> scenes_;
  std::vector<std::unique_ptr<DovetailLimitBulk>> bulks_;
};

// The hidden command that solves one scene in a worker process (studies/parallel/capped_child.h):
// `thinlayer --refinement-scene-worker`, its scene on standard input, the scene's bytes on standard
// output. Not for users: main() runs it before parsing any command line.
constexpr const char* scene_worker_command = "--refinement-scene-worker";
int serve_refinement_scene();

// The outcome of a stored scene (state, detail, solver, time; and from the scene its residual,
// floor, iterations, film slip, id).
SceneOutcome outcome_of(const StoredScene* stored, const DovetailScene* scene);

}  // namespace thinlayer
