#pragma once
// A batch of independent scenes, solved once each over the MPI ranks and, within a rank, over
// threads (SPEC §6). A study lists its scenes, each with a cost estimate and a place for its
// result, calls run(), and then finds every result in place, on every rank, exactly as if it
// had solved them itself one after the other.
//
//   SceneBatch batch("table3", threads, verbose);
//   std::vector<BarScene> scenes(n);        // sized first: add() keeps references
//   for (size_t i = 0; i < n; ++i)
//     batch.add(label(i), cost(i), scenes[i], [=] { return solve(i); });
//   batch.run();
//
// How the work is shared: every rank knows the whole list (all ranks run the same study code),
// so no rank has to hand out work. Each scene goes to a rank by a longest-first greedy
// assignment of the cost estimates (assign_longest_first); a rank solves its share on its
// threads (longest first when there are several), and then every rank receives every result
// (one all-gather of their bytes, studies/parallel/result_bytes.h). Results go to every rank, not just
// rank 0, because what a study does next may depend on them (S3's bisection picks its next
// thicknesses from the distances it measured).
//
// A scene that throws stops its rank's remaining scenes of the batch; after the gather every
// rank throws the same SceneFailure naming the scene and the rank, so no rank waits for
// another that will never come.
//
// Threads: a batch made with threads > 1 may only hold scenes that are safe to solve
// concurrently (no shared lazily built factorisation, no gmsh).
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/parallel/process_group.h"
#include "studies/parallel/result_bytes.h"

namespace thinlayer {

// A scene of a batch failed (on some rank): thrown on every rank alike.
struct SceneFailure : ErrorOnEveryRank {
  using ErrorOnEveryRank::ErrorOnEveryRank;
};

// The rank of each task: tasks by decreasing cost, each to the rank with the least cost so far
// (ties: the lower rank, then the earlier task), so every rank computes the same answer. Within
// 4/3 of the best possible largest load.
std::vector<int> assign_longest_first(const std::vector<double>& costs, int ranks);

class SceneBatch {
 public:
  // tag: the progress lines' prefix. threads: scenes solved at once on each rank.
  explicit SceneBatch(std::string tag, int threads = 1, bool verbose = false);

  // `result` must stay where it is until run() returns; `solve` returns a value of its type,
  // one that has put/get overloads (studies/parallel/result_bytes.h) for the trip between ranks.
  template <class Result, class Solve>
  void add(std::string label, double cost, Result& result, Solve solve) {
    Task t{std::move(label), cost, {}, {}, {}};
    t.solve_here = [solve, &result] { result = solve(); };
    t.solve_to_bytes = [solve] {
      const Result value = solve();
      ByteWriter w;
      put(w, value);
      return w.take();
    };
    t.store = [&result](const std::string& bytes) {
      ByteReader r(bytes);
      get(r, result);
      if (!r.done()) throw std::logic_error("result bytes: unread bytes left (a put/get mismatch)");
    };
    tasks_.push_back(std::move(t));
  }

  // Solves every scene added since the last run(), once, somewhere; every result in place on
  // every rank. Throws SceneFailure (on every rank) if a scene threw.
  void run();

  std::size_t size() const { return seconds_.size(); }
  // The wall time of scene i (in the order added, over all runs) on the rank that solved it.
  double seconds(std::size_t i) const { return seconds_.at(i); }

 private:
  struct Task {
    std::string label;
    double cost;
    std::function<void()> solve_here;                 // one process: straight into the result
    std::function<std::string()> solve_to_bytes;      // several: the result as bytes
    std::function<void(const std::string&)> store;    // the bytes into the result
  };
  struct Outcome {
    bool solved = false;   // false: not reached (its rank had failed already) or it threw
    std::string failure;   // what it threw
    double seconds = 0;
    std::string bytes;     // K > 1: the result
  };

  void solve_on_threads(const std::vector<Task>& tasks, const std::vector<std::size_t>& mine,
                        std::vector<Outcome>& outcomes, bool as_bytes);
  void gather(std::vector<Outcome>& outcomes) const;
  void throw_first_failure(const std::vector<Task>& tasks, const std::vector<Outcome>& outcomes,
                           const std::vector<int>& owner) const;
  void log_times(const std::vector<Task>& tasks, const std::vector<Outcome>& outcomes,
                 const std::vector<int>& owner) const;

  std::string tag_;
  int threads_;
  bool verbose_;
  std::vector<Task> tasks_;
  std::vector<double> seconds_;
};

}  // namespace thinlayer
