#include "studies/parallel/scene_batch.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <numeric>
#include <sstream>
#include <thread>

#include "core/io/output_target.h"
#include "studies/parallel/process_group.h"
#include "studies/tools/stopwatch.h"

namespace thinlayer {

std::vector<int> assign_longest_first(const std::vector<double>& costs, int ranks) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  std::vector<double> load(std::max(1, ranks), 0.0);
  std::vector<int> owner(costs.size(), 0);
  for (std::size_t i : order) {
    const int r = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[i] = r;
    load[r] += costs[i];
  }
  return owner;
}

SceneBatch::SceneBatch(std::string tag, int threads, bool verbose)
    : tag_(std::move(tag)), threads_(std::max(1, threads)), verbose_(verbose) {}

void SceneBatch::run() {
  std::vector<Task> tasks;
  tasks.swap(tasks_);  // the next batch starts empty, whatever happens to this one
  std::vector<double> costs;
  for (const Task& t : tasks) costs.push_back(t.cost);
  const std::vector<int> owner = assign_longest_first(costs, spread_ranks());
  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < tasks.size(); ++i)
    if (owner[i] == spread_rank()) mine.push_back(i);
  // Several threads: the longest first, so that no long scene starts last.
  if (threads_ > 1) std::stable_sort(mine.begin(), mine.end(), [&](auto a, auto b) { return costs[a] > costs[b]; });

  std::vector<Outcome> outcomes(tasks.size());
  const bool spread = spread_ranks() > 1;
  solve_on_threads(tasks, mine, outcomes, spread);
  if (spread) gather(outcomes);
  throw_first_failure(tasks, outcomes, owner);
  if (spread)
    for (std::size_t i = 0; i < tasks.size(); ++i) tasks[i].store(outcomes[i].bytes);
  for (const Outcome& o : outcomes) seconds_.push_back(o.seconds);
  log_times(tasks, outcomes, owner);
}

void SceneBatch::solve_on_threads(const std::vector<Task>& tasks, const std::vector<std::size_t>& mine, std::vector<Outcome>& outcomes, bool as_bytes) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex print;
  int done = 0;
  auto worker = [&] {
    for (std::size_t k; !failed && (k = next++) < mine.size();) {
      const std::size_t i = mine[k];
      const Task& task = tasks[i];
      Outcome& o = outcomes[i];
      const auto start = Clock::now();
      try {
        if (as_bytes) o.bytes = task.solve_to_bytes();
        else task.solve_here();
        o.solved = true;
      } catch (const std::exception& e) {
        o.failure = e.what();
        failed = true;
      } catch (...) {
        o.failure = "an exception that is not a std::exception";
        failed = true;
      }
      o.seconds = seconds_since(start);
      if (verbose_) {
        std::lock_guard<std::mutex> lock(print);
        ++done;
        const std::string who = spread_ranks() > 1 ? "rank " + std::to_string(rank()) + ": " : "";
        std::fprintf(stderr, "[%s] %s%d/%zu  %s  %s in %.2f s\n", tag_.c_str(), who.c_str(), done, mine.size(),
                     task.label.c_str(), o.solved ? "solved" : "FAILED", o.seconds);
      }
    }
  };
  std::vector<std::thread> pool;
  const int n = std::min<int>(threads_, static_cast<int>(mine.size()));
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

// Each rank sends, for each scene it owned: its index, whether it was solved, its time, and its
// result's bytes or what it threw.
void SceneBatch::gather(std::vector<Outcome>& outcomes) const {
  ByteWriter w;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const Outcome& o = outcomes[i];
    if (!o.solved && o.failure.empty()) continue;  // not mine, or not reached
    put(w, static_cast<std::uint64_t>(i)), put(w, o.solved), put(w, o.seconds), put(w, o.solved ? o.bytes : o.failure);
  }
  for (const std::string& blob : all_gather(w.take())) {
    ByteReader r(blob);
    while (!r.done()) {
      std::uint64_t i = 0;
      Outcome o;
      get(r, i), get(r, o.solved), get(r, o.seconds), get(r, o.solved ? o.bytes : o.failure);
      outcomes.at(i) = std::move(o);
    }
  }
}

void SceneBatch::throw_first_failure(const std::vector<Task>& tasks, const std::vector<Outcome>& outcomes,
                                     const std::vector<int>& owner) const {
  std::size_t failures = 0, first = outcomes.size();
  for (std::size_t i = 0; i < outcomes.size(); ++i)
    if (!outcomes[i].failure.empty()) {
      ++failures;
      first = std::min(first, i);
    }
  if (failures == 0) return;
  const std::string where = spread_ranks() > 1 ? " on rank " + std::to_string(owner[first]) : "";
  const std::string more = failures > 1 ? " (and " + std::to_string(failures - 1) + " other scenes)" : "";
  throw SceneFailure("scene '" + tasks[first].label + "'" + where + " failed: " + outcomes[first].failure + more);
}

// THINLAYER_SCENE_TIMES=FILE appends one tab-separated line per scene (tag, batch number in
// this process, label, cost estimate, seconds, rank): the measurements behind the cost
// estimates and the scaling figures of docs/studies.md (scripts/project_scaling.py). Rank 0 writes it
// like every other output (SPEC §4, core/io/output_target.h): the old lines and the new ones to
// a temporary file, renamed onto the target; a FIFO or a device is refused (exit status 2).
void SceneBatch::log_times(const std::vector<Task>& tasks, const std::vector<Outcome>& outcomes,
                           const std::vector<int>& owner) const {
  const char* path = std::getenv("THINLAYER_SCENE_TIMES");
  if (!path || !is_root()) return;
  static int batches = 0;
  ++batches;
  std::ostringstream log;
  if (std::filesystem::exists(resolve_output_target(path))) {
    std::ifstream old(path, std::ios::binary);
    if (!old) throw OutputError("cannot read '" + std::string(path) + "' (THINLAYER_SCENE_TIMES) to append to it");
    log << std::string(std::istreambuf_iterator<char>(old), {});
  }
  for (std::size_t i = 0; i < tasks.size(); ++i)
    log << tag_ << "\t" << batches << "\t" << tasks[i].label << "\t" << tasks[i].cost << "\t" << outcomes[i].seconds << "\t" << owner[i] << "\n";
  write_text_atomically(path, log.str());
}

}  // namespace thinlayer
