#include "core/linalg/factor_memory.h"

#include <malloc.h>

#include <mutex>

namespace thinlayer {

void keep_factor_memory() {
  constexpr int largest_mmap_threshold = 32 * 1024 * 1024;  // glibc's DEFAULT_MMAP_THRESHOLD_MAX on 64-bit
  mallopt(M_MMAP_THRESHOLD, largest_mmap_threshold);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

namespace {
std::mutex heap_scopes_mutex;
int heap_scopes = 0;
constexpr int glibc_default_mmap_max = 65536;  // M_MMAP_MAX's default (malloc/malloc.c)
}  // namespace

FactorsFromTheHeap::FactorsFromTheHeap() {
  std::lock_guard<std::mutex> lock(heap_scopes_mutex);
  if (heap_scopes++ == 0) mallopt(M_MMAP_MAX, 0);
}

FactorsFromTheHeap::~FactorsFromTheHeap() {
  std::lock_guard<std::mutex> lock(heap_scopes_mutex);
  if (--heap_scopes == 0) {
    mallopt(M_MMAP_MAX, glibc_default_mmap_max);
    malloc_trim(0);
  }
}

}  // namespace thinlayer
