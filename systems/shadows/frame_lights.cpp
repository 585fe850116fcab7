#include "systems/shadows/frame_lights.h"

#include <algorithm>
#include <cstdio>

#include "systems/scene/lights.h"
#include "systems/scene/scene.h"

namespace sg::shadows {
namespace {

constexpr glm::vec4 unbounded_reach{0.0f, 0.0f, 0.0f, -1.0f};

uint32_t clamp_resolution(uint32_t requested, uint32_t limit) {
  return std::clamp(requested, min_shadow_resolution, limit);
}

// "shadow <name>", or "shadow <kind> <index>" for unnamed lights, into `out`, whose storage
// is reused from the last frame (thousands of lights would otherwise allocate thousands of
// strings a frame).
void name_view(const ecs::World& world, ecs::Entity entity, const char* kind, size_t index,
               std::string& out) {
  out.assign("shadow ");
  if (const scene::Name* name = world.try_get<scene::Name>(entity); name && !name->value.empty()) {
    out.append(name->value);
    return;
  }
  char number[24];
  std::snprintf(number, sizeof(number), " %zu", index);
  out.append(kind).append(number);
}

// The next view of `views`, reusing last frame's element (and its name's storage) when there is one.
template <class View>
View& next_view(std::vector<View>& views, size_t& count) {
  if (count == views.size()) views.emplace_back();
  return views[count++];
}

scene::ShadowSettings with_overrides(scene::ShadowSettings shadow, const LightOverrides& overrides) {
  if (overrides.algorithm) shadow.algorithm = *overrides.algorithm;
  shadow.casts_shadow = shadow.casts_shadow && overrides.shadows;
  return shadow;
}

uint64_t key_of(ecs::Entity entity) { return uint64_t{entity.generation} << 32 | entity.index; }

// Whether the light's transform, parameters or shadow settings were written since `since`.
template <class Light>
bool changed_since(const ecs::World& world, ecs::Entity entity, ecs::Tick since) {
  return std::max({world.change_tick<ecs::WorldTransform>(entity), world.change_tick<Light>(entity),
                   world.change_tick<scene::ShadowSettings>(entity)}) >= since;
}

// Every light of type Light, with a 2D map from view_of(light, transform) when it casts one.
template <class Light, class ViewOf, class ReachOf>
void gather_2d(const ecs::World& world, const LightOverrides& overrides, ecs::Tick since, const char* kind,
               ViewOf view_of, ReachOf reach_of, FrameLights& out, size_t& map_count) {
  world.query<const ecs::WorldTransform, const Light, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const Light& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = with_overrides(shadow, overrides);
        out.records.push_back(pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        const size_t index = map_count;
        ShadowMapView& map = next_view(out.maps, map_count);
        map.light = static_cast<uint32_t>(out.records.size() - 1);
        map.key = key_of(entity);
        map.requested_resolution = clamp_resolution(s.resolution, max_map_resolution);
        map.view = view_of(light, transform);
        map.reach = reach_of(light, transform);
        map.changed = changed_since<Light>(world, entity, since);
        name_view(world, entity, kind, index, map.name);
      });
}

ShadowKind shadow_kind(const GpuLight& record) {
  if (record.info.w == no_shadow_map) return ShadowKind::none;
  return record.info.x == static_cast<uint32_t>(GpuLightType::point) ? ShadowKind::cube : ShadowKind::map;
}

}  // namespace

void gather_lights(const ecs::World& world, const scene::Aabb& scene_bounds, const LightOverrides& overrides,
                   FrameLights& out) {
  const ecs::Tick since = out.gathered_at;
  out.gathered_at = world.tick();
  out.records.clear();
  size_t map_count = 0;
  size_t cube_count = 0;
  const scene::Aabb bounds =
      scene_bounds.empty() ? scene::Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : scene_bounds;
  const auto no_range = [](const auto&, const ecs::WorldTransform&) { return unbounded_reach; };

  gather_2d<scene::SpotLight>(
      world, overrides, since, "spot",
      [](const scene::SpotLight& light, const ecs::WorldTransform& transform) {
        return spot_light_view(scene::light_position(transform), scene::light_direction(transform),
                               light.outer_cone, light.range);
      },
      [](const scene::SpotLight& light, const ecs::WorldTransform& transform) {
        return glm::vec4(scene::light_position(transform), light.range);
      },
      out, map_count);
  gather_2d<scene::DirectionalLight>(
      world, overrides, since, "directional",
      [&](const scene::DirectionalLight&, const ecs::WorldTransform& transform) {
        return directional_light_view(scene::light_direction(transform), bounds);
      },
      no_range, out, map_count);
  gather_2d<scene::CylinderLight>(
      world, overrides, since, "cylinder",
      [&](const scene::CylinderLight& light, const ecs::WorldTransform& transform) {
        return cylinder_light_view(scene::light_position(transform), scene::light_direction(transform),
                                   light.outer_radius, bounds);
      },
      no_range, out, map_count);

  world.query<const ecs::WorldTransform, const scene::PointLight, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const scene::PointLight& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = with_overrides(shadow, overrides);
        out.records.push_back(pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        const glm::vec3 position = scene::light_position(transform);
        const size_t index = cube_count;
        ShadowCubeView& cube = next_view(out.cubes, cube_count);
        cube.light = static_cast<uint32_t>(out.records.size() - 1);
        cube.key = key_of(entity);
        cube.requested_resolution = clamp_resolution(s.resolution, max_cube_resolution);
        cube.views = point_light_cube(position, light.range);
        cube.position_far = glm::vec4(position, light.range);
        cube.changed = changed_since<scene::PointLight>(world, entity, since);
        name_view(world, entity, "point", index, cube.name);
      });
  out.maps.resize(map_count);
  out.cubes.resize(cube_count);
}

void sort_by_group(FrameLights& out) {
  FrameLights::Scratch& scratch = out.scratch;
  const auto group_of = [](const GpuLight& record) {
    return light_group(shadow_kind(record), static_cast<scene::ShadowAlgorithm>(record.info.z));
  };
  out.group_begin.fill(0);
  for (const GpuLight& record : out.records) ++out.group_begin[group_of(record) + 1];
  for (uint32_t g = 0; g < light_group_count; ++g) out.group_begin[g + 1] += out.group_begin[g];
  std::array<uint32_t, light_group_count + 1> cursor = out.group_begin;
  scratch.moved_to.resize(out.records.size());
  scratch.records.resize(out.records.size());
  for (size_t i = 0; i < out.records.size(); ++i) {
    scratch.moved_to[i] = cursor[group_of(out.records[i])]++;
    scratch.records[scratch.moved_to[i]] = out.records[i];
  }
  std::swap(out.records, scratch.records);
  for (ShadowMapView& map : out.maps) map.light = scratch.moved_to[map.light];
  for (ShadowCubeView& cube : out.cubes) cube.light = scratch.moved_to[cube.light];
}

}  // namespace sg::shadows
