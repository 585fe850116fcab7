// SPDX-License-Identifier: MIT
#pragma once
// Which light gets which shadow, and which shadows render this frame: the atlas planner's tiles
// (resolution from each light's importance on screen, within the memory budget) and the cache's
// choice of the views to re-render (what changed, within a per-frame budget of views), applied
// to a frame's lights, both within the time budget's limits when it has one (ShadowTimeBudget:
// lower resolutions, fewer views, learnt from the shadow passes' measured GPU time). After
// schedule(), every shadowed view carries its tiles or none, `render` says whether it is drawn
// this frame, and each record says where its map is; a light whose map holds nothing valid yet
// (new, moved, or waiting for the budget) is shaded without a shadow.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/jobs/parallel_pieces.h"

#include "systems/shadows/align_by_key.h"
#include "systems/shadows/caster_changes.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/schedule_steps.h"
#include "systems/shadows/shadow_atlas_planner.h"
#include "systems/shadows/shadow_cache.h"
#include "systems/shadows/shadow_resolution.h"
#include "systems/shadows/shadow_time_budget.h"

namespace sg::shadows {

// The camera the importance of lights is measured from.
struct ShadowCamera {
  glm::vec3 eye{0.0f};
  glm::mat4 view_projection{1.0f};
  float pixels_per_radian = 1.0f;  // the screen's height over its vertical field of view, roughly
};

// The projected size, in pixels, of a light's sphere of reach `reach` seen from `camera`: 0 when
// the sphere lies wholly outside the camera's frustum (nothing it lights is seen), the sphere's
// diameter on screen otherwise, unbounded (a large number) when the camera is inside it or the
// light has no range (w < 0).
float light_importance(const glm::vec4& reach, const ShadowCamera& camera);

struct ShadowScheduleStats {
  uint32_t views_rendered = 0;         // 2D maps and cube faces drawn this frame
  uint32_t views_moving_only = 0;      // of those, drawn with the moving casters only
  uint32_t views_cached = 0;           // shadowed views kept from an earlier frame
  uint32_t lights_without_shadow = 0;  // out of sight, or over the memory budget
  uint32_t lights_waiting = 0;         // have a tile, nothing valid in it yet (the view budget)
  // Cascades of directional lights the view uses (cascades.h). Each counts as a light in the
  // other counts here: it has a tile of its own, is redrawn on its own and may wait on its own.
  uint32_t cascades = 0;
  // Over the lights whose maps were due this frame, how many frames each map has been wrong
  // (ShadowCacheStats: 0 when rendered now): median, 99th percentile, most.
  uint32_t lights_due = 0;
  uint32_t map_lag_p50 = 0;
  uint32_t map_lag_p99 = 0;
  uint32_t map_lag_max = 0;
  uint32_t lights_changed_tier = 0;  // resolution other than the previous frame's (AtlasStats)
  uint32_t lights_retiled = 0;       // in tiles other than the previous frame's: maps drawn anew
  bool atlas_repacked = false;       // every tile placed anew (AtlasStats::repacked)
  // What each budget held down: lights at a lower resolution than they want, or without shadow,
  // for memory; lights below what their size on screen asks, and views due (within view_budget)
  // that the time budget's cap left for later frames, for time.
  uint32_t lights_demoted_by_memory = 0;
  uint32_t lights_dropped_by_memory = 0;
  uint32_t lights_demoted_by_time = 0;
  uint32_t views_deferred_by_time = 0;
  uint64_t texels_used = 0;
  uint32_t pages_used = 0;
  std::vector<std::pair<uint32_t, uint32_t>> lights_per_resolution;  // (resolution, lights)
};

// The frame's shadow casters, as schedule() takes them: every caster, which it compares with
// the previous call's (CasterChangeTracker), or, from a caller that knows what moved, just the
// boxes a shadow could have changed in since the previous call (a moved caster's old and new box,
// an added or removed one's box). A caller may mix the two from frame to frame: the tracker then
// compares with the last frame it saw whole and reports at worst more boxes than moved.
// Changes may come split as ShadowCache takes them (CasterChanges): `changed` where still
// casters changed, `moving` where moving ones were and are; every change the tracker finds is a
// still one.
struct CasterUpdate {
  CasterUpdate(std::span<const CasterBounds> all = {}) : all(all) {}
  static CasterUpdate changes(std::span<const scene::Aabb> boxes, std::span<const scene::Aabb> moving = {}) {
    CasterUpdate update;
    update.changed = boxes;
    update.moving = moving;
    update.changes_only = true;
    return update;
  }

  std::span<const CasterBounds> all;
  std::span<const scene::Aabb> changed;
  std::span<const scene::Aabb> moving;
  bool changes_only = false;
};

class ShadowSchedule {
 public:
  // `static_layers`: the renderer keeps a static layer of each map (ShadowCache), so renders for
  // moving casters may draw only those. `time_budget_ms`: the shadow passes' GPU time a frame
  // may take (ShadowTimeBudget); 0: no budget. `time_policy`: how its lowered tiers fall on the
  // lights (shadow_time_policy.h).
  explicit ShadowSchedule(const AtlasConfig& atlas, bool static_layers = false,
                          ShadowResolution resolution = ShadowResolution::screen, double time_budget_ms = 0.0,
                          ShadowTimePolicy time_policy = ShadowTimePolicy::redraw_cost);

  // Places, caches and records every shadow of `lights` (gathered, not yet sorted). The records
  // gathering kept (FrameLights::refilled 0) must hold what this schedule wrote into them last:
  // it writes a record only where that changes. `casters` are the frame's shadow casters or
  // their changes (CasterUpdate); view_budget caps the views rendered (0: no cap), and so may the
  // time budget. With a `pool`, the per-light work runs in pieces on it (the same result).
  void schedule(FrameLights& lights, const ShadowCamera& camera, const CasterUpdate& casters,
                uint32_t view_budget, jobs::ThreadPool* pool = nullptr);
  // Every map must be rendered again (the atlas image was recreated).
  void invalidate_all() { cache_.invalidate_all(); }
  // ShadowCache::forget_static_layers and static_layers_not_kept.
  void forget_static_layers() { cache_.forget_static_layers(); }
  void static_layers_not_kept() { cache_.static_layers_not_kept(); }

  const ShadowScheduleStats& stats() const { return stats_; }
  // How long the last schedule()'s steps took.
  const ScheduleStepTimes& step_times() const { return step_ms_; }
  uint32_t pages_used() const { return planner_.stats().pages_used; }
  // A line for the log when the budget's effect changed (ShadowAtlasPlanner), rate limited.
  std::optional<std::string> take_budget_message() { return planner_.take_budget_message(); }

  // The time budget: the step a frame scheduled now is planned with, to hand back with the frame's
  // measured shadow passes (ShadowTimeBudget::measured).
  const ShadowTimeBudget& time_budget() const { return time_budget_; }
  // A new time budget from the next frame on, learnt afresh (0: none); the same one keeps what
  // it learnt.
  void set_time_budget(double budget_ms) {
    if (budget_ms != time_budget_.budget_ms()) time_budget_ = ShadowTimeBudget(budget_ms);
  }
  uint64_t time_budget_step() const { return time_budget_.step(); }
  void measured(uint64_t step, uint32_t views, double ms) { time_budget_.measured(step, views, ms); }
  std::optional<std::string> take_time_budget_message() { return time_budget_.take_message(); }

 private:
  ShadowAtlasPlanner planner_;
  ShadowCache cache_;
  ShadowTimeBudget time_budget_;
  CasterChangeTracker caster_changes_;
  uint32_t page_size_;
  bool static_layers_;
  ShadowResolution resolution_;
  ShadowScheduleStats stats_;
  ScheduleStepTimes step_ms_{};

  // Per frame, kept so that scheduling allocates nothing once grown.
  static constexpr uint32_t no_request = UINT32_MAX;
  std::vector<uint32_t> request_of_;  // per view (maps, then cubes): its request or no_request
  // Per view, as request_of_: what it would request, and what the cache would see of it.
  std::vector<ShadowRequest> view_requests_;
  std::vector<ShadowCacheLight> cache_lights_;
  std::vector<uint8_t> pieces_aligned_;  // per piece of views: its views' rendered entries are theirs
  jobs::KeepScratch keep_scratch_;
  std::vector<ShadowRequest> requests_;
  std::vector<ShadowPlacement> placements_;
  std::vector<uint8_t> render_;
  std::vector<uint8_t> usable_;
  std::vector<uint8_t> redraws_;  // per request: ShadowAtlasPlanner::RedrawSample

  // The view each light's map was last rendered with, in the order of the frame's maps and
  // cubes: usually the previous frame's lights in the same order, so nothing is looked up.
  struct RenderedMap {
    uint64_t key = 0;
    LightView view;
  };
  struct RenderedCube {
    uint64_t key = 0;
    glm::vec4 position_far{0.0f};
  };
  std::vector<RenderedMap> rendered_maps_;
  std::vector<RenderedCube> rendered_cubes_;
  std::vector<RenderedMap> rendered_maps_scratch_;    // for align_by_key
  std::vector<RenderedCube> rendered_cubes_scratch_;  // for align_by_key
  KeyPlaces places_;                                  // for align_by_key
};

}  // namespace sg::shadows
