// SPDX-License-Identifier: MIT
#pragma once
// The shadow-map caching policy: which lights re-render their maps this frame. A light's map is
// kept from frame to frame and re-rendered only when it may be wrong, at most `view_budget` views
// a frame; a light waiting for its turn is lit with its stale map, or unshadowed when it has no
// valid map at all. Plain data, no GPU: the renderer records the passes this chooses.
//
// Where the renderer keeps a static layer per map (the depths of the casters that do not move,
// from the map's last drawing with every caster), a map that only moving casters made wrong is
// redrawn from that layer with just the moving casters: far fewer than all of them.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/jobs/parallel_pieces.h"

#include "systems/scene/aabb.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/align_by_key.h"
#include "systems/shadows/schedule_steps.h"
#include "systems/shadows/spheres_meeting_boxes.h"

namespace sg::shadows {

// One shadowed light of a frame, as the cache sees it.
struct ShadowCacheLight {
  uint64_t key = 0;  // stable identity, e.g. the entity's; each key once per frame
  // The sphere the light's shadow depends on (xyz centre, w radius): casters outside it cannot
  // change its map. w < 0: unbounded, any caster change affects it.
  glm::vec4 reach{0.0f, 0.0f, 0.0f, -1.0f};
  bool changed = false;  // the light itself moved or changed since it was last rendered
  bool invalid = false;  // its storage is new or moved this frame: the map's contents are garbage
  uint32_t views = 1;    // views a render costs, at least 1: 1 for a 2D map, 6 for a cube
  // every_frame: due every frame; on_demand: due only when `changed` (asked), never for casters.
  scene::ShadowUpdate update = scene::ShadowUpdate::automatic;
  // It has storage this frame. A light without is as if it were not listed (it renders nothing,
  // is not usable, and its state is forgotten) but keeps its place, so that a frame's lights stay
  // in the previous frame's order while some lose and gain storage.
  bool placed = true;
};

// Where shadow casters changed since the last plan.
struct CasterChanges {
  // Where the casters static layers hold changed: added or removed ones, and where a caster
  // stood when it started moving. A map whose reach meets one is drawn again with every caster.
  std::span<const scene::Aabb> still;
  // Where moving casters were and are: a map whose reach meets one needs only those redrawn.
  std::span<const scene::Aabb> moving;
};

// plan()'s decision for a light's map, as the values of its `render` span.
enum ShadowRender : uint8_t {
  keep_map = 0,
  draw_all_casters = 1,     // and keep its static layer, where the renderer keeps them
  draw_moving_casters = 2,  // its static layer restored, the moving casters drawn over it
};

struct ShadowCacheStats {
  uint32_t views_rendered = 0;
  uint32_t views_moving_only = 0;  // of views_rendered, those drawn with the moving casters alone
  uint32_t views_cached = 0;       // views of lights sampling a map kept from an earlier frame
  uint32_t lights_rendered = 0;
  uint32_t lights_waiting = 0;      // dirty but over this frame's budget: rendered in a later frame
  uint32_t views_waiting = 0;       // their views
  uint32_t lights_unavailable = 0;  // no valid map this frame: shaded unshadowed
  // How many frames the maps of the lights due this frame (wrong before this frame's renders:
  // moved, their casters moved, new) have been wrong, this one included, after its renders: 0
  // for a light rendered now, 1 for one that went wrong now and waits, k for one wrong k frames.
  // The median, the 99th percentile and the most over those lights; all 0 when none is due.
  uint32_t lights_due = 0;
  uint32_t lag_p50 = 0;
  uint32_t lag_p99 = 0;
  uint32_t lag_max = 0;

  friend bool operator==(const ShadowCacheStats&, const ShadowCacheStats&) = default;
};

class ShadowCache {
 public:
  // Decides which lights render this frame, and how. `changes` are the (non-empty) boxes shadows
  // may have changed in (CasterChangeTracker::update gives `still` ones). `static_layers`: the
  // renderer keeps a static layer of each map drawn with every caster. `render` and `usable` must
  // have lights.size() elements (else std::invalid_argument); for each light, in the same order:
  // - render: keep_map, or how to render its map this frame (ShadowRender): draw_moving_casters
  //   when only moving casters made it wrong and its static layer is kept (static_layers, drawn
  //   with every caster since the light last changed, moved in the atlas or was invalidated,
  //   and not forgotten); draw_all_casters otherwise;
  // - usable = 1: after this frame's renders its map holds a valid, maybe stale, picture, so the
  //   lighting may sample it; 0: shade the light unshadowed this frame.
  //
  // A light is dirty when its key was not in the previous call (it is new), it is `changed` or
  // `invalid`, its update is every_frame, or a changed caster box (still or moving) meets its
  // reach sphere (not for on_demand lights); it stays dirty until rendered.
  // Every dirty light renders when view_budget is 0 (unlimited) or their views fit in it.
  // Otherwise dirty lights are taken in this order until the budget is used: lights without a
  // valid map first (new, invalid, never rendered into their current storage), then the others,
  // each of the two the stalest (rendered longest ago) first, ties by key. A light with more
  // views than the budget has left is skipped for this frame, unless nothing has been rendered
  // yet this frame (so a budget under 6 views still renders cubes, one a frame). Stalest-first
  // means no light starves: with lights of one view and no new or invalid ones arriving, a dirty
  // light renders within ceil(dirty lights / view_budget) frames.
  //
  // usable = rendered this frame, or rendered in an earlier frame and not `invalid` (nor
  // invalidate_all()) since.
  //
  // Cost: O(lights), plus, when casters changed, testing each clean bounded light against only
  // the boxes near it (SpheresMeetingBoxes), plus, when the budget is short, ordering the dirty
  // lights (O(dirty): their key order, a histogram of how stale they are, and a sort of only
  // the staleness bucket where the budget runs out, and of later ones if it walks past). A
  // frame allocates nothing once grown, except when the lights are not the previous frame's keys
  // in the previous frame's order: the states are then matched to them through a table of keys
  // (KeyPlaces). With a `pool`, the passes over the lights and the tests against the boxes run
  // in pieces on it. `clock`, when given, times the dirty, casters, choose and renders steps.
  void plan(std::span<const ShadowCacheLight> lights, const CasterChanges& changes, uint32_t view_budget,
            bool static_layers, std::span<uint8_t> render, std::span<uint8_t> usable,
            jobs::ThreadPool* pool = nullptr, StepClock* clock = nullptr);

  // The last plan's counts.
  const ShadowCacheStats& stats() const { return stats_; }
  // Plans since the last plan's light `i` (its index in plan()'s `lights`) was rendered: 0 when
  // rendered by it.
  uint64_t plans_since_rendered(uint32_t i) const { return frame_ - states_[i].rendered_frame; }

  // Every map's contents are garbage (e.g. the storage image was recreated): every light is
  // unusable and dirty until rendered again.
  void invalidate_all();
  // Every static layer is wrong (casters that moved are still again): maps stay usable, and each
  // is drawn with every caster when it next renders.
  void forget_static_layers();
  // The last plan's draw_all_casters renders kept no static layer (a path without them drew
  // them).
  void static_layers_not_kept();

 private:
  struct LightState {
    uint64_t key = 0;
    uint64_t rendered_frame = 0;   // the plan that last rendered it; 0: never
    uint64_t drawn_all_frame = 0;  // the plan that last drew it with every caster
    uint64_t wrong_since = 0;      // the plan its map went wrong in since it was last rendered; 0: right
    bool dirty = true;             // wrong beyond what moving casters did
    bool moving_dirty = false;     // moving casters made it wrong
    bool valid = false;            // its map holds a picture rendered into its current storage
    bool static_kept = false;      // its last drawing with every caster kept a static layer: it
                                   // holds while the light is not dirty
  };

  // Sets `flag` on the lights not dirty at all yet whose reach meets one of `boxes`.
  void mark_by_casters(std::span<const ShadowCacheLight> lights, std::span<const scene::Aabb> boxes,
                       bool LightState::*flag, jobs::ThreadPool* pool);
  void choose_renders(std::span<const ShadowCacheLight> lights, uint32_t view_budget,
                      std::span<uint8_t> render, jobs::ThreadPool* pool);
  // Whether states_ holds the lights' keys in their order.
  bool same_keys(std::span<const ShadowCacheLight> lights, jobs::ThreadPool* pool);
  // Fills stats_'s lag figures from lags_.
  void summarize_lags();

  uint64_t frame_ = 0;
  std::vector<LightState> states_;  // parallel to the previous plan's lights
  ShadowCacheStats stats_;

  // Working storage, kept so that a frame allocates nothing once grown.
  std::vector<LightState> matched_;
  KeyPlaces places_;  // for align_by_key
  struct KeyedLight {
    uint64_t key;
    uint32_t index;  // in `lights`
  };
  // choose_renders: every light by key (kept while the lights' keys are the same), and the dirty
  // lights by key when they are few.
  std::vector<KeyedLight> by_key_;
  std::vector<KeyedLight> dirty_by_key_;
  std::vector<KeyedLight> by_key_scratch_;
  // The dirty lights in key order, as staleness rank << 32 | index in `lights`; each piece's
  // views per rank bucket; the lights of the bucket where the budget runs out, ordered by rank.
  std::vector<uint64_t> order_;
  std::vector<uint64_t> piece_views_;
  std::vector<uint64_t> rest_;
  std::vector<uint64_t> order_scratch_;
  // choose_renders, per piece of lights: its dirty lights' views and the range of their
  // rendered_frame.
  struct DirtyTally {
    uint64_t views = 0;
    uint64_t oldest = UINT64_MAX;
    uint64_t newest = 0;
  };
  std::vector<DirtyTally> dirty_tallies_;
  std::vector<uint32_t> lags_;             // the due lights' lags (ShadowCacheStats)
  std::vector<uint32_t> lag_counts_;       // summarize_lags: the due lights per lag below counted_lags
  std::vector<uint32_t> long_lags_;        // and the longer lags, sorted
  std::vector<ShadowCacheStats> tallies_;  // plan's counts, per piece of lights
  std::vector<uint8_t> piece_flags_;       // same_keys: per piece of lights, whether its keys match
  jobs::KeepScratch keep_scratch_;
  std::vector<uint32_t> candidates_;  // lights tested against the caster boxes, then the dirty ones
  std::vector<glm::vec4> candidate_reach_;
  std::vector<uint8_t> candidate_met_;
  SpheresMeetingBoxes spheres_meeting_boxes_;
};

}  // namespace sg::shadows
