// SPDX-License-Identifier: MIT
#include "systems/shadows/depth_placement.h"

#include <algorithm>
#include <bit>

#include "systems/shadows/radix_sort.h"

namespace sg::shadows {
namespace {

bool same_page_and_size(const AtlasTile& a, const AtlasTile& b) {
  return a.page == b.page && a.size == b.size;
}
bool same_row(const AtlasTile& a, const AtlasTile& b) { return same_page_and_size(a, b) && a.y == b.y; }
uint64_t texels_of(const DepthRegion& region) { return uint64_t{region.width} * region.height; }

}  // namespace

void DepthPlacement::place_nowhere(size_t views) {
  tiles_.clear();
  places_.assign(views, glm::uvec2(0u));
  regions_.clear();
  copied_.clear();
  drawn_.clear();
  texels_ = 0;
}

bool DepthPlacement::place(std::span<const AtlasTile> tiles, uint64_t copied_texels) {
  if (copied_texels == copied_texels_ &&
      std::equal(tiles.begin(), tiles.end(), tiles_.begin(), tiles_.end())) {
    return false;
  }
  tiles_.assign(tiles.begin(), tiles.end());
  copied_texels_ = copied_texels;
  places_.assign(tiles.size(), glm::uvec2(0u));
  // By page, size, row, column, packed into 40 bits: tiles lie on multiples of their size, so
  // rows and columns count tiles, not texels (below 2^11 for pages of up to 2^11 of the smallest
  // tiles), which leaves four byte-wide passes of the radix sort instead of six. Were a count
  // larger, tiles would only sort out of place and share fewer regions: merging checks them.
  placed_.resize(tiles.size());
  for (size_t v = 0; v < tiles.size(); ++v) {
    const AtlasTile& t = tiles[v];
    const auto level = static_cast<uint64_t>(std::countr_zero(t.size));
    placed_[v] = {uint64_t{t.page} << 26 | level << 22 | uint64_t{t.y / t.size} << 11 | (t.x / t.size),
                  static_cast<uint32_t>(v)};
  }
  radix_sort(
      placed_, placed_scratch_, [](const Placed& p) { return p.key; }, 40);
  const auto tile_at = [&](size_t k) -> const AtlasTile& { return tiles_[placed_[k].view]; };

  // Runs of side-by-side tiles, row by row; each joins the region of the run above it when that
  // run spans the same columns (runs of a row come in column order, so one cursor finds it).
  runs_.clear();
  regions_.clear();
  size_t row_begin = 0;  // the current row's first run
  size_t above = 0;      // the row above's runs: [above, above_end), empty when it has none
  size_t above_end = 0;
  for (size_t begin = 0; begin < placed_.size();) {
    const AtlasTile& first = tile_at(begin);
    size_t end = begin + 1;
    while (end < placed_.size()) {
      const AtlasTile& next = tile_at(end);
      if (!same_row(next, first) || next.x != tile_at(end - 1).x + first.size) break;
      ++end;
    }
    const auto width = static_cast<uint32_t>(end - begin) * first.size;
    if (runs_.empty() || !same_row(tile_at(runs_[row_begin].begin), first)) {
      const bool below = !runs_.empty() && same_page_and_size(tile_at(runs_[row_begin].begin), first) &&
                         tile_at(runs_[row_begin].begin).y + first.size == first.y;
      above = below ? row_begin : 0;
      above_end = below ? runs_.size() : 0;
      row_begin = runs_.size();
    }
    while (above < above_end && tile_at(runs_[above].begin).x < first.x) ++above;
    uint32_t region = static_cast<uint32_t>(regions_.size());
    if (above < above_end && tile_at(runs_[above].begin).x == first.x && runs_[above].width == width) {
      region = runs_[above].region;
      regions_[region].height += first.size;
    } else {
      regions_.push_back({first, width, first.size, 0});
    }
    runs_.push_back({begin, end, width, region});
    begin = end;
  }

  texels_ = 0;
  copied_.clear();
  for (DepthRegion& region : regions_) {
    region.offset = texels_;
    texels_ += texels_of(region);
    if (texels_of(region) >= copied_texels) copied_.push_back(region);
  }
  view_drawn_.assign(tiles.size(), 0);
  for (const Run& run : runs_) {
    const DepthRegion& region = regions_[run.region];
    const bool drawn = texels_of(region) < copied_texels;
    for (size_t k = run.begin; k < run.end; ++k) {
      const AtlasTile& tile = tile_at(k);
      const uint64_t texel =
          region.offset + uint64_t{tile.y - region.corner.y} * region.width + (tile.x - region.corner.x);
      places_[placed_[k].view] = {static_cast<uint32_t>(texel), region.width};
      view_drawn_[placed_[k].view] = drawn ? 1 : 0;
    }
  }
  drawn_.clear();
  for (uint32_t v = 0; v < view_drawn_.size(); ++v) {
    if (!view_drawn_[v]) continue;
    if (!drawn_.empty() && drawn_.back().first + drawn_.back().count == v) {
      ++drawn_.back().count;
    } else {
      drawn_.push_back({v, 1});
    }
  }
  return true;
}

}  // namespace sg::shadows
