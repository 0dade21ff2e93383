#pragma once
/// @file
/// Values for ordered pairs of a tour's places (legs, leg costs), stored sparsely: a tour of a
/// few places keeps every pair, a tour of thousands keeps only the pairs it routes (near
/// neighbours, home, what the plan flies). Indexed like a matrix, `table[from][to]`: reading a
/// pair that is not stored throws std::out_of_range, writing one stores it. docs/tours.md,
/// "Large tours".

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ceilplan::mission {

template <class Value>
/// Values for ordered pairs of places (0 home, 1..N the others), stored only where set: a sparse table of legs or
/// costs.
class PairTable {
 public:
  PairTable() = default;
  /// A table of `place_count` places, empty.
  explicit PairTable(int place_count) : rows_(static_cast<std::size_t>(place_count)) {}

  /// Places in the table.
  int placeCount() const { return static_cast<int>(rows_.size()); }
  /// Pairs stored.
  std::size_t size() const {
    std::size_t count = 0;
    for (const auto& row : rows_) count += row.size();
    return count;
  }
  /// Whether the pair is stored.
  bool contains(int from, int to) const { return find(from, to) != nullptr; }
  /// The stored value, or null.
  const Value* find(int from, int to) const {
    const auto& row = rows_.at(static_cast<std::size_t>(from));
    const auto it = row.find(to);
    return it == row.end() ? nullptr : &it->second;
  }
  /// The stored value, or null.
  Value* find(int from, int to) {
    auto& row = rows_.at(static_cast<std::size_t>(from));
    const auto it = row.find(to);
    return it == row.end() ? nullptr : &it->second;
  }
  /// The stored value; std::out_of_range when the pair is not stored.
  const Value& at(int from, int to) const {
    if (const Value* value = find(from, to)) return *value;
    throw std::out_of_range("no entry from place " + std::to_string(from) + " to place " + std::to_string(to));
  }
  /// Stores a default value if the pair is not stored yet. References stay valid while other
  /// pairs are added, so several threads may fill cells stored beforehand, one cell each.
  Value& operator()(int from, int to) { return rows_.at(static_cast<std::size_t>(from))[to]; }

  /// The stored pairs out of a place, by destination.
  const std::map<int, Value>& row(int from) const { return rows_.at(static_cast<std::size_t>(from)); }

  /// A read-only row: table[from][to] throws std::out_of_range for a pair not stored.
  class ConstRow {
   public:
    /// The row `row` of place `from`.
    explicit ConstRow(const std::map<int, Value>& row, int from) : row_(&row), from_(from) {}
    /// The value to `to`; std::out_of_range when not stored.
    const Value& operator[](int to) const {
      const auto it = row_->find(to);
      if (it == row_->end())
        throw std::out_of_range("no entry from place " + std::to_string(from_) + " to place " + std::to_string(to));
      return it->second;
    }

   private:
    const std::map<int, Value>* row_;
    int from_;
  };
  /// A writable row: table[from][to] stores a default value if the pair is not stored yet.
  class Row {
   public:
    /// The row `row`.
    explicit Row(std::map<int, Value>& row) : row_(&row) {}
    /// The value to `to`, stored first if need be.
    Value& operator[](int to) { return (*row_)[to]; }

   private:
    std::map<int, Value>* row_;
  };
  /// Read-only row `from`.
  ConstRow operator[](int from) const { return ConstRow(rows_.at(static_cast<std::size_t>(from)), from); }
  /// Writable row `from`.
  Row operator[](int from) { return Row(rows_.at(static_cast<std::size_t>(from))); }

 private:
  std::vector<std::map<int, Value>> rows_;
};

}  // namespace ceilplan::mission
