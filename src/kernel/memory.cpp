#include <hsx/kernel/memory.hpp>

#include <gmp.h>
#include <sys/mman.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace hsx {

namespace {

/// install_out_of_memory_reserve's mapping, until a failed allocation unmaps it. It is address space mapped from the
/// system, not memory from the allocator: a block the allocator frees stays with the allocator, where the unwinding
/// that follows could not always use it. jemalloc (the program's allocator) keeps a freed 16 MiB block in its arena
/// for allocations of 8 MiB and more, and every arena keeps what it frees to itself and needs new address space for
/// its own bookkeeping; with such a reserve, 400 lines under `ulimit -v 400000` ended in std::terminate on every
/// run, and the 3D bracket under `ulimit -v 70000` on 2 runs of 6. Unmapped, the space serves any allocation.
std::atomic<void*> reserve{nullptr};
std::atomic<std::size_t> reserve_bytes{0};

/// Unmaps the reserve (once, whichever thread comes first).
void release_reserve() {
  const std::size_t bytes = reserve_bytes.load();
  if (void* p = reserve.exchange(nullptr)) munmap(p, bytes);
}

/// Releases the reserve and throws std::bad_alloc.
[[noreturn]] void out_of_memory() {
  release_reserve();
  throw std::bad_alloc();
}

void* allocate(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) out_of_memory();
  return p;
}

void* reallocate(void* old, std::size_t /*old_size*/, std::size_t new_size) {
  void* p = std::realloc(old, new_size);
  if (!p) out_of_memory();  // `old` is still valid and still owned by its number
  return p;
}

void release(void* p, std::size_t /*size*/) { std::free(p); }

}  // namespace

void install_gmp_allocation_handlers() { mp_set_memory_functions(allocate, reallocate, release); }

void install_out_of_memory_reserve(std::size_t bytes) {
  release_reserve();
  if (bytes > 0) {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p != MAP_FAILED) {  // else no reserve: failures still throw std::bad_alloc
      reserve_bytes.store(bytes);
      reserve.store(p);
    }
  }
  std::set_new_handler(out_of_memory);
}

}  // namespace hsx
