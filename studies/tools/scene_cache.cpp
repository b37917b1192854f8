#include "studies/tools/scene_cache.h"

#include "studies/parallel/scene_batch.h"
#include "studies/tools/stopwatch.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <set>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace thinlayer {

std::string DovetailSceneDef::definition(const dovetail::MeshOptions& mesh) const {
  const dovetail::Exponents e = dovetail::exponents_of(law_case.at(0));
  std::ostringstream s;
  s.precision(17);
  s << "dovetail|mode=" << mode << "|case=" << law_case << "|gamma=" << e.gamma << "|delta=" << e.delta
    << "|eps=" << (mode == "layer" ? eps : 0.0) << "|tolerance=" << tolerance << "|solver=fast"
    << "|quadrature=" << static_cast<int>(quadrature) << "|selection=" << static_cast<int>(selection)
    << "|h_interface=" << mesh.h_interface << "|h_far=" << mesh.h_far << "|layer_elements=" << mesh.layer_elements;
  return s.str();
}

std::uint64_t definition_hash(const std::string& definition) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : definition) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

DovetailSceneCache::DovetailSceneCache(DovetailLimitBulk& bulk, int threads, bool verbose, std::string progress_tag)
    : bulk_(bulk), threads_(std::max(1, threads)), verbose_(verbose), tag_(std::move(progress_tag)) {}

const DovetailScene* DovetailSceneCache::find(const DovetailSceneDef& def) {
  const std::string text = def.definition(bulk_.options());
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = scenes_.find(definition_hash(text));
  if (it == scenes_.end()) return nullptr;
  if (it->second.first != text) throw std::logic_error("scene cache: hash collision between '" + text + "' and '" +
                                                       it->second.first + "'");
  return it->second.second.get();
}

DovetailScene solve_dovetail_scene(DovetailLimitBulk& bulk, const DovetailSceneDef& def) {
  if (def.mode != "limit" && def.mode != "layer") throw std::invalid_argument("scene mode must be limit or layer");
  SolverOptions options;
  options.tolerance = def.tolerance;
  options.layer_selection = def.selection;
  const dovetail::Exponents e = dovetail::exponents_of(def.law_case.at(0));
  DovetailScene s = def.mode == "limit"
                        ? solve_dovetail_limit(bulk, e, def.law_case, SolverKind::Fast, options)
                        : solve_dovetail_layer(bulk, e, def.eps, def.law_case, SolverKind::Fast, options,
                                               default_status_tolerance, def.quadrature);
  if (def.mode == "layer" && def.selection == LayerSelection::PlusFace) s.record.id += "-plus";
  if (def.tolerance != SolverOptions{}.tolerance) {
    std::ostringstream id;
    id << s.record.id << "-tol" << def.tolerance;
    s.record.id = id.str();
  }
  return s;
}

std::string DovetailSceneDef::label() const {
  std::ostringstream s;
  s << "case " << law_case << " " << mode;
  if (mode == "layer") s << " eps " << eps;
  if (quadrature == LayerQuadrature::Selective) s << " selective";
  if (quadrature == LayerQuadrature::Full) s << " full";
  if (selection == LayerSelection::PlusFace) s << " plus-face selection";
  if (tolerance != SolverOptions{}.tolerance) s << " tol " << tolerance;
  return s.str();
}

namespace {

// What a scene costs, relative to a limit-mode one (measured: a layer scene of the dovetail takes
// about 100 times as long; docs/studies.md, "Studies over MPI ranks").
double scene_cost(const DovetailSceneDef& d) { return d.mode == "limit" ? 1.0 : 100.0; }

}  // namespace

void DovetailSceneCache::solve(const std::vector<DovetailSceneDef>& defs) {
  std::vector<DovetailSceneDef> todo;
  std::set<std::string> queued;
  for (const DovetailSceneDef& d : defs) {
    if (find(d) || !queued.insert(d.definition(bulk_.options())).second) {
      ++reuses_;
      continue;
    }
    todo.push_back(d);
  }
  // The limit scenes share the bulk's factorisation, built on first use: one after the other on
  // each rank. The layer scenes, each with its own layer, on threads. Both spread over the ranks.
  std::vector<DovetailScene> solved(todo.size());
  SceneBatch limit(tag_, 1, verbose_), layer(tag_, threads_, verbose_);
  std::vector<double> seconds;
  for (SceneBatch* batch : {&limit, &layer}) {
    for (size_t i = 0; i < todo.size(); ++i)
      if ((todo[i].mode == "limit") == (batch == &limit))
        batch->add(todo[i].label(), scene_cost(todo[i]), solved[i],
                   [this, d = todo[i]] { return solve_dovetail_scene(bulk_, d); });
    batch->run();
    for (size_t k = 0; k < batch->size(); ++k) solve_time_s_ += batch->seconds(k);
  }
  for (size_t i = 0; i < todo.size(); ++i) {
    const std::string text = todo[i].definition(bulk_.options());
    scenes_[definition_hash(text)] = {text, std::make_unique<DovetailScene>(std::move(solved[i]))};
    ++solves_;
  }
}

const DovetailScene& DovetailSceneCache::get(const DovetailSceneDef& def) {
  if (const DovetailScene* s = find(def)) {
    ++reuses_;
    return *s;
  }
  solve({def});
  return *find(def);
}

void DovetailSceneCache::write(H5Writer& out) const {
  for (const auto& [hash, entry] : scenes_) write_scene(out, entry.second->record);
}

}  // namespace thinlayer
