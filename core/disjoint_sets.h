// Disjoint sets of 0 .. n-1 (union-find with path halving): the components of a relation given one
// pair at a time. The topology of a mesh, its corner fans and its cut graph use it.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace uvtk {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }

  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  // False when a and b were already in one set.
  bool join(std::size_t a, std::size_t b) {
    const std::size_t ra = find(a), rb = find(b);
    parent_[ra] = rb;
    return ra != rb;
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace uvtk
