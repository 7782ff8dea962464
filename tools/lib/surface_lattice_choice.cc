#include "surface_lattice_choice.h"

#include "progressive_rate.h"  // decode_and_measure

namespace qmc::tools {

Status choose_surface_lattice(const Mesh& mesh, const EncodeOptions& options, size_t samples, int* factor,
                              std::vector<LatticeTrial>* trials) {
  trials->clear();
  *factor = 1;
  const auto trial = [&](int f) -> Status {
    EncodeOptions asked = options;
    asked.surface_lattice = f;
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    if (Status s = encode(mesh, asked, &bytes, &stats); !s.ok()) return s;
    DecodedFile decoded;
    MeshDistance distance;
    if (Status s = decode_and_measure(mesh, bytes, samples, &decoded, &distance); !s.ok()) return s;
    trials->push_back({f, bytes.size(), distance.relative(distance.l2), stats.positions.lattice > 1});
    return Status::Ok();
  };
  if (Status s = trial(1); !s.ok()) return s;
  const LatticeTrial grid = trials->front();
  uint64_t smallest = grid.bytes;
  for (const int f : kLatticeTrialFactors) {
    if (Status s = trial(f); !s.ok()) return s;
    const LatticeTrial& t = trials->back();
    if (t.on_lattice && t.l2 <= grid.l2 && t.bytes < smallest) smallest = t.bytes, *factor = f;
  }
  return Status::Ok();
}

}  // namespace qmc::tools
