#include "systems/shadows/shadow_schedule.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <utility>

#include "ecs/parallel_pieces.h"

#include "systems/shadows/align_by_key.h"
#include "systems/shadows/atlas_tile_coords.h"
#include "systems/shadows/quality_floor.h"

namespace sg::shadows {
namespace {

constexpr float unbounded_importance = 1.0e9f;

// Lights a piece of work handles on the pool: enough that a piece outweighs handing it out (a
// compare-exchange), few enough that a thousand lights keep 16 threads busy.
constexpr size_t views_per_piece = 64;

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

}  // namespace

float light_importance(const glm::vec4& reach, const ShadowCamera& camera) {
  return importance_in(reach, camera, CameraFrustum(camera));
}

ShadowSchedule::ShadowSchedule(const AtlasConfig& atlas, bool static_layers)
    : planner_(atlas), page_size_(atlas.page_size), static_layers_(static_layers) {}

void ShadowSchedule::schedule(FrameLights& lights, const ShadowCamera& camera, const CasterUpdate& casters,
                              uint32_t view_budget, ecs::ThreadPool* pool) {
  // Requests: maps first, then cubes, each in the lights' order. A light whose reach is out of
  // the camera's sight shades nothing visible: it asks for no tile at all. Importances and
  // floors are worked out on the pool, the requests listed in order after. There too, each
  // piece checks that its views are the ones their entries of rendered_maps_ and
  // rendered_cubes_ hold (usually: the last frame's lights in the same order), which one thread
  // would read hundreds of bytes apart.
  const CameraFrustum frustum(camera);
  const size_t map_count = lights.maps.size();
  const size_t view_count = map_count + lights.cubes.size();
  quality_floors_.resize(view_count);
  const bool same_counts =
      rendered_maps_.size() == map_count && rendered_cubes_.size() == lights.cubes.size();
  pieces_aligned_.assign(std::max<size_t>((view_count + views_per_piece - 1) / views_per_piece, 1), 1);
  ecs::run_in_pieces(pool, view_count, views_per_piece, [&](size_t begin, size_t end) {
    bool aligned = same_counts;
    for (size_t v = begin; v < end; ++v) {
      if (v < map_count) {
        ShadowMapView& map = lights.maps[v];
        map.importance = importance_in(map.reach, camera, frustum);
        quality_floors_[v] = quality_floor(algorithm_of(lights.records[map.light]));
        aligned = aligned && rendered_maps_[v].key == map.key;
      } else {
        ShadowCubeView& cube = lights.cubes[v - map_count];
        // A face spans a quarter turn, about half of what the whole sphere covers on screen.
        cube.importance = 0.5f * importance_in(cube.position_far, camera, frustum);
        quality_floors_[v] = quality_floor(algorithm_of(lights.records[cube.light]));
        aligned = aligned && rendered_cubes_[v - map_count].key == cube.key;
      }
    }
    pieces_aligned_[begin / views_per_piece] = aligned ? 1 : 0;
  });
  const bool aligned =
      same_counts && std::find(pieces_aligned_.begin(), pieces_aligned_.end(), 0) == pieces_aligned_.end();
  // The requests, then the lights the cache sees (those given tiles), each listed in order on
  // the pool: a view's fields lie hundreds of bytes apart, so one thread reading them for
  // thousands of lights took longer than the work.
  request_of_.assign(view_count, no_request);
  requests_.resize(view_count);
  const size_t request_count = ecs::keep_in_pieces(
      pool, view_count, views_per_piece, keep_scratch_,
      [&](size_t v) {
        return (v < map_count ? lights.maps[v].importance : lights.cubes[v - map_count].importance) > 0.0f;
      },
      [&](size_t v, size_t r) {
        request_of_[v] = static_cast<uint32_t>(r);
        if (v < map_count) {
          const ShadowMapView& map = lights.maps[v];
          requests_[r] = {map.key, false, map.requested_resolution, map.importance, quality_floors_[v]};
        } else {
          const ShadowCubeView& cube = lights.cubes[v - map_count];
          requests_[r] = {cube.key, true, cube.requested_resolution, cube.importance, quality_floors_[v]};
        }
      });
  requests_.resize(request_count);
  placements_.assign(requests_.size(), ShadowPlacement{});
  planner_.plan(requests_, placements_, pool);

  cache_lights_.resize(view_count);
  cached_request_.resize(view_count);
  const size_t cached_count = ecs::keep_in_pieces(
      pool, view_count, views_per_piece, keep_scratch_,
      [&](size_t v) { return request_of_[v] != no_request && placements_[request_of_[v]].resolution != 0; },
      [&](size_t v, size_t k) {
        const uint32_t request = request_of_[v];
        cached_request_[k] = request;
        const bool map = v < map_count;
        const glm::vec4& reach = map ? lights.maps[v].reach : lights.cubes[v - map_count].position_far;
        const bool changed = map ? lights.maps[v].changed : lights.cubes[v - map_count].changed;
        cache_lights_[k] = {requests_[request].key, reach, changed, placements_[request].moved,
                            map ? 1u : 6u};
      });
  cache_lights_.resize(cached_count);
  cached_request_.resize(cached_count);
  render_.assign(cache_lights_.size(), 0);
  usable_.assign(cache_lights_.size(), 0);
  const CasterChanges changes{casters.changes_only ? casters.changed : caster_changes_.update(casters.all),
                              casters.changes_only ? casters.moving : std::span<const scene::Aabb>{}};
  cache_.plan(cache_lights_, changes, view_budget, static_layers_, render_, usable_, pool);

  // Results per request, then onto the views and their records, on the pool: each view writes
  // only itself, its record and its entry, and counts into its piece's tally.
  decision_.assign(requests_.size(), Decision{});
  for (size_t c = 0; c < cached_request_.size(); ++c) {
    decision_[cached_request_[c]] = {render_[c], usable_[c] != 0};
  }
  // A light never has a cached map without its entry: the cache forgets lights that leave too.
  if (!aligned) {
    align_by_key(lights.maps, rendered_maps_, index_of_key_, rendered_maps_scratch_);
    align_by_key(lights.cubes, rendered_cubes_, index_of_key_, rendered_cubes_scratch_);
  }
  const auto apply = [&](uint32_t request, uint32_t views, auto& view, Tally& tally, auto&& give_map) {
    view.resolution = 0;
    view.render = false;
    view.moving_casters_only = false;
    if (request == no_request || placements_[request].resolution == 0) {
      ++tally.without_shadow;
      return;
    }
    const ShadowPlacement& placement = placements_[request];
    ++tally.lights_per_tier[std::countr_zero(placement.resolution)];
    const Decision decision = decision_[request];
    if (!decision.usable) {
      ++tally.waiting;
      return;
    }
    view.resolution = placement.resolution;
    view.render = decision.render != keep_map;
    view.moving_casters_only = decision.render == draw_moving_casters;
    (view.render ? tally.views_rendered : tally.views_cached) += views;
    if (view.moving_casters_only) tally.views_moving_only += views;
    give_map(placement);
  };
  const size_t map_pieces = (map_count + views_per_piece - 1) / views_per_piece;
  tallies_.assign(map_pieces + (lights.cubes.size() + views_per_piece - 1) / views_per_piece, Tally{});
  // A cached map was rendered from where its light was then: the record samples it with that
  // view, not the light's present one.
  ecs::run_in_pieces(pool, map_count, views_per_piece, [&](size_t begin, size_t end) {
    Tally& tally = tallies_[begin / views_per_piece];
    for (size_t m = begin; m < end; ++m) {
      ShadowMapView& map = lights.maps[m];
      apply(request_of_[m], 1, map, tally, [&](const ShadowPlacement& placement) {
        map.tile = placement.tiles[0];
        RenderedMap& rendered = rendered_maps_[m];
        // Moving casters are drawn over the static layer with the view it was drawn with (a map
        // fitted to the scene's bounds may have moved since without its light changing).
        if (map.moving_casters_only) {
          map.view = rendered.view;
        } else if (map.render) {
          rendered.view = map.view;
        }
        set_shadow_map(lights.records[map.light], map.tile.page, tile_uv_rect(map.tile, page_size_),
                       map.resolution, rendered.view);
      });
    }
  });
  ecs::run_in_pieces(pool, lights.cubes.size(), views_per_piece, [&](size_t begin, size_t end) {
    Tally& tally = tallies_[map_pieces + begin / views_per_piece];
    for (size_t c = begin; c < end; ++c) {
      ShadowCubeView& cube = lights.cubes[c];
      apply(request_of_[map_count + c], 6, cube, tally, [&](const ShadowPlacement& placement) {
        cube.tiles = placement.tiles;
        RenderedCube& rendered = rendered_cubes_[c];
        if (cube.moving_casters_only) {
          cube.views = rendered.views;
          cube.position_far = glm::vec4(rendered.origin, cube.position_far.w);
        } else if (cube.render) {
          rendered.views = cube.views;
          rendered.origin = glm::vec3(cube.position_far);
        }
        std::array<glm::vec2, 6> origins;
        for (int f = 0; f < 6; ++f) origins[f] = glm::vec2(tile_uv_rect(cube.tiles[f], page_size_));
        set_shadow_cube(lights.records[cube.light], cube.tiles[0].page, origins,
                        float(cube.resolution) / float(page_size_), cube.resolution, rendered.views,
                        rendered.origin);
      });
    }
  });

  Tally total;
  for (const Tally& tally : tallies_) {
    total.without_shadow += tally.without_shadow;
    total.waiting += tally.waiting;
    total.views_rendered += tally.views_rendered;
    total.views_cached += tally.views_cached;
    total.views_moving_only += tally.views_moving_only;
    for (size_t t = 0; t < total.lights_per_tier.size(); ++t)
      total.lights_per_tier[t] += tally.lights_per_tier[t];
  }
  stats_ = {};
  stats_.lights_without_shadow = total.without_shadow;
  stats_.lights_waiting = total.waiting;
  stats_.views_rendered = total.views_rendered;
  stats_.views_cached = total.views_cached;
  stats_.views_moving_only = total.views_moving_only;
  for (uint32_t tier = 0; tier < total.lights_per_tier.size(); ++tier) {
    if (total.lights_per_tier[tier] != 0) {
      stats_.lights_per_resolution.emplace_back(1u << tier, total.lights_per_tier[tier]);
    }
  }
  stats_.texels_used = planner_.stats().texels_used;
  stats_.pages_used = planner_.stats().pages_used;
}

}  // namespace sg::shadows
