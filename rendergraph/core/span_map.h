// SPDX-License-Identifier: MIT
#pragma once

// Interval maps that keep one value per span of a key range, splitting spans where an update
// starts or ends and joining equal neighbours afterwards. The barrier planner keeps one per image
// (state per mip x layer span); the aliasing planner one per heap (owner per byte span).

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "rendergraph/core/resource_types.h"

namespace sg::rg {

template <class Key, class Value>
class SpanMap {
 public:
  struct Span {
    Key first;
    Key count;
    Value value;
  };

  SpanMap(Key extent, Value initial) : spans_{Span{0, extent, std::move(initial)}} {}

  // Calls visit(first, count, value&) for each span inside [first, first + count), in key order,
  // after splitting the spans that cross its edges.
  template <class Visit>
  void update(Key first, Key count, Visit&& visit) {
    const Key end = first + count;
    split_at(first);
    split_at(end);
    for (auto it = find(first); it != spans_.end() && it->first < end; ++it) {
      visit(it->first, it->count, it->value);
    }
    join_equal_neighbours();
  }

  std::span<const Span> spans() const { return spans_; }

 private:
  // The span that contains `key`.
  auto find(Key key) {
    auto it = std::upper_bound(spans_.begin(), spans_.end(), key,
                               [](Key k, const Span& span) { return k < span.first; });
    return std::prev(it);
  }

  void split_at(Key key) {
    if (key >= spans_.back().first + spans_.back().count) return;
    auto it = find(key);
    if (it->first == key) return;
    Span tail{key, it->first + it->count - key, it->value};
    it->count = key - it->first;
    spans_.insert(std::next(it), std::move(tail));
  }

  void join_equal_neighbours() {
    auto out = spans_.begin();
    for (auto it = std::next(spans_.begin()); it != spans_.end(); ++it) {
      if (it->value == out->value) {
        out->count += it->count;
      } else {
        *++out = std::move(*it);
      }
    }
    spans_.erase(std::next(out), spans_.end());
  }

  std::vector<Span> spans_;
};

// A value per subresource of an image (mips x layers), stored as layer spans per mip.
template <class Value>
class SubresourceMap {
 public:
  SubresourceMap(std::uint32_t mips, std::uint32_t layers, const Value& initial)
      : mips_(mips, SpanMap<std::uint32_t, Value>(layers, initial)) {}

  // Calls visit(single-mip range, value&) for each span inside the resolved `range`.
  template <class Visit>
  void update(const SubresourceRange& range, Visit&& visit) {
    for (std::uint32_t mip = range.base_mip; mip < range.base_mip + range.mip_count; ++mip) {
      mips_[mip].update(range.base_layer, range.layer_count,
                        [&](std::uint32_t first, std::uint32_t count, Value& value) {
                          visit(SubresourceRange{mip, 1, first, count}, value);
                        });
    }
  }

  template <class Visit>
  void for_each(Visit&& visit) const {
    for (std::uint32_t mip = 0; mip < mips_.size(); ++mip) {
      for (const auto& span : mips_[mip].spans())
        visit(SubresourceRange{mip, 1, span.first, span.count}, span.value);
    }
  }

 private:
  std::vector<SpanMap<std::uint32_t, Value>> mips_;
};

template <class Value>
struct RangeValue {
  SubresourceRange range;
  Value value;
};

// Joins single-mip pieces that carry equal values into as few ranges as possible: neighbouring
// layers of a mip first, then the same layers on consecutive mips. Pieces come mip by mip, layers
// ascending, as SubresourceMap produces them.
template <class Value>
std::vector<RangeValue<Value>> merge_into_ranges(const std::vector<RangeValue<Value>>& pieces) {
  std::vector<RangeValue<Value>> rows;
  for (const auto& piece : pieces) {
    if (!rows.empty()) {
      SubresourceRange& last = rows.back().range;
      if (last.base_mip == piece.range.base_mip &&
          last.base_layer + last.layer_count == piece.range.base_layer && rows.back().value == piece.value) {
        last.layer_count += piece.range.layer_count;
        continue;
      }
    }
    rows.push_back(piece);
  }
  std::vector<RangeValue<Value>> ranges;
  for (const auto& row : rows) {
    auto below = std::find_if(ranges.begin(), ranges.end(), [&](const RangeValue<Value>& r) {
      return r.value == row.value && r.range.base_layer == row.range.base_layer &&
             r.range.layer_count == row.range.layer_count &&
             r.range.base_mip + r.range.mip_count == row.range.base_mip;
    });
    if (below != ranges.end()) {
      ++below->range.mip_count;
    } else {
      ranges.push_back(row);
    }
  }
  return ranges;
}

}  // namespace sg::rg
