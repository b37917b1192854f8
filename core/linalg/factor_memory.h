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

}  // namespace thinlayer
