#include <hsx/kernel/memory.hpp>

#include <gmp.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace hsx {

namespace {

std::atomic<void*> reserve{nullptr};  // install_out_of_memory_reserve's block, until a failed allocation frees it

/// Frees the reserve (once, whichever thread comes first) and throws std::bad_alloc.
[[noreturn]] void out_of_memory() {
  std::free(reserve.exchange(nullptr));
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
  std::free(reserve.exchange(std::malloc(bytes)));
  std::set_new_handler(out_of_memory);
}

}  // namespace hsx
