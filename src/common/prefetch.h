// A hint to the processor that memory will be read soon; it changes no
// result. Where there is no such instruction (WebAssembly, compilers
// without the builtin) prefetch_for_read does nothing and kPrefetches is
// false, so that callers keep their plain order there.
#pragma once

namespace qmc {

#if (defined(__GNUC__) || defined(__clang__)) && !defined(__wasm__)
inline constexpr bool kPrefetches = true;
inline void prefetch_for_read(const void* address) { __builtin_prefetch(address, 0, 3); }
#else
inline constexpr bool kPrefetches = false;
inline void prefetch_for_read(const void*) {}
#endif

}  // namespace qmc
