// The shared test corpus: ../shared/corpus beside the repository, or
// $QMC_CORPUS_DIR. Real meshes made by others, used in place, never copied
// into the repository; tests that need them skip when it is absent.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace qmc::testing {

inline std::filesystem::path corpus_dir() {
  if (const char* env = std::getenv("QMC_CORPUS_DIR")) return env;
  return std::filesystem::path(QMC_SOURCE_DIR) / ".." / "shared" / "corpus";
}

}  // namespace qmc::testing
