// SPDX-License-Identifier: MIT
#pragma once
// Square power-of-two tiles in square pages (the layers of one depth-array image): a quadtree
// ("buddy") allocator per page, where a free square splits into four quarters and four free
// quarters merge back into their parent.
//
// Allocating in order of decreasing size never fragments: every free block is then at least as
// large as the tile being allocated, so a page with the area left always has room. The shadow
// atlas planner's repack relies on it.
#include <cstdint>
#include <span>
#include <vector>

namespace sg::shadows {

struct AtlasTile {
  uint32_t page = 0;
  uint32_t x = 0;  // texels within the page
  uint32_t y = 0;
  uint32_t size = 0;  // texels, square

  friend bool operator==(const AtlasTile&, const AtlasTile&) = default;
};

class ShadowAtlasPages {
 public:
  // page_size and min_tile are powers of two with min_tile <= page_size. A page's quadtree
  // costs (page_size / min_tile)^2 * 4/3 bytes; it is made when the page is first used.
  ShadowAtlasPages(uint32_t page_size, uint32_t min_tile, uint32_t max_pages);

  // Fills `tiles` with tiles of `size` texels (a power of two in [min_tile, page_size]), all on
  // the lowest page that has room for every one of them. False, with nothing allocated, when no
  // page below max_pages has.
  bool allocate(uint32_t size, std::span<AtlasTile> tiles);
  // Takes this very tile (one allocate() returned before): false, with nothing taken, when any
  // of it is not free.
  bool claim(const AtlasTile& tile);
  // Gives back a tile that allocate() returned.
  void free(const AtlasTile& tile);
  // Gives back every tile.
  void clear();
  // The highest page holding a tile, plus one (0: none).
  uint32_t pages_used() const;

 private:
  // A page's quadtree: per node the size code of the largest free block in its subtree (0: none,
  // 1: a min_tile square, 2: twice that side, ...). The children of a node that is entirely free
  // hold stale values until the node is split.
  using Tree = std::vector<uint8_t>;

  uint8_t code(uint32_t depth) const { return uint8_t(depth_count_ - depth); }
  bool allocate_on(uint32_t page, uint32_t depth, AtlasTile& tile);
  void update_ancestors(Tree& tree, uint32_t depth, uint32_t i, uint32_t j);
  Tree& page_tree(uint32_t page);

  uint32_t page_size_;
  uint32_t depth_count_;  // depths 0 (the page) .. depth_count_ - 1 (min_tile squares)
  uint32_t max_pages_;
  std::vector<Tree> pages_;
  // Per depth, a page below which no page has a free block of that depth's size: the search for
  // room starts there.
  std::vector<uint32_t> search_from_;
};

}  // namespace sg::shadows
