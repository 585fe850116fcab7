// SPDX-License-Identifier: MIT
#pragma once
// Where the compute shadow raster puts each due view's depths: a tile-sized square of one depth
// buffer per view, and how those squares reach the atlas (ComputeShadowRaster): large rectangles
// by a buffer-to-image copy, the views of small ones by a draw that writes their depths. A copy
// pays for each rectangle as well as its texels, a draw only for its texels but more for each
// (docs/PERFORMANCE.md), so due tiles of one size side by side on a row of a page share one
// rectangle, and such a run directly below one of the same columns extends that run's rectangle
// downward: a block of due tiles is one rectangle, its depths row-major in one rectangle of the
// buffer.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "systems/shadows/shadow_atlas_pages.h"

namespace sg::shadows {

// One rectangle of due tiles.
struct DepthRegion {
  AtlasTile corner;     // its top-left tile
  uint32_t width = 0;   // texels, also the rows' pitch in the depth buffer
  uint32_t height = 0;  // texels
  uint64_t offset = 0;  // its first texel in the depth buffer
};

// Views first, first + 1, ... first + count - 1, drawn.
struct ViewRun {
  uint32_t first = 0;
  uint32_t count = 0;
};

class DepthPlacement {
 public:
  // Places the views whose tiles are `tiles` (one per view); rectangles of at least
  // `copied_texels` are copied, the views of smaller ones drawn. False when the tiles and the
  // size are the last call's, whose places stand (while every light redraws every frame and none
  // moves in the atlas, the sort is skipped).
  bool place(std::span<const AtlasTile> tiles, uint64_t copied_texels);
  // `views` views placed nowhere (every place 0), for frames the hardware rasterizes; the next
  // place() places anew.
  void place_nowhere(size_t views);

  // Per view: its square's texel (0, 0) in the depth buffer, and the row pitch there.
  std::span<const glm::uvec2> places() const { return places_; }
  // The rectangles copied.
  std::span<const DepthRegion> copied() const { return copied_; }
  // The views drawn, in runs of consecutive views.
  std::span<const ViewRun> drawn() const { return drawn_; }
  // The depth buffer's size, texels.
  uint64_t texels() const { return texels_; }

 private:
  struct Placed {
    uint64_t key;  // page, size, row, column
    uint32_t view;
  };
  // A row's run of side-by-side tiles.
  struct Run {
    size_t begin, end;  // in placed_
    uint32_t width;     // texels
    uint32_t region;
  };
  std::vector<AtlasTile> tiles_;  // what the places are for
  uint64_t copied_texels_ = 0;    // and the size copied
  std::vector<glm::uvec2> places_;
  std::vector<DepthRegion> regions_;
  std::vector<DepthRegion> copied_;
  std::vector<ViewRun> drawn_;
  std::vector<uint8_t> view_drawn_;
  uint64_t texels_ = 0;
  std::vector<Placed> placed_;  // the views by page, size, row, column
  std::vector<Placed> placed_scratch_;
  std::vector<Run> runs_;
};

}  // namespace sg::shadows
