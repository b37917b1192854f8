#pragma once
// Dovetail scenes identified by a hash of their full definition and solved once per run, so
// that studies sharing a scene (S2's samples are S3's brackets) pay for it once. Nothing is
// kept on disk between runs. Limit-mode scenes share the bulk's one factorisation; layer-mode
// scenes, each with its own layer, are solved on several threads.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "cases/dovetail/dovetail_scenes.h"

namespace thinlayer {

struct DovetailSceneDef {
  std::string mode = "limit";     // "limit" | "layer"
  std::string law_case;           // Table 2 letter a..i
  double eps = 0;                 // layer mode only (L units)
  double tolerance = 1e-10;       // the SPEC residual the fast solver must reach
  // Layer mode, controls only: the layer's quadrature against the rule of cases/layer_quadrature.h,
  // and the face the selection spring holds (SolverOptions::layer_selection). A scene that
  // departs from the defaults says so in its id ("-selective", "-full", "-plus").
  LayerQuadrature quadrature = LayerQuadrature::ByExponents;
  LayerSelection selection = LayerSelection::MinusFace;
  // Every field that changes the result, with the mesh's options, as canonical text.
  std::string definition(const dovetail::MeshOptions& mesh) const;
  // For progress lines: "case d layer eps 1e-06 plus-face selection".
  std::string label() const;
};

// Solves one scene on `bulk` with the fast solver (its id says when it departs from the defaults:
// "-plus", "-tol<T>"). A limit scene uses the bulk's condensation, built on first use.
DovetailScene solve_dovetail_scene(DovetailLimitBulk& bulk, const DovetailSceneDef& def);

// FNV-1a, 64 bits: stable across runs and platforms (std::hash is not).
std::uint64_t definition_hash(const std::string& definition);

class DovetailSceneCache {
 public:
  DovetailSceneCache(DovetailLimitBulk& bulk, int threads, bool verbose, std::string progress_tag);

  // Solves the listed scenes that are not solved yet: the limit ones first, one after the other
  // (they share a factorisation), then the layer ones in parallel.
  void solve(const std::vector<DovetailSceneDef>& defs);
  const DovetailScene& get(const DovetailSceneDef& def);  // solves it first if needed

  int solves() const { return solves_; }   // scenes computed
  int reuses() const { return reuses_; }   // requests answered from memory
  double solve_time_s() const { return solve_time_s_; }  // summed over scenes (CPU-side, all threads)
  DovetailLimitBulk& bulk() { return bulk_; }
  void set_progress_tag(const std::string& tag) { tag_ = tag; }

  // Every scene solved, once each, under /scenes.
  void write(H5Writer& out) const;

 private:
  const DovetailScene* find(const DovetailSceneDef& def);

  DovetailLimitBulk& bulk_;
  int threads_;
  bool verbose_;
  std::string tag_;
  std::mutex mutex_;
  std::map<std::uint64_t, std::pair<std::string, std::unique_ptr<DovetailScene>>> scenes_;  // hash → (definition, scene)
  int solves_ = 0, reuses_ = 0;
  double solve_time_s_ = 0;
};

}  // namespace thinlayer
