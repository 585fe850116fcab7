// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_atlas_pages.h"

#include <algorithm>
#include <bit>

namespace sg::shadows {
namespace {

// Nodes of depth d come after those of depths 0 .. d - 1: (4^d - 1) / 3 of them.
uint32_t first_node(uint32_t depth) { return ((1u << (2 * depth)) - 1) / 3; }
uint32_t node(uint32_t depth, uint32_t i, uint32_t j) { return first_node(depth) + (j << depth) + i; }

}  // namespace

ShadowAtlasPages::ShadowAtlasPages(uint32_t page_size, uint32_t min_tile, uint32_t max_pages)
    : page_size_(page_size),
      depth_count_(uint32_t(std::countr_zero(page_size / min_tile)) + 1),
      max_pages_(max_pages),
      search_from_(depth_count_, 0) {}

ShadowAtlasPages::Tree& ShadowAtlasPages::page_tree(uint32_t page) {
  if (page == pages_.size()) {
    pages_.emplace_back(first_node(depth_count_), uint8_t(0));
    pages_.back()[0] = code(0);
  }
  return pages_[page];
}

bool ShadowAtlasPages::allocate(uint32_t size, std::span<AtlasTile> tiles) {
  const uint32_t depth = uint32_t(std::countr_zero(page_size_ / size));
  for (uint32_t page = search_from_[depth]; page < max_pages_; ++page) {
    if (page_tree(page)[0] < code(depth)) {
      if (page == search_from_[depth]) ++search_from_[depth];
      continue;
    }
    size_t allocated = 0;
    while (allocated < tiles.size() && allocate_on(page, depth, tiles[allocated])) ++allocated;
    if (allocated == tiles.size()) return true;
    // This page has room for some of the tiles but not all: they must share a page.
    for (size_t k = 0; k < allocated; ++k) free(tiles[k]);
  }
  return false;
}

bool ShadowAtlasPages::allocate_on(uint32_t page, uint32_t depth, AtlasTile& tile) {
  Tree& tree = pages_[page];
  if (tree[0] < code(depth)) return false;
  uint32_t d = 0, i = 0, j = 0;
  while (d < depth) {
    if (tree[node(d, i, j)] == code(d)) {  // entirely free: split it
      for (uint32_t c = 0; c < 4; ++c) tree[node(d + 1, 2 * i + (c & 1), 2 * j + (c >> 1))] = code(d + 1);
    }
    // Into the child with the smallest free block that is large enough, so that large free
    // blocks stay whole for large tiles.
    uint32_t best_i = 0, best_j = 0;
    uint8_t best = 0xff;
    for (uint32_t c = 0; c < 4; ++c) {
      const uint32_t ci = 2 * i + (c & 1), cj = 2 * j + (c >> 1);
      const uint8_t largest = tree[node(d + 1, ci, cj)];
      if (largest >= code(depth) && largest < best) best = largest, best_i = ci, best_j = cj;
    }
    ++d, i = best_i, j = best_j;
  }
  tree[node(d, i, j)] = 0;
  update_ancestors(tree, d, i, j);
  const uint32_t size = page_size_ >> depth;
  tile = {page, i * size, j * size, size};
  return true;
}

bool ShadowAtlasPages::claim(const AtlasTile& tile) {
  const uint32_t depth = uint32_t(std::countr_zero(page_size_ / tile.size));
  if (tile.page >= max_pages_) return false;
  Tree& tree = page_tree(tile.page);
  const uint32_t i = tile.x / tile.size, j = tile.y / tile.size;
  for (uint32_t d = 0; d < depth; ++d) {
    const uint32_t shift = depth - d;
    const uint32_t ai = i >> shift, aj = j >> shift;
    const uint8_t largest = tree[node(d, ai, aj)];
    if (largest < code(depth)) return false;  // no free block of its size below this one
    if (largest == code(d)) {                 // entirely free: split it
      for (uint32_t c = 0; c < 4; ++c) tree[node(d + 1, 2 * ai + (c & 1), 2 * aj + (c >> 1))] = code(d + 1);
    }
  }
  if (tree[node(depth, i, j)] != code(depth)) return false;
  tree[node(depth, i, j)] = 0;
  update_ancestors(tree, depth, i, j);
  return true;
}

void ShadowAtlasPages::free(const AtlasTile& tile) {
  const uint32_t depth = uint32_t(std::countr_zero(page_size_ / tile.size));
  Tree& tree = pages_[tile.page];
  const uint32_t i = tile.x / tile.size, j = tile.y / tile.size;
  tree[node(depth, i, j)] = code(depth);
  update_ancestors(tree, depth, i, j);
  for (uint32_t& from : search_from_) from = std::min(from, tile.page);
}

void ShadowAtlasPages::update_ancestors(Tree& tree, uint32_t depth, uint32_t i, uint32_t j) {
  for (; depth > 0; --depth, i /= 2, j /= 2) {
    const uint32_t pi = i / 2, pj = j / 2;
    uint8_t largest = 0;
    bool all_free = true;
    for (uint32_t c = 0; c < 4; ++c) {
      const uint8_t child = tree[node(depth, 2 * pi + (c & 1), 2 * pj + (c >> 1))];
      largest = std::max(largest, child);
      all_free = all_free && child == code(depth);
    }
    const uint8_t parent = all_free ? code(depth - 1) : largest;
    uint8_t& stored = tree[node(depth - 1, pi, pj)];
    if (stored == parent) return;  // nothing above changes either
    stored = parent;
  }
}

uint32_t ShadowAtlasPages::pages_used() const {
  for (auto page = uint32_t(pages_.size()); page-- > 0;) {
    if (pages_[page][0] != code(0)) return page + 1;  // its root not entirely free
  }
  return 0;
}

void ShadowAtlasPages::clear() {
  // A free root makes the rest of its tree stale, to be rewritten as it splits again.
  for (Tree& tree : pages_) tree[0] = code(0);
  std::fill(search_from_.begin(), search_from_.end(), 0u);
}

}  // namespace sg::shadows
