#include "systems/frame_lights.h"

#include <algorithm>

#include "systems/scene/lights.h"
#include "systems/scene/scene.h"

namespace sg {
namespace {

uint32_t clamp_resolution(uint32_t requested, uint32_t limit) {
  return std::clamp(requested, min_shadow_resolution, limit);
}

std::string light_name(ecs::World& world, ecs::Entity entity, const char* kind, size_t index) {
  if (const scene::Name* name = world.try_get<scene::Name>(entity); name && !name->value.empty()) {
    return name->value;
  }
  return std::string(kind) + " " + std::to_string(index);
}

}  // namespace

void gather_lights(ecs::World& world, const scene::Aabb& scene_bounds,
                   const LightOverrides& overrides, FrameLights& out) {
  out.records.clear();
  out.maps.clear();
  out.cubes.clear();
  const scene::Aabb bounds = scene_bounds.empty() ? scene::Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)}
                                                  : scene_bounds;
  const auto settings = [&](const scene::ShadowSettings& shadow) {
    scene::ShadowSettings s = shadow;
    if (overrides.algorithm) s.algorithm = *overrides.algorithm;
    s.casts_shadow = s.casts_shadow && overrides.shadows;
    return s;
  };
  // 2D maps get their layer now and their uv region once every request is known.
  const auto add_map = [&](ecs::Entity entity, const char* kind, const scene::ShadowSettings& s,
                           const shadows::LightView& view) {
    const auto layer = static_cast<uint32_t>(out.maps.size());
    out.maps.push_back({static_cast<uint32_t>(out.records.size() - 1), layer,
                        clamp_resolution(s.resolution, max_atlas_resolution), view,
                        "shadow " + light_name(world, entity, kind, layer)});
  };

  world.query<const ecs::WorldTransform, const scene::SpotLight, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const scene::SpotLight& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = settings(shadow);
        out.records.push_back(shadows::pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        add_map(entity, "spot", s,
                shadows::spot_light_view(scene::light_position(transform),
                                         scene::light_direction(transform), light.outer_cone,
                                         light.range));
      });
  world.query<const ecs::WorldTransform, const scene::DirectionalLight, const scene::ShadowSettings>()
      .for_each([&](ecs::Entity entity, const ecs::WorldTransform& transform,
                    const scene::DirectionalLight& light, const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = settings(shadow);
        out.records.push_back(shadows::pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        add_map(entity, "directional", s,
                shadows::directional_light_view(scene::light_direction(transform), bounds));
      });
  world.query<const ecs::WorldTransform, const scene::CylinderLight, const scene::ShadowSettings>()
      .for_each([&](ecs::Entity entity, const ecs::WorldTransform& transform,
                    const scene::CylinderLight& light, const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = settings(shadow);
        out.records.push_back(shadows::pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        add_map(entity, "cylinder", s,
                shadows::cylinder_light_view(scene::light_position(transform),
                                             scene::light_direction(transform), light.outer_radius,
                                             bounds));
      });

  out.map_size = min_shadow_resolution;
  for (const ShadowMapView& map : out.maps) out.map_size = std::max(out.map_size, map.resolution);
  for (const ShadowMapView& map : out.maps) {
    const float scale = float(map.resolution) / float(out.map_size);
    shadows::set_shadow_map(out.records[map.light], map.layer, glm::vec4(0.0f, 0.0f, scale, scale),
                            map.resolution, map.view);
  }

  world.query<const ecs::WorldTransform, const scene::PointLight, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& transform, const scene::PointLight& light,
          const scene::ShadowSettings& shadow) {
        const scene::ShadowSettings s = settings(shadow);
        out.records.push_back(shadows::pack_light(light, transform, s));
        if (!s.casts_shadow) return;
        const glm::vec3 position = scene::light_position(transform);
        const auto cube = static_cast<uint32_t>(out.cubes.size());
        out.cubes.push_back({static_cast<uint32_t>(out.records.size() - 1), cube,
                             clamp_resolution(s.resolution, max_cube_resolution),
                             shadows::point_light_cube(position, light.range),
                             glm::vec4(position, light.range),
                             "shadow " + light_name(world, entity, "point", cube)});
      });
  out.cube_size = min_shadow_resolution;
  for (const ShadowCubeView& cube : out.cubes) {
    out.cube_size = std::max(out.cube_size, cube.requested_resolution);
  }
  for (const ShadowCubeView& cube : out.cubes) {
    shadows::set_shadow_cube(out.records[cube.light], cube.cube, out.cube_size, cube.views);
  }
}

}  // namespace sg
