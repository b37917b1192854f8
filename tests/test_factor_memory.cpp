// Where the factorisations' memory comes from (core/linalg/factor_memory.h): inside a
// FactorsFromTheHeap scope a block larger than any mmap threshold comes from the heap, outside it
// from mmap again (glibc's own count of mmapped blocks, mallinfo2().hblks, tells which); scopes nest.
#include <gtest/gtest.h>

#include <malloc.h>

#include <cstdlib>
#include <cstring>

#include "core/linalg/factor_memory.h"

using namespace thinlayer;

namespace {

constexpr std::size_t large = 64u << 20;  // 64 MiB: above glibc's largest mmap threshold (32 MiB)

void* volatile kept;  // so that the compiler cannot drop the allocation

// Whether a large block allocated now is mmapped (it adds to glibc's count of mmapped blocks).
bool large_block_is_mmapped() {
  const std::size_t before = mallinfo2().hblks;
  kept = std::malloc(large);
  std::memset(kept, 1, 4096);
  const bool mapped = mallinfo2().hblks > before;
  std::free(kept);
  return mapped;
}

}  // namespace

TEST(FactorMemory, LargeBlocksComeFromTheHeapInsideTheScopeOnly) {
  EXPECT_TRUE(large_block_is_mmapped());
  {
    const FactorsFromTheHeap outer;
    EXPECT_FALSE(large_block_is_mmapped());
    {
      const FactorsFromTheHeap inner;
      EXPECT_FALSE(large_block_is_mmapped());
    }
    EXPECT_FALSE(large_block_is_mmapped());  // the outer scope still holds
  }
  EXPECT_TRUE(large_block_is_mmapped());
}
