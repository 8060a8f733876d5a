// Disjoint sets with path halving and union by size, over 0..n-1.
#pragma once

#include <numeric>
#include <vector>

namespace qm {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// Joins the sets of a and b; returns false when they were already one.
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }
  /// Dense labels 0..k-1 of the sets, in order of first appearance; returns k.
  int labels(std::vector<int>& label) {
    label.assign(parent_.size(), -1);
    std::vector<int> root_label(parent_.size(), -1);
    int k = 0;
    for (std::size_t i = 0; i < parent_.size(); ++i) {
      int r = find(static_cast<int>(i));
      if (root_label[r] < 0) root_label[r] = k++;
      label[i] = root_label[r];
    }
    return k;
  }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

}  // namespace qm
