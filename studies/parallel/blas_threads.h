#pragma once
// The same bits on any machine and under any launcher: the BLAS (OpenBLAS) and OpenMP
// libraries that CHOLMOD and LAPACK call split their sums over as many threads as the process
// may use, and a different split rounds differently (1e-16 relative, enough to change a
// results file). mpirun binds each rank to one core, so a rank would use 1 thread where a
// one-process run uses all the cores. We fix their count at 1 everywhere: the studies'
// parallelism is over scenes (--threads, and MPI ranks), not inside one linear solve.
namespace thinlayer {

// Once, before any solve (ProcessGroup does it). A library that is not loaded is left alone.
void use_one_blas_thread();

}  // namespace thinlayer
