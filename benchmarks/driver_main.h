#pragma once
// The main() of the benchmark drivers (thinlayer_scaling, thinlayer_export_problem,
// thinlayer_scene_set, thinlayer_random_scenes): one rule for what they let out, and one setting
// for the drivers that time solves.
#include <cstdio>
#include <exception>

#include "core/linalg/factor_memory.h"
#include "studies/parallel/blas_threads.h"

namespace thinlayer {

// run(argc, argv), its exit status returned; an exception it lets out (a bad argument, a scene
// refused, a file it cannot write) is one line on stderr, "NAME: what", and exit status 2.
template <class Run>
int run_driver(const char* name, Run run, int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 2;
  }
}

// run_driver for a driver whose table is time per solve: the solves run as the timing study runs
// them, on one BLAS thread (the same sums, split alike, as every study: studies/parallel/blas_threads.h)
// with the factorisations' freed memory kept for the next one (core/linalg/factor_memory.h).
template <class Run>
int run_timing_driver(const char* name, Run run, int argc, char** argv) {
  use_one_blas_thread();
  keep_factor_memory();
  return run_driver(name, run, argc, argv);
}

}  // namespace thinlayer
