// SPDX-License-Identifier: MIT
#include "systems/shadows/frame_lights.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

#include "ecs/query.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene.h"

namespace sg::shadows {
namespace {

constexpr glm::vec4 unbounded_reach{0.0f, 0.0f, 0.0f, -1.0f};

// What maps are fitted around when the scene has no drawables.
scene::Aabb or_unit_box(const scene::Aabb& bounds) {
  return bounds.empty() ? scene::Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : bounds;
}

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

scene::ShadowSettings with_overrides(scene::ShadowSettings shadow, const LightOverrides& overrides) {
  shadow.casts_shadow = shadow.casts_shadow && overrides.shadows;
  return shadow;
}

// Whether the light's map must be drawn again for what was written since `since`: its transform,
// parameters or shadow settings; an on_demand light's shadow settings only (a request writes them).
template <class Light>
bool changed_since(const ecs::World& world, ecs::Entity entity, ecs::Tick since, scene::ShadowUpdate update) {
  const ecs::Tick settings = world.change_tick<scene::ShadowSettings>(entity);
  if (update == scene::ShadowUpdate::on_demand) return settings >= since;
  return std::max({world.change_tick<ecs::WorldTransform>(entity), world.change_tick<Light>(entity),
                   settings}) >= since;
}

// How many views a light gets: a directional light one per cascade, others one.
template <class Light>
uint32_t views_of(const scene::ShadowSettings& shadow) {
  if constexpr (std::is_same_v<Light, scene::DirectionalLight>) {
    return std::clamp<uint32_t>(shadow.cascades, 1, max_cascades);
  }
  return 1;
}

// Every light of the frame, in the order the records take: spot, directional, cylinder, point
// lights, each in the world's order. A shadowed light's `view` indexes maps (or cubes); a
// cascaded one's cascades follow `cascades`.
template <class Light>
void collect(const ecs::World& world, const LightOverrides& overrides, GatheredLight::Kind kind,
             std::vector<GatheredLight>& gathered, uint32_t& views, uint32_t& cascades) {
  world.query<const ecs::WorldTransform, const Light, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform&, const Light&, const scene::ShadowSettings& shadow) {
        const bool shadowed = with_overrides(shadow, overrides).casts_shadow;
        GatheredLight light{entity, kind, shadowed, shadowed ? views : 0u};
        const uint32_t count = shadowed ? views_of<Light>(shadow) : 0u;
        views += count;
        if (count > 1) {
          light.cascades = count;
          light.first_cascade = cascades;
          cascades += count;
        }
        gathered.push_back(light);
      });
}

LightLayout light_layout(const ecs::World& world) {
  return {world.layout_stamp<ecs::WorldTransform>(),  world.layout_stamp<scene::ShadowSettings>(),
          world.layout_stamp<scene::SpotLight>(),     world.layout_stamp<scene::DirectionalLight>(),
          world.layout_stamp<scene::CylinderLight>(), world.layout_stamp<scene::PointLight>()};
}

// Record `index` and, for a shadowed light, its view, from the entity's components.
template <class Light>
void fill_2d(const ecs::World& world, const LightOverrides& overrides, ecs::Tick since,
             const scene::Aabb& bounds, const GatheredLight& light, uint32_t index, FrameLights& out) {
  const ecs::WorldTransform& transform = *world.try_get<ecs::WorldTransform>(light.entity);
  const Light& parameters = *world.try_get<Light>(light.entity);
  const scene::ShadowSettings s =
      with_overrides(*world.try_get<scene::ShadowSettings>(light.entity), overrides);
  out.records[index] = pack_light(parameters, transform, s);
  if (!light.shadowed) return;
  ShadowMapView& map = out.maps[light.view];
  map.light = index;
  map.key = light_key(light.entity);
  map.requested_resolution = clamp_resolution(s.resolution, max_map_resolution);
  map.cascade = no_cascade;
  map.needed = true;
  map.update = s.update;
  map.priority = s.priority;
  map.caster_mask = s.caster_mask;
  const glm::vec3 position = scene::light_position(transform);
  const glm::vec3 direction = scene::light_direction(transform);
  if constexpr (std::is_same_v<Light, scene::SpotLight>) {
    map.view = spot_light_view(position, direction, parameters.outer_cone, parameters.range);
    map.reach = glm::vec4(position, parameters.range);
    name_view(world, light.entity, "spot", light.view, map.name);
  } else if constexpr (std::is_same_v<Light, scene::DirectionalLight>) {
    map.reach = unbounded_reach;
    name_view(world, light.entity, "directional", light.view, map.name);
    if (light.cascades > 0) {
      // Cascade views take their LightViews from place_cascades, which compares them with these.
      out.records[index].shape = glm::vec4(float(out.records.size() + light.first_cascade), 0.0f, 0.0f, 0.0f);
      const bool changed = changed_since<Light>(world, light.entity, since, s.update);
      for (uint32_t k = light.cascades; k-- > 0;) {  // the first last: the others copy its name
        ShadowMapView& cascade = out.maps[light.view + k];
        if (k > 0) cascade.name = map.name;
        cascade.light = index;
        cascade.key = cascade_key(light.entity, k);
        cascade.requested_resolution = map.requested_resolution;
        cascade.reach = unbounded_reach;
        cascade.cascade = light.first_cascade + k;
        cascade.changed = changed;
        cascade.update = s.update;
        cascade.priority = s.priority;
        cascade.caster_mask = s.caster_mask;
        cascade.name.append(" cascade ").append(std::to_string(k + 1));
      }
      return;
    }
    map.view = directional_light_view(direction, bounds);
  } else {
    map.view = cylinder_light_view(position, direction, parameters.outer_radius, bounds);
    map.reach = unbounded_reach;
    name_view(world, light.entity, "cylinder", light.view, map.name);
  }
  map.changed = changed_since<Light>(world, light.entity, since, s.update);
}

void fill_point(const ecs::World& world, const LightOverrides& overrides, ecs::Tick since,
                const GatheredLight& light, uint32_t index, FrameLights& out) {
  const ecs::WorldTransform& transform = *world.try_get<ecs::WorldTransform>(light.entity);
  const scene::PointLight& parameters = *world.try_get<scene::PointLight>(light.entity);
  const scene::ShadowSettings s =
      with_overrides(*world.try_get<scene::ShadowSettings>(light.entity), overrides);
  out.records[index] = pack_light(parameters, transform, s);
  if (!light.shadowed) return;
  const glm::vec3 position = scene::light_position(transform);
  ShadowCubeView& cube = out.cubes[light.view];
  cube.light = index;
  cube.key = light_key(light.entity);
  cube.requested_resolution = clamp_resolution(s.resolution, max_cube_resolution);
  cube.position_far = glm::vec4(position, parameters.range);
  cube.changed = changed_since<scene::PointLight>(world, light.entity, since, s.update);
  cube.update = s.update;
  cube.priority = s.priority;
  cube.caster_mask = s.caster_mask;
  name_view(world, light.entity, "point", light.view, cube.name);
}

// Marks in scratch.written the gathered lights whose `T` was written at or after `since` (any
// write, whatever the light's update: its record follows it). Costs the writes, not the lights;
// on the pool, as with every light moving they are 100,000 lookups (each light its own place).
template <class T>
void mark_written(const ecs::World& world, ecs::Tick since, FrameLights::Scratch& scratch,
                  jobs::ThreadPool* pool) {
  world.query<const T>().template changed_since<T>(since - 1).for_each_parallel(
      pool, [&](ecs::Entity entity, const T&) {
        if (entity.index < scratch.place_of_entity.size()) {
          const uint32_t place = scratch.place_of_entity[entity.index];
          if (place != ~0u) scratch.written[place] = 1;
        }
      });
}

ShadowKind shadow_kind(const GpuLight& record) {
  if (record.info.w == no_shadow_map) return ShadowKind::none;
  return record.info.x == static_cast<uint32_t>(GpuLightType::point) ? ShadowKind::cube : ShadowKind::map;
}

}  // namespace

uint64_t light_key(ecs::Entity entity) { return ecs::entity_key(entity); }

uint64_t cascade_key(ecs::Entity entity, uint32_t cascade) {
  return ecs::entity_key(entity) | uint64_t{cascade + 1} << cascade_key_shift;
}

uint32_t shadowed_light_count(const FrameLights& lights) {
  // Every cascaded light has a first cascade (number 1); views that are no cascade have 0.
  const auto first_view = [](const ShadowMapView& map) { return view_cascade_number(map.key) <= 1; };
  return static_cast<uint32_t>(lights.cubes.size() + std::ranges::count_if(lights.maps, first_view));
}

void gather_lights(const ecs::World& world, const scene::Aabb& scene_bounds, const LightOverrides& overrides,
                   FrameLights& out, jobs::ThreadPool* pool) {
  const ecs::Tick since = out.gathered_at;
  out.gathered_at = world.tick();
  const scene::Aabb bounds = or_unit_box(scene_bounds);

  // The order and places first, on this thread; then each light's record and view, which are
  // independent (packing, view matrices, change ticks, names), in chunks on the pool. The list
  // is the last gather's when the pools it is read from are as they were and no light's shadow
  // settings were written since: listing 100,000 lights and comparing the list with the last
  // took 3.4 ms a frame on one thread of an H200 host (2026-12-03).
  FrameLights::Scratch& scratch = out.scratch;
  const LightLayout layout = light_layout(world);
  const bool same_list =
      since > 0 && layout == scratch.last_layout && overrides == scratch.last_overrides &&
      world.query<const scene::ShadowSettings>().changed_since<scene::ShadowSettings>(since - 1).count() == 0;
  scratch.last_layout = layout;
  if (!same_list) {
    std::vector<GatheredLight>& listed = scratch.gathered;
    listed.clear();
    GatheredViews& views = scratch.views;
    views = {};
    collect<scene::SpotLight>(world, overrides, GatheredLight::spot, listed, views.maps, views.cascades);
    collect<scene::DirectionalLight>(world, overrides, GatheredLight::directional, listed, views.maps,
                                     views.cascades);
    collect<scene::CylinderLight>(world, overrides, GatheredLight::cylinder, listed, views.maps,
                                  views.cascades);
    collect<scene::PointLight>(world, overrides, GatheredLight::point, listed, views.cubes, views.cascades);
  }
  // The list this gather fills from: last_gathered from here on.
  const bool same_lights =
      same_list || (scratch.gathered == scratch.last_gathered && overrides == scratch.last_overrides);
  if (!same_list) std::swap(scratch.last_gathered, scratch.gathered);  // gathered is refilled next time
  const std::vector<GatheredLight>& gathered = scratch.last_gathered;
  // A spot or point light (directional and cylinder views follow the scene's bounds) none of
  // whose components was written since, and that has a Name as it had then, keeps its view and
  // record. The writes are found from the pools' change ticks, not light by light: with four
  // ticks and a name looked up for each of 100,000 lights (5% moving), gathering took 5.7 ms on
  // one thread of the 2-core VM against 4.5 (2026-12-04). The transforms' writes include every
  // moving mesh's: with 8 lights among the stress scene's crates, all moving, gathering took 0.01
  // ms more. Names added or removed anywhere send every light to a look at its own.
  const uint64_t names_layout = world.layout_stamp<scene::Name>();
  const bool same_names = names_layout == scratch.last_names_layout;
  scratch.last_names_layout = names_layout;
  if (!same_list) {
    scratch.place_of_entity.clear();
    for (uint32_t i = 0; i < gathered.size(); ++i) {
      const uint32_t index = gathered[i].entity.index;
      if (index >= scratch.place_of_entity.size()) scratch.place_of_entity.resize(size_t{index} + 1, ~0u);
      scratch.place_of_entity[index] = i;
    }
  }
  scratch.written.assign(gathered.size(), 0);
  if (same_lights) {
    mark_written<ecs::WorldTransform>(world, since, scratch, pool);
    mark_written<scene::SpotLight>(world, since, scratch, pool);
    mark_written<scene::PointLight>(world, since, scratch, pool);
    mark_written<scene::ShadowSettings>(world, since, scratch, pool);
    mark_written<scene::Name>(world, since, scratch, pool);
  }
  const auto kept = [&](size_t i) {
    const GatheredLight& light = gathered[i];
    if (!same_lights || scratch.written[i] != 0 ||
        (light.kind != GatheredLight::spot && light.kind != GatheredLight::point)) {
      return false;
    }
    return same_names || (world.try_get<scene::Name>(light.entity) != nullptr) == (scratch.named[i] != 0);
  };
  out.records.resize(gathered.size());
  out.maps.resize(scratch.views.maps);  // shrinking keeps the survivors' name storage for reuse
  out.cubes.resize(scratch.views.cubes);
  out.cascades.resize(scratch.views.cascades);
  if (!same_list) {
    scratch.cascaded.clear();
    for (uint32_t i = 0; i < gathered.size(); ++i) {
      if (gathered[i].cascades > 0) scratch.cascaded.push_back({i, gathered[i].view, gathered[i].cascades});
    }
  }
  out.cascaded = scratch.cascaded;
  out.refilled.resize(gathered.size());
  scratch.named.resize(gathered.size());

  // Pieces of 64 lights: a light's views and record take about half a microsecond, a kept one
  // a tenth of that. Pieces of 16 balanced a thousand lights no better on an H200 host, and the
  // pieces' neighbouring bytes of `named` share cache lines.
  jobs::run_in_pieces(pool, gathered.size(), 64, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const auto index = static_cast<uint32_t>(i);
      const GatheredLight& light = gathered[i];
      out.refilled[i] = kept(i) ? 0 : 1;
      if (out.refilled[i] == 0) {
        // Of what gathering sets, `changed` may be stale; the record (with the shadow fields the
        // schedule gave it) and the view's other fields are as they were left (the schedule's
        // moving-caster draws put back the view the light has anyway, unchanged since its map
        // was drawn whole).
        const auto keep = [index](auto& view) {
          view.light = index;
          view.changed = false;
        };
        if (light.shadowed && light.kind == GatheredLight::point) keep(out.cubes[light.view]);
        if (light.shadowed && light.kind != GatheredLight::point) keep(out.maps[light.view]);
        continue;
      }
      scratch.named[i] = world.try_get<scene::Name>(light.entity) != nullptr ? 1 : 0;
      switch (gathered[i].kind) {
        case GatheredLight::spot:
          fill_2d<scene::SpotLight>(world, overrides, since, bounds, gathered[i], index, out);
          break;
        case GatheredLight::directional:
          fill_2d<scene::DirectionalLight>(world, overrides, since, bounds, gathered[i], index, out);
          break;
        case GatheredLight::cylinder:
          fill_2d<scene::CylinderLight>(world, overrides, since, bounds, gathered[i], index, out);
          break;
        case GatheredLight::point: fill_point(world, overrides, since, gathered[i], index, out); break;
      }
    }
  });
  scratch.last_overrides = overrides;
}

void place_cascades(FrameLights& lights, const CascadeCamera& camera, const scene::Aabb& scene_bounds) {
  const scene::Aabb bounds = or_unit_box(scene_bounds);
  for (const FrameLights::CascadedLight& light : lights.cascaded) {
    GpuLight& record = lights.records[light.record];
    const CascadeFit fit = fit_cascades(glm::vec3(record.direction_type), bounds, camera, light.views);
    record.shape.y = float(fit.count);
    for (uint32_t k = 0; k < light.views; ++k) {
      ShadowMapView& map = lights.maps[light.first_view + k];
      map.needed = k < fit.count;
      if (!map.needed) continue;
      // An on_demand cascade keeps its map where it was drawn until asked (sampled with that view).
      map.changed = map.changed || (map.update != scene::ShadowUpdate::on_demand && fit.views[k] != map.view);
      map.view = fit.views[k];
    }
  }
}

void sort_by_group(FrameLights& out, std::span<GpuLight> sorted, jobs::ThreadPool* pool,
                   SortedChanges changes) {
  FrameLights::Scratch& scratch = out.scratch;
  const auto group_of = [](const GpuLight& record) {
    return light_group(shadow_kind(record), algorithm_of(record));
  };
  // A counting sort in two passes over pieces of records on the pool: each piece counts its
  // records' groups, then, from the counts of the pieces before it, puts each record (208 bytes)
  // in its place. On one thread the sort took 0.05 ms with 1,024 lights and 0.14 with 4,096 (an
  // H200 host, 2026-12-01). Pieces of 128 records (26 KiB) keep a thousand lights on eight threads.
  constexpr size_t piece = 128;
  const size_t count = out.records.size();
  assert(sorted.size() == count && (changes.changed_at.empty() || changes.changed_at.size() == count));
  const size_t pieces = jobs::piece_count(count, piece);
  out.sorted_place.resize(count);  // each record's group, then its place
  scratch.piece_groups.assign(pieces * light_group_count, 0);
  scratch.piece_types.assign(pieces * light_group_count, 0);
  scratch.piece_contact.assign(pieces * light_group_count, 0);
  jobs::run_in_pieces(pool, count, piece, [&](size_t begin, size_t end) {
    uint32_t* groups = &scratch.piece_groups[begin / piece * light_group_count];
    uint32_t* types = &scratch.piece_types[begin / piece * light_group_count];
    uint32_t* contact = &scratch.piece_contact[begin / piece * light_group_count];
    for (size_t i = begin; i < end; ++i) {
      const uint32_t group = group_of(out.records[i]);
      out.sorted_place[i] = group;
      ++groups[group];
      types[group] |= light_type_bits(out.records[i]);
      contact[group] += out.records[i].direction_type.w > 0.0f ? 1 : 0;
    }
  });
  out.group_begin.fill(0);
  out.group_types.fill(0);
  out.group_contact_lights.fill(0);
  for (size_t p = 0; p < pieces; ++p) {
    for (uint32_t g = 0; g < light_group_count; ++g) {
      out.group_begin[g + 1] += scratch.piece_groups[p * light_group_count + g];
      out.group_types[g] |= scratch.piece_types[p * light_group_count + g];
      out.group_contact_lights[g] += scratch.piece_contact[p * light_group_count + g];
    }
  }
  for (uint32_t g = 0; g < light_group_count; ++g) out.group_begin[g + 1] += out.group_begin[g];
  // Each piece's counts become its first place in each group (stable: pieces in order).
  std::array<uint32_t, light_group_count> next{};
  std::copy(out.group_begin.begin(), out.group_begin.end() - 1, next.begin());
  for (size_t p = 0; p < pieces; ++p) {
    for (uint32_t g = 0; g < light_group_count; ++g) {
      uint32_t& piece_group = scratch.piece_groups[p * light_group_count + g];
      next[g] += std::exchange(piece_group, next[g]);
    }
  }
  jobs::run_in_pieces(pool, count, piece, [&](size_t begin, size_t end) {
    uint32_t* places = &scratch.piece_groups[begin / piece * light_group_count];
    for (size_t i = begin; i < end; ++i) {
      const uint32_t place = places[out.sorted_place[i]]++;
      out.sorted_place[i] = place;
      if (changes.changed_at.empty()) {
        sorted[place] = out.records[i];
      } else if (std::memcmp(&sorted[place], &out.records[i], sizeof(GpuLight)) != 0) {
        sorted[place] = out.records[i];
        changes.changed_at[place] = changes.now;
      }
    }
  });
}

}  // namespace sg::shadows
