// SPDX-License-Identifier: MIT
#pragma once
// A stable LSD radix sort by an unsigned integer key, a byte a pass: what the shadow code sorts
// each frame (thousands of views, up to 100,000 lights) by packed keys, several times faster at
// those sizes than a comparison sort. Bytes in which every key agrees cost one counting pass.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sg::shadows {

// Sorts `items` ascending by the low `key_bits` bits of key(item) (a uint64_t), keeping the order
// of equal keys; `scratch` is working storage, its contents lost.
template <class T, class Key>
void radix_sort(std::vector<T>& items, std::vector<T>& scratch, Key key, uint32_t key_bits = 64) {
  scratch.resize(items.size());
  for (uint32_t shift = 0; shift < key_bits; shift += 8) {
    const uint64_t mask = key_bits - shift >= 8 ? 0xff : (uint64_t{1} << (key_bits - shift)) - 1;
    const auto digit = [&](const T& item) { return size_t((uint64_t(key(item)) >> shift) & mask); };
    std::array<size_t, 257> starts{};
    for (const T& item : items) ++starts[digit(item) + 1];
    bool one_digit = false;
    for (size_t d = 1; d < starts.size(); ++d) one_digit = one_digit || starts[d] == items.size();
    if (one_digit) continue;
    for (size_t d = 1; d < starts.size(); ++d) starts[d] += starts[d - 1];
    for (const T& item : items) scratch[starts[digit(item)]++] = item;
    items.swap(scratch);
  }
}

}  // namespace sg::shadows
