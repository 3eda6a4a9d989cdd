#pragma once
// Append-only storage in blocks of 2^Shift elements that never move, for the
// samplers' large working lists (ebeida's sub-cell codes, the unbounded
// field's darts and sub-cells, best-candidate's live boxes).
//
// Why not std::vector: growing a vector copies what it holds into a buffer
// twice the size and holds both until the copy ends, three times the data at
// the moment of the peak (ebeida's level-1 codes: 100 MB at 10^6 samples in
// 2D; best-candidate's live boxes: a third of its heap at 10^5). Here a full
// block stays where it is and a new one is added; references to elements stay
// valid while more are added, which the unbounded field's recursion relies on.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace pds::detail {

template <class T, unsigned Shift = 16>
class BlockVector {
 public:
  static constexpr std::size_t kBlock = std::size_t{1} << Shift;

  void push_back(const T& value) {
    if ((size_ & (kBlock - 1)) == 0 && size_ >> Shift == blocks_.size())
      blocks_.push_back(std::make_unique_for_overwrite<T[]>(kBlock));
    (*this)[size_++] = value;
  }
  T& operator[](std::size_t i) { return blocks_[i >> Shift][i & (kBlock - 1)]; }
  const T& operator[](std::size_t i) const { return blocks_[i >> Shift][i & (kBlock - 1)]; }
  std::size_t size() const { return size_; }

  /// Frees the blocks that hold only elements before i (a reader done with
  /// them); those elements must not be read again.
  void release_before(std::size_t i) {
    for (std::size_t b = released_; b < (i >> Shift) && b < blocks_.size(); ++b) blocks_[b].reset();
    released_ = std::max(released_, i >> Shift);
  }

  /// Keeps the first n elements (n <= size()) and frees the blocks past them.
  void truncate(std::size_t n) {
    size_ = n;
    blocks_.resize((n + kBlock - 1) >> Shift);
  }

 private:
  std::vector<std::unique_ptr<T[]>> blocks_;
  std::size_t size_ = 0;
  std::size_t released_ = 0;  // blocks before this one are freed
};

/// A BlockVector of Wide values kept as Narrow ones when its owner knows they
/// fit (said once, at construction; a value is cast, not checked): ebeida's
/// sub-cell codes are 128-bit in general, and under 32 bits at the levels
/// that hold nearly all of them, where they are the largest array.
template <class Wide, class Narrow, unsigned Shift = 16>
class NarrowableBlockVector {
 public:
  explicit NarrowableBlockVector(bool narrow = true) : narrow_(narrow) {}

  void push_back(const Wide& value) {
    if (narrow_)
      narrow_values_.push_back(static_cast<Narrow>(value));
    else
      wide_values_.push_back(value);
  }
  Wide operator[](std::size_t i) const { return narrow_ ? static_cast<Wide>(narrow_values_[i]) : wide_values_[i]; }
  std::size_t size() const { return narrow_ ? narrow_values_.size() : wide_values_.size(); }
  /// BlockVector::release_before.
  void release_before(std::size_t i) {
    narrow_values_.release_before(i);
    wide_values_.release_before(i);
  }

 private:
  bool narrow_;
  BlockVector<Narrow, Shift> narrow_values_;
  BlockVector<Wide, Shift> wide_values_;
};

}  // namespace pds::detail
