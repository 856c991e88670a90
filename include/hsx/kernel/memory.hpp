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
#pragma once

namespace hsx {

/// Makes every later GMP allocation failure throw std::bad_alloc (see above). Affects the whole process and is
/// idempotent; call it at the start of a program, before any number exists. The handlers allocate with
/// std::malloc/realloc/free, as GMP's defaults do.
void install_gmp_allocation_handlers();

}  // namespace hsx
