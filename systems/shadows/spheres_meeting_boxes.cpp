// SPDX-License-Identifier: MIT
#include "systems/shadows/spheres_meeting_boxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ecs/jobs/thread_pool.h"

namespace sg::shadows {
namespace {

// A uniform grid over the x-z plane. Coordinates beyond its edges fall into its edge cells, so a
// sphere and a box that overlap in x and z always share a cell, wherever they are: the cell of a
// coordinate never decreases as the coordinate grows.
struct Grid {
  glm::vec2 origin{0.0f};  // x and z of cell (0, 0)'s lower corner
  float cell = 1.0f;       // side, world units
  uint32_t columns = 1;    // along x
  uint32_t rows = 1;       // along z

  uint32_t index(float offset, uint32_t count) const {
    const float i = std::floor(offset / cell);
    if (!(i > 0.0f)) return 0;
    return i >= static_cast<float>(count - 1) ? count - 1 : static_cast<uint32_t>(i);
  }
  uint32_t column(float x) const { return index(x - origin.x, columns); }
  uint32_t row(float z) const { return index(z - origin.y, rows); }
  size_t cell_count() const { return size_t{columns} * rows; }

  // Calls visit(cell) for every cell the x-z rectangle [min, max] covers, until visit returns true.
  template <class Visit>
  void for_each_cell(glm::vec2 min, glm::vec2 max, Visit visit) const {
    const uint32_t last_column = column(max.x);
    const uint32_t last_row = row(max.y);
    for (uint32_t r = row(min.y); r <= last_row; ++r) {
      for (uint32_t c = column(min.x); c <= last_column; ++c) {
        if (visit(size_t{r} * columns + c)) return;
      }
    }
  }
};

glm::vec2 footprint_min(const scene::Aabb& box) { return {box.min.x, box.min.z}; }
glm::vec2 footprint_max(const scene::Aabb& box) { return {box.max.x, box.max.z}; }
glm::vec2 footprint_min(const glm::vec4& sphere) { return {sphere.x - sphere.w, sphere.z - sphere.w}; }
glm::vec2 footprint_max(const glm::vec4& sphere) { return {sphere.x + sphere.w, sphere.z + sphere.w}; }

// Over the boxes' centres (an outlying box, or a sphere far from every box, falls into the edge
// cells rather than stretching the grid), cells about one mean sphere diameter wide so that a
// typical sphere covers up to four, and at most about twice as many cells as boxes and spheres.
Grid grid_for(std::span<const glm::vec4> spheres, std::span<const scene::Aabb> boxes) {
  glm::vec2 low{std::numeric_limits<float>::max()};
  glm::vec2 high{std::numeric_limits<float>::lowest()};
  for (const scene::Aabb& box : boxes) {
    const glm::vec3 centre = box.center();
    low = glm::min(low, glm::vec2(centre.x, centre.z));
    high = glm::max(high, glm::vec2(centre.x, centre.z));
  }
  double radius_sum = 0.0;
  for (const glm::vec4& sphere : spheres) radius_sum += sphere.w;
  const glm::vec2 extent = high - low;
  const double max_cells = 2.0 * static_cast<double>(spheres.size() + boxes.size()) + 16.0;
  Grid grid;
  grid.origin = low;
  grid.cell = std::max({2.0f * static_cast<float>(radius_sum / static_cast<double>(spheres.size())),
                        std::max(extent.x, extent.y) / static_cast<float>(max_cells),
                        std::numeric_limits<float>::min()});
  for (;;) {
    const double columns = std::floor(extent.x / grid.cell) + 1.0;
    const double rows = std::floor(extent.y / grid.cell) + 1.0;
    if (columns * rows <= max_cells) {
      grid.columns = static_cast<uint32_t>(columns);
      grid.rows = static_cast<uint32_t>(rows);
      return grid;
    }
    grid.cell *= 2.0f;
  }
}

}  // namespace

bool sphere_meets_box(const glm::vec4& sphere, const scene::Aabb& box) {
  const glm::vec3 centre(sphere);
  const glm::vec3 offset = centre - glm::clamp(centre, box.min, box.max);
  return glm::dot(offset, offset) <= sphere.w * sphere.w;
}

// The boxes are binned and the spheres looked up, not the other way round: the boxes are usually
// far fewer, so binning them is cheap, and the spheres are then read in order with the grid in
// cache. Binning 100,000 spheres scattered their writes over megabytes and cost more than all the
// tests it saved.
void SpheresMeetingBoxes::find(std::span<const glm::vec4> spheres, std::span<const scene::Aabb> boxes,
                               std::span<uint8_t> met, jobs::ThreadPool* pool) {
  if (spheres.empty() || boxes.empty()) return;
  const Grid grid = grid_for(spheres, boxes);

  // Bin the boxes: count per cell, prefix sums, fill (each cell's begin advances to its end),
  // then shift the begins back.
  cell_begin_.assign(grid.cell_count() + 1, 0);
  for (const scene::Aabb& box : boxes) {
    grid.for_each_cell(footprint_min(box), footprint_max(box), [&](size_t cell) {
      ++cell_begin_[cell + 1];
      return false;
    });
  }
  for (size_t cell = 0; cell < grid.cell_count(); ++cell) cell_begin_[cell + 1] += cell_begin_[cell];
  cell_boxes_.resize(cell_begin_.back());
  for (uint32_t b = 0; b < boxes.size(); ++b) {
    grid.for_each_cell(footprint_min(boxes[b]), footprint_max(boxes[b]), [&](size_t cell) {
      cell_boxes_[cell_begin_[cell]++] = b;
      return false;
    });
  }
  for (size_t cell = grid.cell_count(); cell > 0; --cell) cell_begin_[cell] = cell_begin_[cell - 1];
  cell_begin_[0] = 0;

  constexpr size_t spheres_per_piece = 256;
  jobs::run_in_pieces(pool, spheres.size(), spheres_per_piece, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      if (met[i] != 0) continue;
      grid.for_each_cell(footprint_min(spheres[i]), footprint_max(spheres[i]), [&](size_t cell) {
        for (uint32_t k = cell_begin_[cell]; k < cell_begin_[cell + 1]; ++k) {
          if (sphere_meets_box(spheres[i], boxes[cell_boxes_[k]])) {
            met[i] = 1;
            return true;
          }
        }
        return false;
      });
    }
  });
}

}  // namespace sg::shadows
