#include "core/linalg/factor_memory.h"

#include <malloc.h>

namespace thinlayer {

void keep_factor_memory() {
  constexpr int largest_mmap_threshold = 32 * 1024 * 1024;  // glibc's DEFAULT_MMAP_THRESHOLD_MAX on 64-bit
  mallopt(M_MMAP_THRESHOLD, largest_mmap_threshold);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace thinlayer
