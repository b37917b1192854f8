#pragma once
// The sparse factorisations (UMFPACK, CHOLMOD) allocate their factors afresh at every call. By
// default glibc hands every block above 128 KiB straight back to the kernel when it is freed, so
// the next factorisation page-faults its whole factor in again: on the friction-held double lap
// (cases/friction_lap, 474 nodes on S, limit mode, five factorisations) 51 000 page faults, 22 000
// with freed memory kept for reuse (`perf stat -e page-faults`). Keeping it costs nothing a run
// did not already need at its peak.
namespace thinlayer {

// Once, at the start of a process that factors repeatedly (the CLI's ProcessGroup does it; the
// benchmark drivers too): blocks up to 32 MiB (glibc's largest mmap threshold) come from the heap,
// and the heap's top is not trimmed back to the kernel.
void keep_factor_memory();

// For the life of this object, blocks of any size come from the heap (glibc's M_MMAP_MAX = 0): a
// loop that factors the same pattern again and again (the sparse Newton, core/solvers/sparse_newton.h)
// then reuses its factor's pages. UMFPACK's numeric object on the friction lap at 810 and 1 394 nodes
// on S is larger than the 32 MiB keep_factor_memory can keep: each of its five factorisations was
// mapped afresh and zero-filled by the kernel on first touch (340 000 minor page faults in the
// benchmark's run), and 1.50 s → 0.86 s, 3.56 s → 2.18 s once they come from the heap (peak memory
// +25 %: a freed factor stays in the heap until the next one takes it). Nested and concurrent
// scopes count: mmap comes back when the last one ends, and the heap's free top is then trimmed.
class FactorsFromTheHeap {
 public:
  FactorsFromTheHeap();
  ~FactorsFromTheHeap();
  FactorsFromTheHeap(const FactorsFromTheHeap&) = delete;
  FactorsFromTheHeap& operator=(const FactorsFromTheHeap&) = delete;
};

}  // namespace thinlayer
