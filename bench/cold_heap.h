// qmc bench: a decode "from a cold heap", as the first decode of a fresh
// process (a `qmc decode` run, a viewer opening its first file) meets it.
// A benchmark that decodes the same file again and again reuses the pages
// the previous decode touched; a fresh process takes a page fault for every
// page it writes first, and on a virtual machine each costs microseconds.
// glibc's malloc_trim(0) hands every free page of the heap back to the
// system, so the next decode faults in all the memory it touches, as in a
// new process, while codecs can still be compared in one interleaved run.
#pragma once

#include <malloc.h>

namespace qmc::bench {

inline void hand_heap_back() { malloc_trim(0); }

}  // namespace qmc::bench
