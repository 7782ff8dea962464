// The move-to-front list of recently referenced vertices used by the indexed
// connectivity coding (spec/qmc-format.md section 5.2.3). Shared by encoder
// and decoder so both sides update it identically.
#pragma once

#include <cstdint>

namespace qmc {

class RecentVertexList {
 public:
  static constexpr int kCapacity = 32;

  int size() const { return size_; }
  uint32_t at(int position) const { return items_[position]; }

  // Position of `label`, or -1.
  int find(uint32_t label) const {
    for (int i = 0; i < size_; ++i)
      if (items_[i] == label) return i;
    return -1;
  }

  // Moves `label` to the front, inserting it if absent; the oldest entry
  // drops out when the list is full.
  void touch(uint32_t label) {
    int i = find(label);
    if (i < 0) i = size_ < kCapacity ? size_++ : kCapacity - 1;
    for (; i > 0; --i) items_[i] = items_[i - 1];
    items_[0] = label;
  }

 private:
  uint32_t items_[kCapacity] = {};
  int size_ = 0;
};

}  // namespace qmc
