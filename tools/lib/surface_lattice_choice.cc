#include "surface_lattice_choice.h"

#include "progressive_rate.h"  // decode_and_measure

namespace qmc::tools {

Status choose_surface_lattice(const Mesh& mesh, const EncodeOptions& options, size_t samples, int* factor,
                              std::vector<uint8_t>* bytes, EncodeStats* stats, std::vector<LatticeTrial>* trials) {
  trials->clear();
  *factor = 1;
  // Tries factor f; keeps its file in *bytes and *stats if `keep` says so
  // of its trial.
  const auto trial = [&](int f, auto keep) -> Status {
    EncodeOptions asked = options;
    asked.surface_lattice = f;
    std::vector<uint8_t> file;
    EncodeStats file_stats;
    if (Status s = encode(mesh, asked, &file, &file_stats); !s.ok()) return s;
    DecodedFile decoded;
    MeshDistance distance;
    if (Status s = decode_and_measure(mesh, file, samples, &decoded, &distance); !s.ok()) return s;
    trials->push_back({f, file.size(), distance.relative(distance.l2), file_stats.positions.lattice > 1});
    if (keep(trials->back())) {
      *factor = f;
      *bytes = std::move(file);
      *stats = std::move(file_stats);
    }
    return Status::Ok();
  };
  if (Status s = trial(1, [](const LatticeTrial&) { return true; }); !s.ok()) return s;
  const LatticeTrial grid = trials->front();
  for (const int f : kLatticeTrialFactors) {
    const auto smaller_within_grid = [&](const LatticeTrial& t) {
      return t.on_lattice && t.l2 <= grid.l2 && t.bytes < bytes->size();
    };
    if (Status s = trial(f, smaller_within_grid); !s.ok()) return s;
  }
  return Status::Ok();
}

}  // namespace qmc::tools
