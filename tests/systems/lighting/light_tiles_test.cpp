// SPDX-License-Identifier: MIT
// Tiled light culling on lavapipe against a brute-force CPU assignment of the same lights to the
// same tiles (tests/support/light_tiles_reference.h), with validation on.
#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/transform_system.h"
#include "rendergraph/core/compile.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/vulkan/graph_executor.h"
#include "systems/gpu/camera.h"
#include "systems/lighting/light_tiles_pass.h"
#include "systems/scene/scene_builder.h"
#include "systems/shadows/frame_lights.h"
#include "tests/support/gpu_test.h"
#include "tests/support/light_tiles_reference.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 200;  // not a multiple of the tile size: partial tiles at the edges
constexpr uint32_t height = 120;

// Light records as the renderer uploads them: sorted by group, each group's range.
struct SortedLights {
  std::vector<shadows::GpuLight> sorted;
  std::array<uint32_t, shadows::light_group_count + 1> group_begin{};
};

SortedLights sorted_by_group(shadows::FrameLights& lights) {
  SortedLights out{std::vector<shadows::GpuLight>(lights.records.size())};
  shadows::sort_by_group(lights, out.sorted);
  out.group_begin = lights.group_begin;
  return out;
}

// `count` lights of every type and several groups scattered in front of a camera at the origin
// looking down -Z, spots aimed at the floor, the sun, and `behind` unshadowed point lights behind
// the camera, which reach nothing it sees; sorted by group as the renderer uploads them.
SortedLights scattered_lights(uint32_t behind = 0, int count = 60) {
  scene::Scene scene;
  uint32_t seed = 12345;
  const auto random = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1u << 24);
  };
  for (int i = 0; i < count; ++i) {
    // Braces: their elements are drawn left to right under every compiler.
    const glm::vec3 position{random() * 30.0f - 15.0f, random() * 8.0f - 3.0f, -2.0f - random() * 26.0f};
    const glm::vec3 target{position.x + random() * 6.0f - 3.0f, -4.0f, position.z + random() * 6.0f - 3.0f};
    scene::ShadowSettings shadow;
    shadow.algorithm = scene::all_shadow_algorithms[i % 5];
    shadow.casts_shadow = i % 4 != 0;
    const ecs::LocalTransform local{position, scene::look_rotation(position, target), glm::vec3(1.0f)};
    if (i % 3 == 0) {
      scene::SpotLight spot;
      spot.range = 4.0f + random() * 8.0f;
      spot.outer_cone = 0.2f + random() * 0.6f;
      spot.inner_cone = spot.outer_cone * 0.5f;
      scene::add_light(scene, spot, local, shadow, "spot");
    } else if (i == 7 || i == 29) {
      scene::add_light(scene, scene::CylinderLight{glm::vec3(1.0f), 1.0f, 0.5f, 1.5f}, local, shadow, "beam");
    } else {
      scene::PointLight point;
      point.range = 1.0f + random() * 6.0f;
      scene::add_light(scene, point, local, shadow, "point");
    }
  }
  scene::add_light(scene, scene::DirectionalLight{}, ecs::LocalTransform{}, scene::ShadowSettings{}, "sun");
  scene::ShadowSettings unshadowed;
  unshadowed.casts_shadow = false;
  for (uint32_t i = 0; i < behind; ++i) {
    const glm::vec3 position(float(i % 256) * 0.1f, float(i / 256 % 64) * 0.1f, 20.0f + float(i / 16384));
    scene::add_light(scene, scene::PointLight{}, {position}, unshadowed, "behind");
  }
  ecs::update_world_transforms(scene.world, 0);
  shadows::FrameLights lights;
  shadows::gather_lights(scene.world, {glm::vec3(-20.0f), glm::vec3(20.0f)}, {}, lights);
  // Every shadow in the same place: culling only reads which group a light is in.
  for (const shadows::ShadowMapView& map : lights.maps) {
    shadows::set_shadow_map(lights.records[map.light], 0, {0.0f, 0.0f, 1.0f, 1.0f}, 1024, map.view);
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    shadows::set_shadow_cube(lights.records[cube.light], 0, {}, 0.25f, 256, cube.position_far);
  }
  return sorted_by_group(lights);
}

// The centre of pixel (x, y) in normalized device coordinates.
glm::vec2 pixel_ndc(uint32_t x, uint32_t y) {
  return {(x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f};
}

// The world position of the surface at pixel (x, y) with depth `depth`, through `inverse`, the
// inverse of the view-projection that drew it.
glm::vec3 surface_at(const glm::mat4& inverse, uint32_t x, uint32_t y, float depth) {
  const glm::vec4 world = inverse * glm::vec4(pixel_ndc(x, y), depth, 1.0f);
  return glm::vec3(world) / world.w;
}

// The depth buffer of what `view_projection` sees from `eye`: `hit(x, y, ray)` is how far along
// the unit `ray` through pixel (x, y) the first surface lies, or 0 where there is none.
template <class Hit>
std::vector<float> depth_of(const glm::mat4& view_projection, const glm::vec3& eye, Hit hit) {
  const glm::mat4 inverse = glm::inverse(view_projection);
  std::vector<float> depth(width * height, camera_far_depth);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const glm::vec3 ray = glm::normalize(surface_at(inverse, x, y, camera_far_depth) - eye);
      const float t = hit(x, y, ray);
      if (t <= 0.0f) continue;
      const glm::vec4 clip = view_projection * glm::vec4(eye + ray * t, 1.0f);
      depth[y * width + x] = clip.z / clip.w;
    }
  }
  return depth;
}

// The view-projection of a camera at the origin looking down -Z, which scene_depth's scene is
// laid out for.
glm::mat4 origin_view_projection() {
  return projection_matrix(scene::Camera{}, float(width) / float(height)) *
         view_matrix({{0, 0, 0}, {0, 0, -1}});
}

// What a camera at the origin sees: a floor at y = -4, a wall at z = -30 and a corner of sky (the
// far depth); with `posts`, posts at z = -6 in every 24th pixel column and the three after it, so
// that tiles hold surfaces 6 m and 30 m away and nothing between.
std::vector<float> scene_depth(const glm::mat4& view_projection, bool posts = false) {
  return depth_of(view_projection, glm::vec3(0.0f), [posts](uint32_t x, uint32_t y, const glm::vec3& ray) {
    if (x < 40 && y < 30) return 0.0f;
    const float wall = (posts && x % 24 < 4 ? -6.0f : -30.0f) / ray.z;
    return ray.y < 0.0f ? std::min(wall, -4.0f / ray.y) : wall;  // the floor, where nearer
  });
}

vk::Buffer readable(vk::VulkanContext& context, uint64_t bytes, VkBufferUsageFlags usage) {
  return vk::Buffer(context,
                    {bytes, usage | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     vk::MemoryUsage::readback, "light tiles output"});
}

template <class T>
std::vector<T> contents(const vk::Buffer& buffer) {
  std::vector<T> items(buffer.size() / sizeof(T));
  std::memcpy(items.data(), buffer.mapped(), items.size() * sizeof(T));
  return items;
}

// Independently of the shared tile tests: whether `light` lights `point` at all (inside its
// range, cone or beam). Culling may keep lights that reach no pixel, never drop one that does.
bool lights_point(const shadows::GpuLight& light, const glm::vec3& point) {
  const auto type = shadows::GpuLightType(light.info.x);
  const glm::vec3 offset = point - glm::vec3(light.position_range);
  const glm::vec3 axis = glm::vec3(light.direction_type);
  switch (type) {
    case shadows::GpuLightType::directional: return true;
    case shadows::GpuLightType::cylinder:
      return glm::dot(offset, axis) >= 0.0f && glm::length(glm::cross(axis, offset)) <= light.shape.w;
    case shadows::GpuLightType::point: return glm::length(offset) <= light.position_range.w;
    case shadows::GpuLightType::spot:
      return glm::length(offset) <= light.position_range.w &&
             glm::dot(axis, offset) >= light.shape.y * glm::length(offset);
  }
  return false;
}

// One unshadowed light (a scene::PointLight, SpotLight, ...) placed by `local`.
template <typename Light>
SortedLights one_light(const Light& light, const ecs::LocalTransform& local) {
  scene::Scene scene;
  scene::ShadowSettings unshadowed;
  unshadowed.casts_shadow = false;
  scene::add_light(scene, light, local, unshadowed, "light");
  ecs::update_world_transforms(scene.world, 0);
  shadows::FrameLights gathered;
  shadows::gather_lights(scene.world, {glm::vec3(-50.0f), glm::vec3(50.0f)}, {false}, gathered);
  return sorted_by_group(gathered);
}

// One unshadowed spot light at `position` aimed along `direction`.
SortedLights one_spot(const glm::vec3& position, const glm::vec3& direction, float outer_cone, float range) {
  scene::SpotLight spot;
  spot.range = range;
  spot.outer_cone = outer_cone;
  spot.inner_cone = 0.8f * outer_cone;
  return one_light(spot, {position, scene::look_rotation(position, position + direction), glm::vec3(1.0f)});
}

// A wide spot light aimed down at a floor seen from above: a sphere around a floor's tile reaches
// below the floor, where the cone is wider than its pool of light, so tests of spheres alone list
// the spot two tiles and more beyond the pool. The tiles' slices of the view frustum against the
// cone's tangent planes list it only in tiles the pool lights or their neighbours.
TEST(SpotLightCulling, ListsASpotOnlyNearItsPoolOfLight) {
  const SortedLights lights = one_spot({1.0f, 2.0f, -1.0f}, {0, -1, 0}, 1.2f, 20.0f);
  ASSERT_EQ(lights.sorted.size(), 1u);
  const glm::vec3 eye(0.0f, 16.0f, 6.0f);
  const glm::mat4 view_projection =
      projection_matrix(scene::Camera{}, float(width) / float(height)) * view_matrix({eye, {0, 0, 0}});
  const std::vector<float> depth =
      depth_of(view_projection, eye, [&eye](uint32_t, uint32_t, const glm::vec3& ray) {
        return ray.y < 0.0f ? -eye.y / ray.y : 0.0f;  // a floor at y = 0
      });
  const std::vector<TileLightSets> reference =
      reference_light_tiles(depth, width, height, view_projection, lights.sorted);

  const LightTileGrid grid = LightTileGrid::of(width, height);
  std::vector<uint8_t> lit(grid.count(), 0);
  const glm::mat4 inverse = glm::inverse(view_projection);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      if (lights_point(lights.sorted[0], surface_at(inverse, x, y, depth[y * width + x])))
        lit[(y / tiles::LIGHT_TILE_SIZE) * grid.across + x / tiles::LIGHT_TILE_SIZE] = 1;
    }
  }
  uint32_t lit_tiles = 0, listed = 0, far_listed = 0;
  for (uint32_t tile = 0; tile < grid.count(); ++tile) {
    lit_tiles += lit[tile];
    if (reference[tile].may.empty()) continue;
    ++listed;
    const int tx = int(tile % grid.across), ty = int(tile / grid.across);
    bool near = false;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = tx + dx, ny = ty + dy;
        if (nx >= 0 && ny >= 0 && nx < int(grid.across) && ny < int(grid.count() / grid.across)) {
          near = near || lit[ny * grid.across + nx];
        }
      }
    }
    far_listed += !near;
  }
  EXPECT_GT(lit_tiles, 4u);
  EXPECT_GE(listed, lit_tiles);
  EXPECT_EQ(far_listed, 0u) << "of " << listed << " tiles listing the spot";
}

// Expects `lights`, one light that reaches none of scene_depth's surfaces with posts, to be in no
// tile's list, not even among the lights the CPU reference allows (`may`).
void expect_listed_nowhere_among_the_posts(const SortedLights& lights) {
  ASSERT_EQ(lights.sorted.size(), 1u);
  const glm::mat4 view_projection = origin_view_projection();
  const std::vector<TileLightSets> reference = reference_light_tiles(
      scene_depth(view_projection, true), width, height, view_projection, lights.sorted);
  for (uint32_t tile = 0; tile < reference.size(); ++tile) {
    EXPECT_TRUE(reference[tile].may.empty()) << "tile " << tile;
  }
}

// A narrow spot light between posts 6 m away and a wall 30 m away, aimed up where there is no
// ceiling: it lights no pixel. The tiles that see both a post and the wall have a slice of the
// view frustum from 6 to 30 m that the cone crosses; their depth slices with a surface are at
// either end, and the cone misses those.
TEST(SpotLightCulling, ASpotBetweenANearAndAFarSurfaceIsListedNowhere) {
  expect_listed_nowhere_among_the_posts(one_spot({0.5f, -1.0f, -15.0f}, {0, 1, 0}, 0.3f, 2.5f));
}

// A point light halfway between posts 6 m away and a wall 30 m away, above the floor and out of
// the posts' and the wall's reach: it lights no pixel. The tiles that see both a post and the wall
// have a slice of the view frustum that holds its sphere; their depth slices with a surface are
// at either end, beyond its range along the view direction.
TEST(PointLightCulling, APointLightBetweenANearAndAFarSurfaceIsListedNowhere) {
  scene::PointLight point;
  point.range = 2.5f;
  expect_listed_nowhere_among_the_posts(
      one_light(point, {{0.5f, 1.0f, -15.0f}, glm::quat(1, 0, 0, 0), glm::vec3(1.0f)}));
}

class LightTilesTest : public GpuTest {
 protected:
  // One culling of `lights` against `depth` on the device, read back.
  struct Culled {
    std::vector<uint32_t> entries;
    std::vector<glm::uvec2> ranges;
    std::vector<uint32_t> tiles_of_group;
    std::vector<glm::uvec4> commands;
    uint64_t dropped = 0;  // LightTilesPass::take_dropped_pairs
    uint64_t asked = 0;    // LightTilesPass::listed_pairs
    uint32_t cut = 0;      // LightTilesPass::tiles_cut
  };
  // Cullings of `lights` against `depth` on the device, `frames` one after another by one pass
  // whose pools hold at most `most_pool_entries` and `most_coarse_entries` (0: the device's
  // limit), each frame's pool as the pass sizes it (LightTilesPass::pool_entries), read back.
  std::vector<Culled> cull(const SortedLights& lights, LightCullingShape shape,
                           const std::vector<float>& depth, const glm::mat4& view_projection,
                           uint32_t frames = 1, uint64_t most_pool_entries = 0,
                           uint64_t most_coarse_entries = 0);
  void expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape shape, uint32_t behind = 0,
                                                       uint64_t most_coarse_entries = 0);
  // Each of the first `tiles` tiles' lists, its groups' one after another.
  static std::vector<std::vector<uint32_t>> listed_per_tile(const Culled& culled, uint32_t tiles) {
    std::vector<std::vector<uint32_t>> listed(tiles);
    for (uint32_t tile = 0; tile < tiles; ++tile) {
      for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
        const glm::uvec2 range = culled.ranges[tile * shadows::light_group_count + group];
        listed[tile].insert(listed[tile].end(), culled.entries.begin() + range.x,
                            culled.entries.begin() + range.x + range.y);
      }
    }
    return listed;
  }
};

// Both shapes of the culling, whatever the device would pick.
TEST_F(LightTilesTest, ListsMatchABruteForceCpuAssignment) {
  expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape::workgroup_per_tile);
}

TEST_F(LightTilesTest, ListsOfAnInvocationPerTileMatchABruteForceCpuAssignment) {
  expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape::thread_per_tile);
}

// A frame of fewer lights than the culling finds depth slices for (FEWEST_LIGHTS_SLICED) is
// listed as if every depth slice of a tile held a surface: an invocation per tile lists at least
// what a workgroup per tile lists with the slices, which ListsMatchABruteForceCpuAssignment holds
// to the CPU reference. Both list a tile's lights in order.
TEST_F(LightTilesTest, AnInvocationPerTileListsAFewLightsWhereverTheSlicedCullingDoes) {
  // Spots, point lights and the sun.
  const SortedLights lights = scattered_lights(0, int(tiles::FEWEST_LIGHTS_SLICED) - 2);
  ASSERT_LT(lights.sorted.size(), tiles::FEWEST_LIGHTS_SLICED);
  const glm::mat4 view_projection = origin_view_projection();
  const std::vector<float> depth = scene_depth(view_projection, true);
  const Culled sliced = cull(lights, LightCullingShape::workgroup_per_tile, depth, view_projection).front();
  const Culled few = cull(lights, LightCullingShape::thread_per_tile, depth, view_projection).front();
  const uint32_t tiles = LightTileGrid::of(width, height).count();
  const std::vector<std::vector<uint32_t>> with_slices = listed_per_tile(sliced, tiles);
  const std::vector<std::vector<uint32_t>> without = listed_per_tile(few, tiles);
  size_t pairs = 0;
  for (uint32_t tile = 0; tile < tiles; ++tile) {
    EXPECT_TRUE(std::includes(without[tile].begin(), without[tile].end(), with_slices[tile].begin(),
                              with_slices[tile].end()))
        << "tile " << tile;
    pairs += with_slices[tile].size();
  }
  EXPECT_GT(pairs, 100u) << "the lights reach many tiles";
}

// A coarse pool with no room for any coarse tile's list: each tile tests every light instead, and
// lists the same.
TEST_F(LightTilesTest, TilesWhoseCoarseListFoundNoRoomTestEveryLight) {
  expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape::workgroup_per_tile, 0, 1);
}

// More lights than the coarse pass keeps a bit for in shared memory in each of its two segments
// (2 x 131,072): it tests them again to write its lists, and lists the same.
TEST_F(LightTilesTest, MoreLightsThanTheCoarsePassKeepsBitsForAreListedAlike) {
  expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape::workgroup_per_tile, 262200);
}

// A crowd of point lights (300 unless a test asks for more) that reach everything on screen: how
// many (tile, light) pairs that asks of the pool, and each tile's lists as one list.
class CrowdTest : public LightTilesTest {
 protected:
  CrowdTest() { gather_crowd(300); }

  void gather_crowd(int size) {
    scene::Scene scene;
    for (int i = 0; i < size; ++i) {
      scene::PointLight point;
      point.range = 100.0f;
      // Within 20 units of the first, however many: every light reaches what the camera sees.
      scene::add_light(scene, point, {{0.0f, 0.0f, -10.0f - 0.01f * float(i % 2000)}},
                       scene::ShadowSettings{}, "crowd");
    }
    ecs::update_world_transforms(scene.world, 0);
    shadows::FrameLights gathered;
    shadows::gather_lights(scene.world, {glm::vec3(-20.0f), glm::vec3(20.0f)}, {false}, gathered);
    lights = sorted_by_group(gathered);
    view_projection = origin_view_projection();
    depth = scene_depth(view_projection);
    tiles_with_surfaces = 0;
    for (uint32_t tile = 0; tile < grid.count(); ++tile) {
      const uint32_t x0 = tile % grid.across * tiles::LIGHT_TILE_SIZE,
                     y0 = tile / grid.across * tiles::LIGHT_TILE_SIZE;
      bool surface = false;
      for (uint32_t y = y0; y < std::min(y0 + tiles::LIGHT_TILE_SIZE, height); ++y) {
        for (uint32_t x = x0; x < std::min(x0 + tiles::LIGHT_TILE_SIZE, width); ++x) {
          surface = surface || depth[y * width + x] != camera_far_depth;
        }
      }
      tiles_with_surfaces += surface;
    }
  }

  // No limit per tile: every tile lists the whole crowd, in order, in both shapes of the culling.
  void expect_every_tile_lists_the_crowd() {
    const uint32_t size = uint32_t(lights.sorted.size());
    ASSERT_GT(tiles_with_surfaces, 0u);
    for (const LightCullingShape shape :
         {LightCullingShape::workgroup_per_tile, LightCullingShape::thread_per_tile}) {
      SCOPED_TRACE(shape == LightCullingShape::thread_per_tile ? "an invocation per tile"
                                                               : "a workgroup per tile");
      const Culled culled = cull(lights, shape, depth, view_projection).front();
      EXPECT_EQ(culled.cut, 0u);
      EXPECT_EQ(culled.dropped, 0u);
      EXPECT_EQ(culled.asked, tiles_with_surfaces * size);
      uint64_t full_tiles = 0;
      for (const std::vector<uint32_t>& tile : listed_per_tile(culled, grid.count())) {
        if (tile.empty()) continue;
        ASSERT_EQ(tile.size(), size);
        for (uint32_t j = 0; j < tile.size(); ++j) ASSERT_EQ(tile[j], j);
        ++full_tiles;
      }
      EXPECT_EQ(full_tiles, tiles_with_surfaces);
    }
  }

  const LightTileGrid grid = LightTileGrid::of(width, height);
  SortedLights lights;
  glm::mat4 view_projection{1.0f};
  std::vector<float> depth;
  uint64_t tiles_with_surfaces = 0;
};

TEST_F(CrowdTest, EveryLightThatReachesATileIsListed) { expect_every_tile_lists_the_crowd(); }

// More lights than the GPU shape keeps of a tile's list in shared memory (2,048): the list is
// found again in chunks, whole and in order.
TEST_F(CrowdTest, ListsLongerThanAWorkgroupHoldsAreListedWhole) {
  gather_crowd(2100);
  expect_every_tile_lists_the_crowd();
}

// llvmpipe ends a shader invocation's loops once they have run 65,535 iterations in all (a guard
// against endless loops), and an invocation per tile tests each light twice, each test about two
// iterations (shaders/light_tiles_serial.comp): 15,000 lights in every tile are listed whole and
// in order all the same, and no tile counts as cut short. About 16,200 are (lavapipe, Debian 12).
TEST_F(CrowdTest, FifteenThousandLightsStayWithinACpuDriversLoopGuard) {
  gather_crowd(15000);
  expect_every_tile_lists_the_crowd();
}

// Beyond that, the tiles whose loops the guard ended are counted: their lists miss lights. Every
// other tile lists the crowd whole, which is every tile on a driver without the guard (Mesa 25's
// llvmpipe, Debian 13) and none on Debian 12's.
TEST_F(CrowdTest, TilesACpuDriversLoopGuardCutShortAreCounted) {
  gather_crowd(20000);
  const Culled culled = cull(lights, LightCullingShape::thread_per_tile, depth, view_projection).front();
  std::vector<uint32_t> crowd(lights.sorted.size());
  std::iota(crowd.begin(), crowd.end(), 0u);
  uint64_t whole_tiles = 0;
  for (const std::vector<uint32_t>& tile : listed_per_tile(culled, grid.count()))
    whole_tiles += tile == crowd;
  EXPECT_EQ(culled.cut + whole_tiles, tiles_with_surfaces);
}

// A pool at the device's limit, smaller than the lists: every frame lists what fits and counts
// the rest, in both shapes of the culling, each tile's list in light order.
TEST_F(CrowdTest, APoolAtItsLimitListsWhatFitsAndCountsTheRest) {
  const uint64_t wanted = tiles_with_surfaces * 300;
  constexpr uint64_t limit = 20000;
  ASSERT_GT(wanted, limit);
  for (const LightCullingShape shape :
       {LightCullingShape::workgroup_per_tile, LightCullingShape::thread_per_tile}) {
    for (const Culled& culled : cull(lights, shape, depth, view_projection, 2, limit)) {
      ASSERT_EQ(culled.entries.size(), limit);
      EXPECT_EQ(culled.dropped, wanted - limit);
      EXPECT_EQ(culled.asked, wanted) << "what the lists asked for, the dropped pairs included";
      uint64_t listed = 0;
      for (const std::vector<uint32_t>& tile : listed_per_tile(culled, grid.count())) {
        EXPECT_TRUE(std::is_sorted(tile.begin(), tile.end()));
        EXPECT_EQ(std::adjacent_find(tile.begin(), tile.end()), tile.end()) << "each light once";
        listed += tile.size();
      }
      EXPECT_EQ(listed, limit);
    }
  }
}

// The same with the crowd's intensities rising with their index, then falling: each tile keeps
// the brightest, the end of its list, then its start.
TEST_F(CrowdTest, APoolAtItsLimitLeavesOutTheLightsWorthLeast) {
  const uint64_t wanted = tiles_with_surfaces * 300;
  constexpr uint64_t limit = 20000;
  for (const bool rising : {true, false}) {
    for (size_t i = 0; i < lights.sorted.size(); ++i) {
      lights.sorted[i].color_intensity.a = 1.0f + float(rising ? i : 299 - i);
    }
    for (const LightCullingShape shape :
         {LightCullingShape::workgroup_per_tile, LightCullingShape::thread_per_tile}) {
      const Culled culled = cull(lights, shape, depth, view_projection, 1, limit).front();
      EXPECT_EQ(culled.dropped, wanted - limit);
      uint64_t listed = 0;
      for (const std::vector<uint32_t>& tile : listed_per_tile(culled, grid.count())) {
        const uint32_t first_kept = rising ? 300 - uint32_t(tile.size()) : 0;
        for (uint32_t j = 0; j < tile.size(); ++j) {
          ASSERT_EQ(tile[j], first_kept + j)
              << (rising ? "rising" : "falling") << ": the brightest, in order";
        }
        listed += tile.size();
      }
      EXPECT_EQ(listed, limit);
    }
  }
}

std::vector<LightTilesTest::Culled> LightTilesTest::cull(const SortedLights& lights, LightCullingShape shape,
                                                         const std::vector<float>& depth,
                                                         const glm::mat4& view_projection, uint32_t frames,
                                                         uint64_t most_pool_entries,
                                                         uint64_t most_coarse_entries) {
  const LightTileGrid grid = LightTileGrid::of(width, height);
  vk::Image depth_image(context, {{width, height},
                                  VK_FORMAT_D32_SFLOAT,
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  1,
                                  1,
                                  VK_IMAGE_VIEW_TYPE_2D,
                                  "test depth"});
  vk::Buffer records(context, {lights.sorted.size() * sizeof(shadows::GpuLight),
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::upload, "test lights"});
  std::memcpy(records.mapped(), lights.sorted.data(), records.size());
  vk::UploadBatch upload(context);
  upload.copy_to_image(depth_image, 1, std::as_bytes(std::span<const float>(depth)));
  upload.submit();
  vk::FrameRing ring(context);
  LightTilesPass pass(context, ring.frames_in_flight(), shape, false, most_pool_entries, most_coarse_entries);
  EXPECT_EQ(pass.shape(), shape);
  const uint32_t light_count = uint32_t(lights.sorted.size());
  std::vector<Culled> culled;
  for (uint32_t f = 0; f < frames; ++f) {
    const vk::Buffer tile_lights =
        readable(context, pass.pool_entries(grid, light_count) * sizeof(uint32_t), 0);
    const vk::Buffer tile_ranges = readable(context, LightTilesPass::ranges_bytes(grid), 0);
    const vk::Buffer group_tiles = readable(context, LightTilesPass::tiles_bytes(grid), 0);
    const vk::Buffer group_commands =
        readable(context, LightTilesPass::commands_bytes(), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);

    rg::RenderGraph graph;
    const rg::ResourceState sampled{rg::PipelineStage::all_commands, rg::Access::shader_sampled_read,
                                    rg::ImageLayout::read_only_optimal};
    const rg::ResourceState host_read{rg::PipelineStage::host, rg::Access::host_read,
                                      rg::ImageLayout::undefined};
    vk::ImportedResources imports;
    const rg::ImageHandle depth_handle =
        graph.import_image("depth", {width, height, rg::Format::d32_sfloat}, sampled, sampled);
    imports.bind(depth_handle, depth_image);
    const auto import = [&](const char* name, const vk::Buffer& buffer) {
      const rg::BufferHandle handle =
          graph.import_buffer(name, {buffer.size()}, rg::ResourceState{}, host_read);
      imports.bind(handle, buffer);
      return handle;
    };
    const LightTiles outputs{import("tile lights", tile_lights), import("tile ranges", tile_ranges),
                             import("group tiles", group_tiles), import("commands", group_commands)};
    vk::FrameSlot& frame = ring.begin_frame();
    EXPECT_EQ(pass.take_dropped_pairs(frame.slot), 0u) << "every frame before was read back";
    pass.add_to(graph, frame.slot, depth_handle, records, light_count, view_projection, &outputs);
    const rg::CompileResult compiled = rg::compile(graph);
    EXPECT_TRUE(compiled.ok());
    vk::GraphExecutor executor(context, ring.frames_in_flight());
    executor.execute(frame.cmd, frame.slot, frame.frame_number, graph, compiled.plan, imports);
    ring.submit();
    ring.wait_idle();
    const uint64_t dropped = pass.take_dropped_pairs(frame.slot);
    culled.push_back({contents<uint32_t>(tile_lights), contents<glm::uvec2>(tile_ranges),
                      contents<uint32_t>(group_tiles), contents<glm::uvec4>(group_commands), dropped,
                      pass.listed_pairs(), pass.tiles_cut()});
  }
  return culled;
}

void LightTilesTest::expect_lists_match_a_brute_force_cpu_assignment(LightCullingShape shape, uint32_t behind,
                                                                     uint64_t most_coarse_entries) {
  const SortedLights lights = scattered_lights(behind);
  const glm::mat4 view_projection = origin_view_projection();
  const std::vector<float> depth = scene_depth(view_projection, true);
  const LightTileGrid grid = LightTileGrid::of(width, height);
  const Culled culled = cull(lights, shape, depth, view_projection, 1, 0, most_coarse_entries).front();
  EXPECT_EQ(culled.dropped, 0u) << "the pool holds every list";
  const std::vector<uint32_t>& entries = culled.entries;
  const std::vector<glm::uvec2>& ranges = culled.ranges;
  const std::vector<uint32_t>& tiles_of_group = culled.tiles_of_group;
  const std::vector<glm::uvec4>& commands = culled.commands;
  const std::vector<TileLightSets> reference =
      reference_light_tiles(depth, width, height, view_projection, lights.sorted);
  ASSERT_EQ(reference.size(), grid.count());

  const uint32_t groups = shadows::light_group_count;
  size_t listed = 0, undecided = 0;
  for (uint32_t tile = 0; tile < grid.count(); ++tile) {
    std::vector<uint32_t> gpu;
    for (uint32_t group = 0; group < groups; ++group) {
      const glm::uvec2 range = ranges[tile * groups + group];
      for (uint32_t j = 0; j < range.y; ++j) {
        const uint32_t light = entries[range.x + j];
        // Each group's range holds lights of that group only.
        EXPECT_GE(light, lights.group_begin[group]);
        EXPECT_LT(light, lights.group_begin[group + 1]);
        gpu.push_back(light);
      }
    }
    EXPECT_TRUE(std::is_sorted(gpu.begin(), gpu.end()));
    const TileLightSets& cpu = reference[tile];
    EXPECT_TRUE(std::includes(gpu.begin(), gpu.end(), cpu.must.begin(), cpu.must.end())) << "tile " << tile;
    EXPECT_TRUE(std::includes(cpu.may.begin(), cpu.may.end(), gpu.begin(), gpu.end())) << "tile " << tile;
    listed += gpu.size();
    undecided += cpu.may.size() - cpu.must.size();
  }
  // No two lists, of two tiles or two groups, share an entry of the pool.
  std::vector<uint8_t> taken(entries.size(), 0);
  for (const glm::uvec2& range : ranges) {
    ASSERT_LE(uint64_t{range.x} + range.y, entries.size());
    for (uint32_t j = range.x; j < range.x + range.y; ++j) EXPECT_EQ(taken[j]++, 0) << "entry " << j;
  }
  // Every light that reaches a visible pixel is in that pixel's tile.
  const glm::mat4 inverse = glm::inverse(view_projection);
  size_t reached = 0;
  for (uint32_t y = 0; y < height; y += 3) {
    for (uint32_t x = 0; x < width; x += 3) {
      const float d = depth[y * width + x];
      if (d <= camera_far_depth) continue;
      const glm::vec3 point = surface_at(inverse, x, y, d);
      const uint32_t tile = (y / 16) * grid.across + x / 16;
      for (uint32_t light = 0; light < lights.sorted.size(); ++light) {
        if (!lights_point(lights.sorted[light], point)) continue;
        ++reached;
        const uint32_t group = std::upper_bound(lights.group_begin.begin(), lights.group_begin.end(), light) -
                               lights.group_begin.begin() - 1;
        const glm::uvec2 range = ranges[tile * groups + group];
        const auto first = entries.begin() + range.x;
        EXPECT_NE(std::find(first, first + range.y, light), first + range.y)
            << "light " << light << " reaches pixel (" << x << ", " << y << ") but tile " << tile
            << " drops it";
      }
    }
  }
  EXPECT_GT(reached, 1000u);
  // The scene is meant to exercise the culling: many listings, few lights on a tile's boundary.
  EXPECT_GT(listed, 200u);
  EXPECT_LT(undecided, listed / 50 + 1);
  // Each group's dispatch names exactly the tiles that have its lights, each once, the other slots
  // NO_TILE: on GPUs in tile order, a tile in its own slot; the sky corner has none.
  for (uint32_t group = 0; group < groups; ++group) {
    std::vector<uint32_t> with_lights;
    for (uint32_t tile = 0; tile < grid.count(); ++tile) {
      if (ranges[tile * groups + group].y > 0) with_lights.push_back(tile);
    }
    ASSERT_LE(commands[group].x, grid.count());
    std::vector<uint32_t> dispatched;
    for (uint32_t slot = 0; slot < commands[group].x; ++slot) {
      const uint32_t tile = tiles_of_group[group * grid.count() + slot];
      if (tile == tiles::NO_TILE) continue;
      if (shape == LightCullingShape::workgroup_per_tile) {
        EXPECT_EQ(tile, slot) << "group " << group;
      }
      dispatched.push_back(tile);
    }
    std::sort(dispatched.begin(), dispatched.end());
    EXPECT_EQ(dispatched, with_lights) << "group " << group;
    EXPECT_EQ(commands[group].y, 1u);
    EXPECT_EQ(commands[group].z, 1u);
  }
  EXPECT_EQ(ranges[0].y + ranges[1].y, 0u) << "the sky tile (0, 0) lists no lights";
}

}  // namespace
}  // namespace sg::test
