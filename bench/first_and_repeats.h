// qmc bench: an action timed as a fresh process meets it (`qmc decode`, a
// viewer opening its first file), then REPEAT more times in the same
// process: the first run's milliseconds and minor page faults, and each
// repeat's milliseconds. Header-only and the standard library's alone, so
// that bench/decode_once.cc builds against the decoder library of any
// revision.
#pragma once

#include <sys/resource.h>

#include <vector>

namespace qmc::bench {

inline long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

struct FirstAndRepeats {
  double first_ms = 0;
  long first_faults = 0;
  std::vector<double> repeat_ms;
};

// run() performs the action once and returns its milliseconds.
template <class Run>
FirstAndRepeats first_and_repeats(int repeat, Run&& run) {
  FirstAndRepeats r;
  const long faults_before = minor_faults();
  r.first_ms = run();
  r.first_faults = minor_faults() - faults_before;
  for (int i = 0; i < repeat; ++i) r.repeat_ms.push_back(run());
  return r;
}

}  // namespace qmc::bench
