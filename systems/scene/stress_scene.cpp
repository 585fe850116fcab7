// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/gtc/constants.hpp>

#include "ecs/transform_system.h"
#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/scene_queries.h"

namespace sg::scene {
namespace {

constexpr float cell_size = 4.0f;
constexpr std::uint32_t column_segments = 16;
constexpr std::uint64_t typical_cell_triangles = 170;  // column, table, chair, two crates

// splitmix64: tiny, and its sequence is fixed by the seed on every platform (the standard
// distributions are not specified bit-exactly across libraries).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float uniform(float low, float high) {
    return low + (high - low) * static_cast<float>(next() >> 40) * 0x1.0p-24f;
  }
  // Points drawn last coordinate first, the order GCC gives a constructor's arguments, which the
  // hall was built in when its figures were measured. Left to the compiler, clang (left to right)
  // built another hall from the same seed.
  glm::vec2 uniform(glm::vec2 low, glm::vec2 high) {
    const float y = uniform(low.y, high.y);
    return {uniform(low.x, high.x), y};
  }
  glm::vec3 uniform(glm::vec3 low, glm::vec3 high) {
    const float z = uniform(low.z, high.z);
    const float y = uniform(low.y, high.y);
    return {uniform(low.x, high.x), y, z};
  }

 private:
  std::uint64_t state_;
};

// Spreads round(fraction * count) selections evenly over indices 0..count-1.
bool selected(std::uint64_t index, float fraction) {
  return std::floor(static_cast<double>(index + 1) * fraction) >
         std::floor(static_cast<double>(index) * fraction);
}

struct Hall {
  Scene& scene;
  Random random;
  float moving_fraction;
  std::uint32_t box = 0;
  std::uint32_t column = 0;
  std::uint64_t triangles = 0;
  std::uint64_t crates = 0;

  ecs::Entity add(std::uint32_t mesh, glm::vec3 center, glm::vec3 size, float yaw, const Material& material) {
    triangles += triangle_count(scene.meshes.meshes[mesh]);
    return add_instance(scene, mesh, {center, glm::angleAxis(yaw, glm::vec3(0, 1, 0)), size}, material);
  }

  // One cell: a column at its corner, a table with a chair, and up to three crates.
  void furnish(glm::vec2 origin) {
    const Material stone{{0.55f, 0.55f, 0.6f, 1.0f}};
    const Material wood{{random.uniform(0.4f, 0.6f), 0.35f, 0.2f, 1.0f}, no_texture, 0.3f, 48.0f};
    add(column, {origin.x, 2.5f, origin.y}, {0.6f, 5.0f, 0.6f}, 0.0f, stone);
    const glm::vec2 table = origin + random.uniform(glm::vec2(1.5f), glm::vec2(2.5f));
    const float yaw = random.uniform(0.0f, glm::pi<float>());
    const glm::vec3 right(std::cos(yaw), 0.0f, -std::sin(yaw));
    const glm::vec3 forward(std::sin(yaw), 0.0f, std::cos(yaw));
    const glm::vec3 top(table.x, 0.75f, table.y);
    add(box, top, {1.2f, 0.06f, 0.8f}, yaw, wood);
    for (const float sx : {-1.0f, 1.0f}) {
      for (const float sz : {-1.0f, 1.0f}) {
        add(box, top + right * (0.55f * sx) + forward * (0.35f * sz) - glm::vec3(0, 0.39f, 0),
            {0.06f, 0.72f, 0.06f}, yaw, wood);
      }
    }
    const glm::vec3 seat = top + forward * 0.7f - glm::vec3(0, 0.3f, 0);
    add(box, seat, {0.45f, 0.05f, 0.45f}, yaw, wood);
    add(box, seat + forward * 0.22f + glm::vec3(0, 0.25f, 0), {0.45f, 0.5f, 0.04f}, yaw, wood);
    const int crate_count = static_cast<int>(random.next() % 4);
    for (int c = 0; c < crate_count; ++c) {
      const float size = random.uniform(0.3f, 0.7f);
      const glm::vec2 offset = random.uniform(glm::vec2(0.6f), glm::vec2(3.4f, 1.2f));
      const glm::vec3 at(origin.x + offset.x, size * 0.5f, origin.y + offset.y);
      const ecs::Entity crate = add(box, at, glm::vec3(size), random.uniform(0.0f, 1.5f), wood);
      if (selected(crates++, moving_fraction)) {
        scene.world.add<OrbitMotion>(crate, OrbitMotion{at, 0.4f, random.uniform(0.3f, 1.0f),
                                                        random.uniform(0.0f, glm::two_pi<float>())});
      }
    }
  }
};

}  // namespace

Scene build_stress_scene(const BuiltinSceneParams& params) {
  Scene scene;
  scene.name = "stress";
  Hall hall{scene, Random(params.seed), params.moving_fraction};
  hall.box = add_box_mesh(scene.meshes);
  hall.column = add_cylinder_mesh(scene.meshes, column_segments);

  const std::uint64_t estimated_cells = params.triangles / typical_cell_triangles + 1;
  const auto side = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(estimated_cells))));
  const float extent = static_cast<float>(side) * cell_size;
  hall.add(hall.box, {extent * 0.5f, -0.1f, extent * 0.5f}, {extent, 0.2f, extent}, 0.0f,
           Material{{0.6f, 0.6f, 0.58f, 1.0f}, no_texture, 0.1f, 16.0f});
  // Fill cells row by row until the target is met; with an underestimate the grid grows a row.
  for (std::uint32_t cell = 0; hall.triangles < params.triangles; ++cell) {
    hall.furnish({static_cast<float>(cell % side) * cell_size, static_cast<float>(cell / side) * cell_size});
  }

  Random& random = hall.random;
  const float spread = params.light_spread * extent;  // the side of the lights' square
  const float spread_x = (extent - spread) * 0.5f;
  const std::uint32_t light_count = params.point_lights + params.spot_lights;
  for (std::uint32_t i = 0; i < light_count; ++i) {
    ShadowSettings shadow;
    shadow.algorithm = all_shadow_algorithms[i % std::size(all_shadow_algorithms)];
    shadow.resolution = 512;
    const glm::vec3 color = random.uniform(glm::vec3(0.7f), glm::vec3(1.0f));
    const glm::vec3 position =
        random.uniform(glm::vec3(spread_x, 2.5f, 0.0f), glm::vec3(spread_x + spread, 4.5f, spread));
    ecs::Entity light;
    if (i < params.point_lights) {
      light = add_light(scene, PointLight{color, 1.0f, 2.5f * cell_size}, {position}, shadow,
                        "point " + std::to_string(i));
    } else {
      const glm::vec2 aim = random.uniform(glm::vec2(-2.0f), glm::vec2(2.0f));
      const glm::vec3 target = position + glm::vec3(aim.x, -position.y, aim.y);
      const float outer = random.uniform(0.4f, 0.8f);
      light = add_light(scene, SpotLight{color, 1.5f, 3.0f * cell_size, 0.8f * outer, outer},
                        {position, look_rotation(position, target), glm::vec3(1.0f)}, shadow,
                        "spot " + std::to_string(i - params.point_lights));
    }
    if (selected(i, params.moving_fraction)) {
      scene.world.add<OrbitMotion>(
          light, OrbitMotion{position, random.uniform(1.0f, 3.0f), random.uniform(0.2f, 0.8f),
                             random.uniform(0.0f, glm::two_pi<float>())});
    }
  }
  const glm::vec3 center(extent * 0.5f, 0.0f, extent * 0.5f);
  add_light(scene, DirectionalLight{{1.0f, 0.97f, 0.9f}, 0.3f},
            {center, look_rotation(center, center + glm::vec3(-0.3f, -1.0f, -0.4f)), glm::vec3(1.0f)},
            ShadowSettings{}, "sun");

  ecs::update_world_transforms(scene.world, 0);
  // "overview" frames the whole hall from above; "street" stands at eye height inside it, 2.5
  // cells from its near edge, looking 12.5 cells along it: there the lights are near and many
  // reach each pixel, the case to measure besides the overview (--camera street).
  const ecs::Entity overview =
      add_camera(scene.world, frame_bounds(scene_bounds(scene), Camera{}.yfov, 16.0f / 9.0f));
  scene.world.add<Name>(overview, Name{"overview"});
  const float street_z = 2.5f * cell_size;
  const ecs::Entity street = add_camera(
      scene.world,
      {{center.x, 1.7f, street_z}, {center.x, 1.5f, std::min(extent, street_z + 12.5f * cell_size)}});
  scene.world.add<Name>(street, Name{"street"});
  return scene;
}

}  // namespace sg::scene
