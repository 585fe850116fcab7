// SPDX-License-Identifier: MIT
#pragma once
// State kept per light across frames, matched to a frame's lights by their keys.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sg::shadows {

// Makes `entries` hold one entry per item of `items` (anything with a uint64_t `key`), in their
// order: each carried over from the entry of the same key, or new (Entry{.key = key}); entries
// whose key is gone are dropped. Usually the items come in the previous call's order and nothing
// is looked up. `index_of_key` and `scratch` are storage kept between calls, so that a call
// allocates nothing once grown. Returns whether the entries' keys changed.
template <class Items, class Entry>
bool align_by_key(const Items& items, std::vector<Entry>& entries,
                  std::unordered_map<uint64_t, uint32_t>& index_of_key, std::vector<Entry>& scratch) {
  if (std::equal(items.begin(), items.end(), entries.begin(), entries.end(),
                 [](const auto& item, const Entry& entry) { return item.key == entry.key; }))
    return false;
  index_of_key.clear();
  for (uint32_t k = 0; k < entries.size(); ++k) index_of_key.emplace(entries[k].key, k);
  scratch.clear();
  for (const auto& item : items) {
    const auto found = index_of_key.find(item.key);
    scratch.push_back(found == index_of_key.end() ? Entry{.key = item.key} : entries[found->second]);
  }
  std::swap(entries, scratch);
  return true;
}

}  // namespace sg::shadows
