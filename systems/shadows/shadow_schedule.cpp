#include "systems/shadows/shadow_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "systems/shadows/atlas_tile_coords.h"
#include "systems/shadows/quality_floor.h"

namespace sg::shadows {
namespace {

constexpr float unbounded_importance = 1.0e9f;

// The entry of `views[i]` in `rendered`, which holds one entry per view in the order of an
// earlier frame's views. Usually that order is this frame's and entry i is the one; otherwise
// `rendered` is first reordered to follow `views`: each entry carried over from the same key, or
// new. Lights that are gone lose theirs; a light never has a cached map without its entry, since
// the cache forgets lights that leave the list too. Checked one view at a time, where the caller
// reads the view anyway: thousands of views are large and a separate pass over them is not free.
template <class Views, class Rendered>
Rendered& entry_for(const Views& views, size_t i, std::vector<Rendered>& rendered,
                    std::unordered_map<uint64_t, uint32_t>& index_of_key) {
  if (i < rendered.size() && rendered.size() == views.size() && rendered[i].key == views[i].key)
    return rendered[i];
  index_of_key.clear();
  for (uint32_t k = 0; k < rendered.size(); ++k) index_of_key.emplace(rendered[k].key, k);
  std::vector<Rendered> matched;
  matched.reserve(views.size());
  for (const auto& view : views) {
    const auto found = index_of_key.find(view.key);
    matched.push_back(found == index_of_key.end() ? Rendered{.key = view.key} : rendered[found->second]);
  }
  rendered = std::move(matched);
  return rendered[i];
}

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

ShadowSchedule::ShadowSchedule(const AtlasConfig& atlas) : planner_(atlas), page_size_(atlas.page_size) {}

void ShadowSchedule::schedule(FrameLights& lights, const ShadowCamera& camera, const CasterUpdate& casters,
                              uint32_t view_budget) {
  // Requests: maps first, then cubes, each in the lights' order. A light whose reach is out of
  // the camera's sight shades nothing visible: it asks for no tile at all.
  const CameraFrustum frustum(camera);
  requests_.clear();
  request_of_.assign(lights.maps.size() + lights.cubes.size(), no_request);
  stats_ = {};
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    ShadowMapView& map = lights.maps[m];
    const float importance = importance_in(map.reach, camera, frustum);
    map.importance = importance;
    if (importance <= 0.0f) continue;
    request_of_[m] = static_cast<uint32_t>(requests_.size());
    requests_.push_back({map.key, false, map.requested_resolution, importance,
                         quality_floor(algorithm_of(lights.records[map.light]))});
  }
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    ShadowCubeView& cube = lights.cubes[c];
    // A face spans a quarter turn, about half of what the whole sphere covers on screen.
    const float importance = 0.5f * importance_in(cube.position_far, camera, frustum);
    cube.importance = importance;
    if (importance <= 0.0f) continue;
    request_of_[lights.maps.size() + c] = static_cast<uint32_t>(requests_.size());
    requests_.push_back({cube.key, true, cube.requested_resolution, importance,
                         quality_floor(algorithm_of(lights.records[cube.light]))});
  }
  placements_.assign(requests_.size(), ShadowPlacement{});
  planner_.plan(requests_, placements_);

  // The cache sees the lights that have tiles.
  cache_lights_.clear();
  cached_request_.clear();
  const auto add_to_cache = [&](uint32_t request, const glm::vec4& reach, bool changed, uint32_t views) {
    if (request == no_request || placements_[request].resolution == 0) return;
    cached_request_.push_back(request);
    cache_lights_.push_back({requests_[request].key, reach, changed, placements_[request].moved, views});
  };
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    add_to_cache(request_of_[m], lights.maps[m].reach, lights.maps[m].changed, 1);
  }
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    const ShadowCubeView& cube = lights.cubes[c];
    add_to_cache(request_of_[lights.maps.size() + c], cube.position_far, cube.changed, 6);
  }
  render_.assign(cache_lights_.size(), 0);
  usable_.assign(cache_lights_.size(), 0);
  const std::span<const scene::Aabb> changed_casters =
      casters.changes_only ? casters.changed : caster_changes_.update(casters.all);
  cache_.plan(cache_lights_, changed_casters, view_budget, render_, usable_);

  // Results per request, then onto the views and their records.
  decision_.assign(requests_.size(), Decision{});
  for (size_t c = 0; c < cached_request_.size(); ++c) {
    decision_[cached_request_[c]] = {render_[c] != 0, usable_[c] != 0};
  }
  const auto count_resolution = [&](uint32_t resolution) {
    auto found = std::find_if(stats_.lights_per_resolution.begin(), stats_.lights_per_resolution.end(),
                              [&](const auto& entry) { return entry.first == resolution; });
    if (found == stats_.lights_per_resolution.end()) {
      stats_.lights_per_resolution.emplace_back(resolution, 1);
    } else {
      ++found->second;
    }
  };
  const auto apply = [&](uint32_t request, uint32_t views, auto& view, auto&& give_map) {
    view.resolution = 0;
    view.render = false;
    if (request == no_request || placements_[request].resolution == 0) {
      ++stats_.lights_without_shadow;
      return;
    }
    const ShadowPlacement& placement = placements_[request];
    count_resolution(placement.resolution);
    const Decision decision = decision_[request];
    if (!decision.usable) {
      ++stats_.lights_waiting;
      return;
    }
    view.resolution = placement.resolution;
    view.render = decision.render;
    (decision.render ? stats_.views_rendered : stats_.views_cached) += views;
    give_map(placement);
  };
  // A cached map was rendered from where its light was then: the record samples it with that
  // view, not the light's present one.
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    ShadowMapView& map = lights.maps[m];
    apply(request_of_[m], 1, map, [&](const ShadowPlacement& placement) {
      map.tile = placement.tiles[0];
      RenderedMap& rendered = entry_for(lights.maps, m, rendered_maps_, index_of_key_);
      if (map.render) rendered.view = map.view;
      set_shadow_map(lights.records[map.light], map.tile.page, tile_uv_rect(map.tile, page_size_),
                     map.resolution, rendered.view);
    });
  }
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    ShadowCubeView& cube = lights.cubes[c];
    apply(request_of_[lights.maps.size() + c], 6, cube, [&](const ShadowPlacement& placement) {
      cube.tiles = placement.tiles;
      RenderedCube& rendered = entry_for(lights.cubes, c, rendered_cubes_, index_of_key_);
      if (cube.render) {
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
  std::sort(stats_.lights_per_resolution.begin(), stats_.lights_per_resolution.end());
  stats_.texels_used = planner_.stats().texels_used;
  stats_.pages_used = planner_.stats().pages_used;
}

}  // namespace sg::shadows
