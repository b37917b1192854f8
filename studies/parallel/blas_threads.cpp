#include "studies/parallel/blas_threads.h"

#include <dlfcn.h>

#include <initializer_list>

namespace thinlayer {

void use_one_blas_thread() {
  // Looked up rather than called: which BLAS serves libblas.so.3 is the machine's choice
  // (Debian's alternatives), and only OpenBLAS has this function.
  for (const char* name : {"openblas_set_num_threads", "omp_set_num_threads"})
    if (void* f = ::dlsym(RTLD_DEFAULT, name)) reinterpret_cast<void (*)(int)>(f)(1);
}

}  // namespace thinlayer
