#include "systems/shadows/frame_lights.h"

#include <algorithm>

#include "systems/scene/lights.h"
#include "systems/scene/scene.h"

namespace sg::shadows {
namespace {

constexpr glm::vec4 unbounded_reach{0.0f, 0.0f, 0.0f, -1.0f};

uint32_t clamp_resolution(uint32_t requested, uint32_t limit) {
  return std::clamp(requested, min_shadow_resolution, limit);
}

std::string light_name(const ecs::World& world, ecs::Entity entity, const char* kind, size_t index) {
  if (const scene::Name* name = world.try_get<scene::Name>(entity); name && !name->value.empty()) {
    return name->value;
  }
  return std::string(kind) + " " + std::to_string(index);
}

scene::ShadowSettings with_overrides(scene::ShadowSettings shadow, const LightOverrides& overrides) {
  if (overrides.algorithm) shadow.algorithm = *overrides.algorithm;
  shadow.casts_shadow = shadow.casts_shadow && overrides.shadows;
  return shadow;
}

// Every light of type Light, with a 2D map from view_of(light, transform) when it casts one.
template <class Light, class ViewOf, class ReachOf>
void gather_2d(const ecs::World& world, const LightOverrides& overrides, const char* kind, ViewOf view_of,
               ReachOf reach_of, FrameLights& out) {
  world.query<const ecs::WorldTransform, const Light, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const Light& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = with_overrides(shadow, overrides);
        out.records.push_back(pack_light(light, transform, s));
        out.scratch.groups.push_back(
            light_group(s.casts_shadow ? ShadowKind::map : ShadowKind::none, s.algorithm));
        if (!s.casts_shadow) return;
        const auto layer = static_cast<uint32_t>(out.maps.size());
        out.maps.push_back({static_cast<uint32_t>(out.records.size() - 1), layer,
                            clamp_resolution(s.resolution, max_map_resolution), view_of(light, transform),
                            reach_of(light, transform), "shadow " + light_name(world, entity, kind, layer)});
        out.map_size = std::max(out.map_size, out.maps.back().resolution);
      });
}

// Orders the records by group (stably, so lights keep the world's order within a group) and
// points the views at their records' new places.
void sort_by_group(FrameLights& out) {
  FrameLights::Scratch& scratch = out.scratch;
  out.group_begin.fill(0);
  for (const uint32_t group : scratch.groups) ++out.group_begin[group + 1];
  for (uint32_t g = 0; g < light_group_count; ++g) out.group_begin[g + 1] += out.group_begin[g];
  std::array<uint32_t, light_group_count + 1> cursor = out.group_begin;
  scratch.moved_to.resize(out.records.size());
  scratch.records.resize(out.records.size());
  for (size_t i = 0; i < out.records.size(); ++i) {
    scratch.moved_to[i] = cursor[scratch.groups[i]]++;
    scratch.records[scratch.moved_to[i]] = out.records[i];
  }
  std::swap(out.records, scratch.records);
  for (ShadowMapView& map : out.maps) map.light = scratch.moved_to[map.light];
  for (ShadowCubeView& cube : out.cubes) cube.light = scratch.moved_to[cube.light];
}

}  // namespace

void gather_lights(const ecs::World& world, const scene::Aabb& scene_bounds, const LightOverrides& overrides,
                   FrameLights& out) {
  out.records.clear();
  out.scratch.groups.clear();
  out.maps.clear();
  out.cubes.clear();
  out.map_size = min_shadow_resolution;
  out.cube_size = min_shadow_resolution;
  const scene::Aabb bounds =
      scene_bounds.empty() ? scene::Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : scene_bounds;
  const auto no_range = [](const auto&, const ecs::WorldTransform&) { return unbounded_reach; };

  gather_2d<scene::SpotLight>(
      world, overrides, "spot",
      [](const scene::SpotLight& light, const ecs::WorldTransform& transform) {
        return spot_light_view(scene::light_position(transform), scene::light_direction(transform),
                               light.outer_cone, light.range);
      },
      [](const scene::SpotLight& light, const ecs::WorldTransform& transform) {
        return glm::vec4(scene::light_position(transform), light.range);
      },
      out);
  gather_2d<scene::DirectionalLight>(
      world, overrides, "directional",
      [&](const scene::DirectionalLight&, const ecs::WorldTransform& transform) {
        return directional_light_view(scene::light_direction(transform), bounds);
      },
      no_range, out);
  gather_2d<scene::CylinderLight>(
      world, overrides, "cylinder",
      [&](const scene::CylinderLight& light, const ecs::WorldTransform& transform) {
        return cylinder_light_view(scene::light_position(transform), scene::light_direction(transform),
                                   light.outer_radius, bounds);
      },
      no_range, out);

  world.query<const ecs::WorldTransform, const scene::PointLight, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const scene::PointLight& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = with_overrides(shadow, overrides);
        out.records.push_back(pack_light(light, transform, s));
        out.scratch.groups.push_back(
            light_group(s.casts_shadow ? ShadowKind::cube : ShadowKind::none, s.algorithm));
        if (!s.casts_shadow) return;
        const glm::vec3 position = scene::light_position(transform);
        const auto cube = static_cast<uint32_t>(out.cubes.size());
        out.cubes.push_back({static_cast<uint32_t>(out.records.size() - 1), cube,
                             clamp_resolution(s.resolution, max_cube_resolution),
                             point_light_cube(position, light.range), glm::vec4(position, light.range),
                             "shadow " + light_name(world, entity, "point", cube)});
        out.cube_size = std::max(out.cube_size, out.cubes.back().requested_resolution);
      });
  sort_by_group(out);
}

ShadowStorageSize needed_storage(const FrameLights& lights) {
  return {{lights.map_size, static_cast<uint32_t>(lights.maps.size())},
          {lights.cube_size, static_cast<uint32_t>(lights.cubes.size())}};
}

void place_shadow_maps(FrameLights& lights, uint32_t layer_size, uint32_t face_size) {
  for (const ShadowMapView& map : lights.maps) {
    const float scale = float(map.resolution) / float(layer_size);
    set_shadow_map(lights.records[map.light], map.layer, glm::vec4(0.0f, 0.0f, scale, scale), map.resolution,
                   map.view);
  }
  for (const ShadowCubeView& cube : lights.cubes) {
    set_shadow_cube(lights.records[cube.light], cube.cube, face_size, cube.views);
  }
}

}  // namespace sg::shadows
