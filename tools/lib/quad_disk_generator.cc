#include "quad_disk_generator.h"

#include <algorithm>

#include "decoder/spirale_reversi_decoder.h"
#include "splitmix64.h"

namespace qmc::tools {
namespace {

// The choices draw `next() % n`: the published conformance vectors made
// from these disks depend on exactly this sequence.
uint32_t draw(SplitMix64& rng, uint32_t n) { return uint32_t(rng.next() % n); }

// Loop lengths after each decoding operation (spec 5.3.6), tracked so that
// only operations valid in the current state are chosen.
struct DecoderShape {
  bool current = false;
  uint64_t length = 0;
  std::vector<uint64_t> stack;

  void apply(int type) {
    switch (type) {
      case 1: if (current) stack.push_back(length); current = true; length = 4; break;
      case 2: case 4: case 6: length += 2; break;
      case 5: case 12: break;
      case 13: length -= 2; break;
      case 3: case 7: case 9: length += stack.back(); stack.pop_back(); break;
      case 10: case 11: length += stack.back() - 2; stack.pop_back(); break;
      case 8: length += stack[stack.size() - 1] + stack[stack.size() - 2] - 2; stack.resize(stack.size() - 2); break;
    }
  }
};

// Weights roughly as in real meshes: mostly Q13, Q12, Q6; splits now and then.
bool claimed(int type) { return type == 5 || type == 10 || type == 12 || type == 13; }

// `previous` is the type generated just before: it follows the new one in
// the encoder's order.
int pick(SplitMix64& rng, const DecoderShape& shape, uint32_t remaining, int previous, bool respect_claim) {
  if (!shape.current) return 1;
  const bool avoid_claimed = respect_claim && previous >= 1 && previous <= 5;
  const size_t depth = shape.stack.size();
  if (remaining == depth) {  // every remaining step must rejoin one loop
    static const int kJoins[] = {3, 7, 9, 10, 11};
    static const int kUnclaimedJoins[] = {3, 7, 9, 11};
    return avoid_claimed ? kUnclaimedJoins[draw(rng, 4)] : kJoins[draw(rng, 5)];
  }
  struct Option { int type; uint32_t weight; };
  std::vector<Option> options = {{2, 3}, {4, 3}, {5, 4}, {6, 8}, {12, 10}};
  if (shape.length >= 6) options.push_back({13, 12});
  if (remaining >= depth + 2) options.push_back({1, 3});
  if (depth >= 1) for (int t : {3, 7, 9, 10, 11}) options.push_back({t, 2});
  if (depth >= 2) options.push_back({8, 2});
  if (avoid_claimed)
    options.erase(std::remove_if(options.begin(), options.end(), [](const Option& o) { return claimed(o.type); }),
                  options.end());
  uint32_t total = 0;
  for (const Option& o : options) total += o.weight;
  uint32_t r = draw(rng, total);
  for (const Option& o : options) {
    if (r < o.weight) return o.type;
    r -= o.weight;
  }
  return options.back().type;
}

// One attempt; the decoder may reject it (a Q13 closing an edge that exists).
std::vector<uint8_t> attempt(SplitMix64& rng, uint32_t operations, bool respect_claim) {
  DecoderShape shape;
  std::vector<uint8_t> decoding_order;
  for (uint32_t done = 0; done < operations; ++done) {
    const int previous = decoding_order.empty() ? 0 : decoding_order.back();
    const int type = pick(rng, shape, operations - done, previous, respect_claim);
    shape.apply(type);
    decoding_order.push_back(uint8_t(type));
  }
  std::reverse(decoding_order.begin(), decoding_order.end());
  return decoding_order;
}

}  // namespace

std::vector<uint8_t> random_quad_sequence(uint64_t seed, uint32_t operations, bool respect_claim) {
  SplitMix64 rng(seed);
  for (;;) {
    std::vector<uint8_t> types = attempt(rng, operations, respect_claim);
    Mesh mesh;
    if (spirale_reversi_decode(types, false, UINT32_MAX, &mesh).ok()) return types;
  }
}

Mesh make_random_quad_disk(uint64_t seed, uint32_t operations) {
  Mesh mesh;
  const std::vector<uint8_t> types = random_quad_sequence(seed, std::max<uint32_t>(operations, 1));
  if (!spirale_reversi_decode(types, false, UINT32_MAX, &mesh).ok()) return {};
  uint32_t vertices = 0;
  for (uint32_t v : mesh.corners) vertices = std::max(vertices, v + 1);
  SplitMix64 rng(seed ^ 0x5EEDull);
  for (uint32_t i = 0; i < 3 * vertices; ++i) mesh.positions.push_back(float(draw(rng, 1 << 16)) / 65536.f);
  return mesh;
}

}  // namespace qmc::tools
