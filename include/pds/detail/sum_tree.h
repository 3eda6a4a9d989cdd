#pragma once
// Weighted choice among n items with O(log n) updates: partial sums over a
// complete binary tree. Every inner node is recomputed from its children (no
// drift), so the root is exactly 0 once every weight is. Used by the samplers
// that pick a region in proportion to its free area (Jones, Dunbar-Humphreys).

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pds::detail {

class SumTree {
 public:
  double total() const { return node_.empty() ? 0.0 : node_[1]; }
  double weight(std::size_t i) const { return i < leaves_ ? node_[leaves_ + i] : 0.0; }

  /// Sets item i's weight (w >= 0), growing the tree as needed.
  void set(std::size_t i, double w) {
    if (i >= leaves_) grow(i + 1);
    std::size_t at = leaves_ + i;
    node_[at] = w;
    for (at /= 2; at >= 1; at /= 2) node_[at] = node_[2 * at] + node_[2 * at + 1];
  }

  /// The item where the running sum passes u, u in [0, total()). A subtree
  /// whose sum is 0 is never entered, whatever the rounding of u.
  std::size_t find(double u) const {
    std::size_t at = 1;
    while (at < leaves_) {
      if (u < node_[2 * at] || node_[2 * at + 1] <= 0.0) {
        at = 2 * at;
      } else {
        u -= node_[2 * at];
        at = 2 * at + 1;
      }
    }
    return at - leaves_;
  }

  /// Makes room for n items without changing any weight.
  void reserve(std::size_t n) {
    if (n > leaves_) grow(n);
  }

 private:
  void grow(std::size_t n) {
    std::size_t leaves = std::max<std::size_t>(leaves_, 1);
    while (leaves < n) leaves *= 2;
    std::vector<double> old(node_.begin() + static_cast<std::ptrdiff_t>(leaves_), node_.end());
    leaves_ = leaves;
    node_.assign(2 * leaves_, 0.0);
    std::copy(old.begin(), old.end(), node_.begin() + static_cast<std::ptrdiff_t>(leaves_));
    for (std::size_t at = leaves_ - 1; at >= 1; --at) node_[at] = node_[2 * at] + node_[2 * at + 1];
  }

  std::size_t leaves_ = 0;
  std::vector<double> node_;
};

}  // namespace pds::detail
