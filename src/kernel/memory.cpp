#include <hsx/kernel/memory.hpp>

#include <gmp.h>

#include <cstdlib>
#include <new>

namespace hsx {

namespace {

void* allocate(std::size_t size) {
  void* p = std::malloc(size);
  if (!p) throw std::bad_alloc();
  return p;
}

void* reallocate(void* old, std::size_t /*old_size*/, std::size_t new_size) {
  void* p = std::realloc(old, new_size);
  if (!p) throw std::bad_alloc();  // `old` is still valid and still owned by its number
  return p;
}

void release(void* p, std::size_t /*size*/) { std::free(p); }

}  // namespace

void install_gmp_allocation_handlers() { mp_set_memory_functions(allocate, reallocate, release); }

}  // namespace hsx
