// Running out of memory in exact arithmetic.
//
// Conventions (owned here):
// - GMP (and MPFR, which allocates through it) aborts the process when an allocation fails: its default
//   handler prints "GNU MP: Cannot allocate memory" and calls abort(), so no caller can report it. After
//   install_gmp_allocation_handlers(), a failed GMP allocation throws std::bad_alloc instead, like operator new.
// - GMP's manual leaves throwing from its allocation functions undefined in general (the number being computed
//   may be left half-built, and temporaries leak). On x86-64, where every function has unwind tables, the
//   exception does unwind through GMP; what it leaves behind must not be used. hsx's program therefore ends
//   the run on std::bad_alloc (exit 2, "out of memory", its partial outputs removed), and a long-lived host that
//   installs the handlers should treat std::bad_alloc from hsx the same way: drop everything of that call.
// - Unwinding after std::bad_alloc may itself allocate (a destructor that walks a large document with a stack of
//   its own, an error message being built). When memory is exhausted those allocations fail too, and an exception
//   thrown during unwinding ends the process in std::terminate. install_out_of_memory_reserve() maps address
//   space from the system (not from the allocator, whose freed blocks stay in its own pools where the unwinding
//   cannot always use them) that the first failed allocation (operator new or GMP) unmaps before throwing, so that
//   the unwinding which follows has room; later failures throw as usual.
#pragma once

#include <cstddef>

namespace hsx {

/// Makes every later GMP allocation failure throw std::bad_alloc (see above). Affects the whole process and is
/// idempotent; call it at the start of a program, before any number exists. The handlers allocate with
/// std::malloc/realloc/free, as GMP's defaults do.
void install_gmp_allocation_handlers();

/// Maps `bytes` of address space from the system (mmap; none when that fails or `bytes` is 0), unmapped by the first
/// allocation that fails after this call (through operator new or, once install_gmp_allocation_handlers() ran, GMP),
/// just before that allocation throws std::bad_alloc: the stack unwinding that follows can then allocate. Installs a
/// std::new_handler (replacing any other). Call it once,
/// at the start of a program that ends its run on std::bad_alloc; later calls replace the reserve.
void install_out_of_memory_reserve(std::size_t bytes);

}  // namespace hsx
