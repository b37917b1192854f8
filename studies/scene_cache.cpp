#include "studies/scene_cache.h"

#include "studies/stopwatch.h"

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

DovetailScene DovetailSceneCache::compute(const DovetailSceneDef& def) {
  if (def.mode != "limit" && def.mode != "layer") throw std::invalid_argument("scene mode must be limit or layer");
  SolverOptions options;
  options.tolerance = def.tolerance;
  const dovetail::Exponents e = dovetail::exponents_of(def.law_case.at(0));
  DovetailScene s = def.mode == "limit"
                        ? solve_dovetail_limit(bulk_, e, def.law_case, SolverKind::Fast, options)
                        : solve_dovetail_layer(bulk_, e, def.eps, def.law_case, SolverKind::Fast, options);
  if (def.tolerance != SolverOptions{}.tolerance) {
    std::ostringstream id;
    id << s.record.id << "-tol" << def.tolerance;
    s.record.id = id.str();
  }
  return s;
}

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
  std::stable_partition(todo.begin(), todo.end(), [](const DovetailSceneDef& d) { return d.mode == "limit"; });
  std::atomic<int> next{0}, done{0};
  std::exception_ptr failure;
  auto store = [&](const DovetailSceneDef& d, DovetailScene scene, double seconds) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string text = d.definition(bulk_.options());
    const bool converged = scene.report.converged;
    scenes_[definition_hash(text)] = {text, std::make_unique<DovetailScene>(std::move(scene))};
    ++solves_;
    solve_time_s_ += seconds;
    const int k = ++done;
    if (verbose_)
      std::fprintf(stderr, "[%s] %d/%zu  case %s %s%s  %s in %.2f s\n", tag_.c_str(), k, todo.size(), d.law_case.c_str(),
                   d.mode.c_str(), d.mode == "layer" ? (" eps " + std::to_string(d.eps)).c_str() : "",
                   converged ? "converged" : "NOT converged", seconds);
  };
  auto run = [&](const DovetailSceneDef& d) {
    const auto start = Clock::now();
    DovetailScene scene = compute(d);
    store(d, std::move(scene), seconds_since(start));
  };
  size_t first_layer = 0;
  for (; first_layer < todo.size() && todo[first_layer].mode == "limit"; ++first_layer) run(todo[first_layer]);
  next = static_cast<int>(first_layer);
  auto worker = [&] {
    for (int i; (i = next++) < static_cast<int>(todo.size());) {
      try {
        run(todo[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const int n = std::min<int>(threads_, static_cast<int>(todo.size() - first_layer));
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
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
