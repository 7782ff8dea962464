// A hint to the processor that memory will be read soon. It changes no
// result: compilers without the builtin (and WebAssembly, which has no
// prefetch) get nothing.
#pragma once

namespace qmc {

inline void prefetch_for_read(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address, 0, 3);
#else
  (void)address;
#endif
}

}  // namespace qmc
