// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "ecs/jobs/parallel_pieces.h"

#include "systems/shadows/align_by_key.h"
#include "systems/shadows/atlas_tile_coords.h"
#include "systems/shadows/quality_floor.h"

namespace sg::shadows {
namespace {

constexpr float unbounded_importance = 1.0e9f;

// Lights a piece of work handles on the pool: enough that a piece outweighs handing it out (a
// compare-exchange), few enough that a thousand lights keep 16 threads busy.
constexpr size_t views_per_piece = 64;

// The tighter of two caps on views, 0 meaning none.
uint32_t tighter_cap(uint32_t a, uint32_t b) { return a == 0 ? b : b == 0 ? a : std::min(a, b); }

// The camera's frustum planes, normalized, computed once for all of a frame's lights.
struct CameraFrustum {
  std::array<glm::vec4, 6> planes;

  explicit CameraFrustum(const ShadowCamera& camera) : planes(frustum_planes(camera.view_projection)) {
    for (glm::vec4& plane : planes) plane /= glm::length(glm::vec3(plane));
  }
};

float importance_in(const glm::vec4& reach, const ShadowCamera& camera, const CameraFrustum& frustum) {
  if (reach.w < 0.0f) return unbounded_importance;
  const glm::vec3 centre(reach);
  for (const glm::vec4& plane : frustum.planes) {
    if (glm::dot(glm::vec3(plane), centre) + plane.w < -reach.w) return 0.0f;
  }
  const float distance = glm::length(centre - camera.eye);
  if (distance <= reach.w) return unbounded_importance;
  return 2.0f * std::asin(reach.w / distance) * camera.pixels_per_radian;
}

// ShadowSettings::priority: tiers added to log2 of the importance, within its range.
float prioritized(float importance, float priority) {
  return importance *
         std::exp2(std::clamp(priority, -scene::max_shadow_priority, scene::max_shadow_priority));
}

}  // namespace

float light_importance(const glm::vec4& reach, const ShadowCamera& camera) {
  return importance_in(reach, camera, CameraFrustum(camera));
}

ShadowSchedule::ShadowSchedule(const AtlasConfig& atlas, bool static_layers, ShadowResolution resolution,
                               double time_budget_ms, ShadowTimePolicy time_policy)
    : planner_(atlas, time_policy),
      time_budget_(time_budget_ms),
      page_size_(atlas.page_size),
      static_layers_(static_layers),
      resolution_(resolution) {}

void ShadowSchedule::schedule(FrameLights& lights, const ShadowCamera& camera, const CasterUpdate& casters,
                              uint32_t view_budget, jobs::ThreadPool* pool) {
  // Requests: maps first, then cubes, each in the lights' order. A light whose reach is out of
  // the camera's sight shades nothing visible: it asks for no tile at all. Importances, floors
  // and compact copies of what the planner and the cache need of each view are worked out on
  // the pool, the requests listed in order after. There too, each piece checks that its views
  // are the ones their entries of rendered_maps_ and rendered_cubes_ hold (usually: the last
  // frame's lights in the same order). One thread would read all that hundreds of bytes apart.
  step_ms_.fill(0.0);
  StepClock clock(step_ms_);
  const CameraFrustum frustum(camera);
  const bool pinned = resolution_ == ShadowResolution::requested;
  const size_t map_count = lights.maps.size();
  const size_t view_count = map_count + lights.cubes.size();
  view_requests_.resize(view_count);
  cache_lights_.resize(view_count);
  const bool same_counts =
      rendered_maps_.size() == map_count && rendered_cubes_.size() == lights.cubes.size();
  pieces_aligned_.assign(jobs::piece_count(view_count, views_per_piece), 1);
  jobs::run_in_pieces(pool, view_count, views_per_piece, [&](size_t begin, size_t end) {
    bool aligned = same_counts;
    for (size_t v = begin; v < end; ++v) {
      if (v < map_count) {
        ShadowMapView& map = lights.maps[v];
        map.importance =
            map.needed ? prioritized(importance_in(map.reach, camera, frustum), map.priority) : 0.0f;
        view_requests_[v] = {map.key,
                             false,
                             map.requested_resolution,
                             map.importance,
                             quality_floor(algorithm_of(lights.records[map.light])),
                             pinned,
                             static_cast<uint32_t>(v)};
        cache_lights_[v] = {
            .key = map.key, .reach = map.reach, .changed = map.changed, .views = 1, .update = map.update};
        aligned = aligned && rendered_maps_[v].key == map.key;
      } else {
        ShadowCubeView& cube = lights.cubes[v - map_count];
        // A face spans a quarter turn, about half of what the whole sphere covers on screen.
        cube.importance =
            prioritized(0.5f * importance_in(cube.position_far, camera, frustum), cube.priority);
        view_requests_[v] = {cube.key,
                             true,
                             cube.requested_resolution,
                             cube.importance,
                             quality_floor(algorithm_of(lights.records[cube.light])),
                             pinned,
                             static_cast<uint32_t>(v)};
        cache_lights_[v] = {.key = cube.key,
                            .reach = cube.position_far,
                            .changed = cube.changed,
                            .views = 6,
                            .update = cube.update};
        aligned = aligned && rendered_cubes_[v - map_count].key == cube.key;
      }
    }
    pieces_aligned_[begin / views_per_piece] = aligned ? 1 : 0;
  });
  clock.lap(ScheduleStep::views);
  const bool aligned =
      same_counts && std::find(pieces_aligned_.begin(), pieces_aligned_.end(), 0) == pieces_aligned_.end();
  // The requests, then the lights the cache sees (those given tiles), each listed in order on
  // the pool: a view's fields lie hundreds of bytes apart, so one thread reading them for
  // thousands of lights took longer than the work; both are filtered from the compact copies
  // the pass above made.
  request_of_.assign(view_count, no_request);
  requests_.resize(view_count);
  const size_t request_count = jobs::keep_in_pieces(
      pool, view_count, views_per_piece, keep_scratch_,
      [&](size_t v) { return view_requests_[v].importance > 0.0f; },
      [&](size_t v, size_t r) {
        request_of_[v] = static_cast<uint32_t>(r);
        requests_[r] = view_requests_[v];
      });
  requests_.resize(request_count);
  clock.lap(ScheduleStep::requests);
  placements_.resize(requests_.size());  // plan() writes every one
  const ShadowTimeBudget::Limits& limits = time_budget_.limits();
  planner_.plan(requests_, placements_, pool, limits.lowered_tiers, view_count, &clock);

  // The cache sees every view, in the views' order (usually the last frame's, so that its states
  // need no lookup by key), those without a tile as not placed.
  jobs::run_in_pieces(pool, view_count, views_per_piece, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      const uint32_t request = request_of_[v];
      cache_lights_[v].placed = request != no_request && placements_[request].resolution != 0;
      cache_lights_[v].invalid = cache_lights_[v].placed && placements_[request].moved;
    }
  });
  render_.assign(view_count, 0);
  usable_.assign(view_count, 0);
  const CasterChanges changes{casters.changes_only ? casters.changed : caster_changes_.update(casters.all),
                              casters.changes_only ? casters.moving : std::span<const scene::Aabb>{}};
  cache_.plan(cache_lights_, changes, tighter_cap(view_budget, limits.view_cap), static_layers_, render_,
              usable_, pool, &clock);
  // The results onto the views and their records, on the pool: each view writes only itself,
  // its record, its entry and what its map cost this frame, for the planner's redraw rates (a
  // map drawn into new tiles says nothing of how often its light or its casters change).
  // A light never has a cached map without its entry: the cache forgets lights that leave too.
  if (!aligned) {
    align_by_key(lights.maps, rendered_maps_, places_, rendered_maps_scratch_);
    align_by_key(lights.cubes, rendered_cubes_, places_, rendered_cubes_scratch_);
  }
  redraws_.resize(requests_.size());
  // The records keep their shadow fields from frame to frame (FrameLights::records): a record is
  // written where gathering packed it afresh (without a map) or its map was drawn, and loses its
  // map where its view has none usable. A map in new tiles or of a new resolution is usable only
  // once drawn there.
  const auto refilled = [&](uint32_t light) { return lights.refilled[light] != 0; };
  const auto apply = [&](size_t v, auto& view, GpuLight& record, bool packed_afresh, auto&& give_map) {
    if (const uint32_t request = request_of_[v]; request != no_request) {
      redraws_[request] = !cache_lights_[v].placed || cache_lights_[v].invalid
                              ? ShadowAtlasPlanner::no_redraw_sample
                          : render_[v] != keep_map ? ShadowAtlasPlanner::map_redrawn
                                                   : ShadowAtlasPlanner::map_kept;
    }
    view.resolution = 0;
    view.render = false;
    view.moving_casters_only = false;
    if (usable_[v] == 0) {  // not placed, or nothing valid in its tile yet
      record.info.w = no_shadow_map;
      return;
    }
    const uint32_t request = request_of_[v];
    view.resolution = placements_[request].resolution;
    view.render = render_[v] != keep_map;
    view.moving_casters_only = render_[v] == draw_moving_casters;
    view.frames_since_drawn =
        uint32_t(std::min<uint64_t>(cache_.plans_since_rendered(uint32_t(v)), UINT32_MAX));
    give_map(planner_.tiles_of(request), packed_afresh || view.render);
  };
  // A cached map was rendered from where its light was then: the record samples it with that
  // view, not the light's present one.
  jobs::run_in_pieces(pool, view_count, views_per_piece, [&](size_t begin, size_t end) {
    for (size_t v = begin; v < end; ++v) {
      if (v < map_count) {
        ShadowMapView& map = lights.maps[v];
        const bool cascade = map.cascade != no_cascade;
        if (cascade) lights.cascades[map.cascade] = GpuLight{};  // no map unless given one
        GpuLight& record = cascade ? lights.cascades[map.cascade] : lights.records[map.light];
        apply(v, map, record, cascade || refilled(map.light),
              [&](const std::array<AtlasTile, 6>& tiles, bool write) {
                map.tile = tiles[0];
                RenderedMap& rendered = rendered_maps_[v];
                // Moving casters are drawn over the static layer with the view it was drawn with (a
                // map fitted to the scene's bounds may have moved since without its light changing).
                if (map.moving_casters_only) {
                  map.view = rendered.view;
                } else if (map.render) {
                  rendered.view = map.view;
                }
                if (write) {
                  set_shadow_map(record, map.tile.page, tile_uv_rect(map.tile, page_size_), map.resolution,
                                 rendered.view);
                }
              });
        continue;
      }
      ShadowCubeView& cube = lights.cubes[v - map_count];
      GpuLight& record = lights.records[cube.light];
      apply(v, cube, record, refilled(cube.light), [&](const std::array<AtlasTile, 6>& tiles, bool write) {
        cube.tiles = tiles;
        RenderedCube& rendered = rendered_cubes_[v - map_count];
        if (cube.moving_casters_only) {
          cube.position_far = rendered.position_far;
        } else if (cube.render) {
          rendered.position_far = cube.position_far;
        }
        if (!write) return;
        std::array<glm::vec2, 6> origins;
        for (int f = 0; f < 6; ++f) origins[f] = glm::vec2(tile_uv_rect(cube.tiles[f], page_size_));
        set_shadow_cube(record, cube.tiles[0].page, origins, float(cube.resolution) / float(page_size_),
                        cube.resolution, rendered.position_far);
      });
    }
  });

  planner_.record_redraws(redraws_, pool);

  // A cascaded light is shadowed where any of its cascades has a map.
  uint32_t idle_cascades = 0;
  for (const FrameLights::CascadedLight& light : lights.cascaded) {
    const auto first = lights.maps.begin() + light.first_view;
    const bool any = std::any_of(first, first + light.views, [&](const ShadowMapView& map) {
      return lights.cascades[map.cascade].info.w != no_shadow_map;
    });
    lights.records[light.record].info.w = any ? cascaded_shadow_maps : no_shadow_map;
    idle_cascades += static_cast<uint32_t>(
        std::count_if(first, first + light.views, [](const ShadowMapView& map) { return !map.needed; }));
  }

  // The frame's counts are the planner's (tiles) and the cache's (renders): every view without a
  // request has no shadow, and every request is one view's.
  const AtlasStats& atlas = planner_.stats();
  const ShadowCacheStats& cache = cache_.stats();
  stats_ = {};
  stats_.lights_without_shadow =
      static_cast<uint32_t>(view_count - requests_.size()) - idle_cascades + atlas.lights_without_shadow;
  stats_.cascades = static_cast<uint32_t>(lights.cascades.size()) - idle_cascades;
  stats_.lights_waiting = cache.lights_unavailable;
  stats_.views_rendered = cache.views_rendered;
  stats_.views_cached = cache.views_cached;
  stats_.views_moving_only = cache.views_moving_only;
  stats_.lights_due = cache.lights_due;
  stats_.map_lag_p50 = cache.lag_p50;
  stats_.map_lag_p99 = cache.lag_p99;
  stats_.map_lag_max = cache.lag_max;
  stats_.lights_changed_tier = atlas.lights_changed_tier;
  stats_.lights_retiled = atlas.lights_retiled;
  stats_.atlas_repacked = atlas.repacked;
  stats_.lights_per_resolution.assign(atlas.lights_per_resolution.rbegin(),  // smallest first
                                      atlas.lights_per_resolution.rend());
  stats_.texels_used = atlas.texels_used;
  stats_.pages_used = atlas.pages_used;
  stats_.lights_demoted_by_memory = atlas.demoted_by_budget;
  stats_.lights_dropped_by_memory = atlas.dropped_by_budget;
  stats_.lights_demoted_by_time = atlas.demoted_by_time;
  // The views view_budget alone would have drawn, about: a cube over what is left is skipped
  // whichever cap binds.
  const uint32_t due = cache.views_rendered + cache.views_waiting;
  const uint32_t uncapped = view_budget == 0 ? due : std::min(due, view_budget);
  if (tighter_cap(view_budget, limits.view_cap) != view_budget && uncapped > cache.views_rendered) {
    stats_.views_deferred_by_time = uncapped - cache.views_rendered;
  }
  time_budget_.planned(
      {atlas.lowerable_by_time, uncapped, stats_.lights_demoted_by_time, stats_.views_deferred_by_time});
  clock.lap(ScheduleStep::apply);
}

}  // namespace sg::shadows
