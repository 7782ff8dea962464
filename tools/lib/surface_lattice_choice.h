// `qmc encode --surface-lattice auto` (spec 14.15, informative): the lattice
// factor F whose file is smallest among those no farther from the input's
// surface (L2, as qmc compare measures it) than the grid's file. Every
// candidate is coded, decoded and measured: the lattice pays on dense scans
// and not on regular, mirrored or coarse meshes, and which F is best differs
// from mesh to mesh (docs/results/surface_lattice.md).
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/encoder.h"
#include "qmc/status.h"

namespace qmc::tools {

// The factors tried, in this order.
inline constexpr int kLatticeTrialFactors[] = {2, 3, 4, 6};

struct LatticeTrial {
  int factor = 1;      // 1: the grid
  uint64_t bytes = 0;  // the whole file
  double l2 = 0;       // relative to the input's bounding-box diagonal
  bool on_lattice = false;  // false: the encoder kept the grid's POSN (smaller)
};

// Encodes mesh with `options` on the grid (surface_lattice 1) and with each
// factor of kLatticeTrialFactors, measures each decoded file with `samples`
// area samples, and sets *factor to the one of the smallest file whose L2 is
// at most the grid's (1 if none is), *bytes and *stats to that file's
// (what encode gives with that factor). trials gets the grid's first.
Status choose_surface_lattice(const Mesh& mesh, const EncodeOptions& options, size_t samples, int* factor,
                              std::vector<uint8_t>* bytes, EncodeStats* stats, std::vector<LatticeTrial>* trials);

}  // namespace qmc::tools
