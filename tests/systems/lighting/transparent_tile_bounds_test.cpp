// SPDX-License-Identifier: MIT
// Where transparent instances lie per light tile (systems/lighting/transparent_tile_bounds.h), on the CPU.
#include "systems/lighting/transparent_tile_bounds.h"

#include <vector>

#include <gtest/gtest.h>

#include "systems/gpu/camera.h"
#include "systems/scene/camera.h"

namespace sg::test {
namespace {

constexpr glm::uvec2 screen{160, 96};  // 10 x 6 tiles

struct Seen {
  glm::mat4 view_projection;
  LightTileGrid grid = LightTileGrid::of(screen.x, screen.y);
};

// A camera at the origin looking down -Z.
Seen camera_at_origin() {
  scene::Camera lens;
  const scene::CameraPose pose{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
  return {projection_matrix(lens, float(screen.x) / float(screen.y)) * view_matrix(pose)};
}

glm::vec2 depth_range(const Seen& seen, const scene::Aabb& box) {
  float nearest = camera_far_depth, farthest = camera_near_depth;
  for (int c = 0; c < 8; ++c) {
    const glm::vec4 clip =
        seen.view_projection * glm::vec4((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                         (c & 4) ? box.max.z : box.min.z, 1.0f);
    nearest = std::max(nearest, clip.z / clip.w);
    farthest = std::min(farthest, clip.z / clip.w);
  }
  return {nearest, farthest};
}

TEST(TransparentTileBounds, ABoxAheadBoundsTheTilesItCoversByItsDepths) {
  const Seen seen = camera_at_origin();
  const scene::Aabb box{{-0.5f, -0.5f, -6.0f}, {0.5f, 0.5f, -5.0f}};  // small, straight ahead
  std::vector<glm::vec2> bounds;
  transparent_tile_bounds(seen.view_projection, seen.grid, screen, std::span(&box, 1), bounds);
  ASSERT_EQ(bounds.size(), seen.grid.count());
  const glm::vec2 expected = depth_range(seen, box);
  const glm::vec2 centre = bounds[3 * seen.grid.across + 5];  // the tile right of the centre
  EXPECT_FLOAT_EQ(centre.x, expected.x);
  EXPECT_FLOAT_EQ(centre.y, expected.y);
  EXPECT_EQ(bounds[0].x, 0.0f) << "a corner tile has no transparent surface";
  EXPECT_EQ(bounds[seen.grid.count() - 1].x, 0.0f);
}

TEST(TransparentTileBounds, ABoxAroundTheCameraCoversEveryTileFromTheNearPlane) {
  const Seen seen = camera_at_origin();
  const scene::Aabb box{{-2.0f, -2.0f, -2.0f}, {2.0f, 2.0f, 2.0f}};
  std::vector<glm::vec2> bounds;
  transparent_tile_bounds(seen.view_projection, seen.grid, screen, std::span(&box, 1), bounds);
  for (const glm::vec2& tile : bounds) {
    EXPECT_EQ(tile.x, camera_near_depth);
    EXPECT_LT(tile.y, camera_near_depth) << "reaches out to the box's far side";
  }
}

TEST(TransparentTileBounds, ABoxBehindTheCameraCoversNothing) {
  const Seen seen = camera_at_origin();
  const scene::Aabb box{{-1.0f, -1.0f, 2.0f}, {1.0f, 1.0f, 3.0f}};
  std::vector<glm::vec2> bounds;
  transparent_tile_bounds(seen.view_projection, seen.grid, screen, std::span(&box, 1), bounds);
  for (const glm::vec2& tile : bounds) EXPECT_EQ(tile.x, 0.0f);
}

}  // namespace
}  // namespace sg::test
