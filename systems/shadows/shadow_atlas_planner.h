// SPDX-License-Identifier: MIT
#pragma once
// Where every shadow map lives, frame after frame, under a memory budget.
//
// Shadow maps are square power-of-two tiles in "pages", the layers of one 2D depth-array image of
// page_size x page_size texels (D32: 4 bytes a texel). A 2D shadow (spot, directional, cylinder
// light) takes one tile; a point light takes six tiles of one size on one page, its cube faces.
// Each plan() decides every shadowed light's resolution and tiles:
//
// - Resolution: a light wants its importance rounded to a power of two (to the nearest one in
//   log2), clamped to [min_resolution, its cap], or its cap when pinned; the cap is page_size (page_size / 4
//   for cubes, so that six faces fit a page) and, when max_resolution is not 0, max_resolution rounded down
//   to a power of two (but never below min_resolution). Hysteresis: a light keeps last frame's wanted
//   resolution R while log2(importance) stays within 0.75 of log2(R), so it does not pop between
//   tiers when its importance hovers at a boundary.
// - Time (plan()'s lowered_tiers, from the time budget, ShadowTimeBudget): each light then wants
//   2^round(held - lowered_tiers) within [its quality floor (or min_resolution), what it gets],
//   where `held` follows log2 of what it gets (its importance, within its cap) with a backlash of
//   hysteresis_tiers. Importances that wobble by less change nothing, and the same lowered_tiers
//   always give the same resolutions, so a controller that steps back gets back where it was (a
//   hysteresis on the lowered resolution itself would take 1.5 tiers to undo a quarter tier's
//   step). Every map keeps in proportion to its light's size on screen, and the least important
//   lights reach their floor, and stop, first. A light that wants less than its floor anyway
//   keeps what it wants; pinned lights keep their cap. Under the redraw_cost policy
//   (shadow_time_policy.h) `held` also counts the tiers a light is spared for how seldom its map
//   is redrawn (record_redraws(), a rate over recent frames): the lowered tiers fall on the maps that
//   cost time.
// - Budget: the tiles must fit max_pages pages. When they do not, the least important light drops
//   one tier, then the next least important, and so on upward, pass after pass, first only lights
//   above their quality floor (down to it), then all of them; once every light is at
//   min_resolution the least important lose their shadow (resolution 0). It never fails,
//   however many lights. Where cube faces leave gaps a light may be demoted one step more than
//   strictly needed.
// - Persistence: a light whose resolution did not change keeps exactly its tiles (moved = false).
//   New lights and lights whose resolution changed get new tiles (moved = true); lights that are
//   no longer requested free theirs. The free space of a full atlas is in pieces: a light going
//   up that finds no free tile of its new size keeps its tiles, a new or lowered one takes the
//   largest free size below its own (AtlasStats::held_back_by_free_space). Only when not even
//   the smallest tile is free is everything repacked from scratch, largest first (which packs
//   power-of-two squares without gaps), and the lights whose tiles changed are moved.
//
// A moved light's map content is invalid: it must be rendered again this frame.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ecs/jobs/parallel_pieces.h"

#include "systems/shadows/budget_report.h"
#include "systems/shadows/schedule_steps.h"
#include "systems/shadows/shadow_atlas_pages.h"
#include "systems/shadows/shadow_time_policy.h"

namespace sg::shadows {

struct AtlasConfig {
  uint32_t page_size = 4096;  // texels, rounded down to a power of two
  uint32_t max_pages = 1;     // the budget: the caller derives it from MiB and device limits
  // The smallest tile, rounded up to a power of two and kept within [page_size / 1024, page_size]
  // (a page's quadtree has (page_size / min_resolution)^2 * 4/3 nodes of one byte). Below it a
  // light loses its shadow instead.
  uint32_t min_resolution = 32;

  friend bool operator==(const AtlasConfig&, const AtlasConfig&) = default;
};

struct ShadowRequest {
  uint64_t key = 0;             // the light's identity across frames (its entity); unique within a plan()
  bool cube = false;            // six faces on one page
  uint32_t max_resolution = 0;  // an upper bound on the resolution; 0: none of its own
  // The resolution it should have, in texels before rounding (e.g. the projected screen size of
  // its volume); the budget demotes the least important lights first.
  float importance = 0.0f;
  // The smallest resolution at which its shadow stays accurate (quality_floor); 0: none. The
  // budget takes every light down to its floor before it takes any light below its own.
  uint32_t quality_floor = 0;
  // Wants its cap whatever its importance (which still orders the budget's demotions).
  bool pinned = false;
  // Where the light's request stands from plan to plan, below plan()'s `slots`, one request a slot
  // (ShadowSchedule: its view's index among every light's views, in sight or not): a light is
  // found there without a lookup by key when the requests before it change. A slot out of that
  // range is looked up by key every plan.
  uint32_t slot = 0;
};

// What plan() gives a request; its tiles are ShadowAtlasPlanner::tiles_of's. Eight bytes: the
// plan writes one for every request each frame, and with the tiles in it (104 bytes) that pass
// moved 40 MB a frame at 100,000 lights and took as long on two threads as on one (the 2-core
// VM, 2026-12-04).
struct ShadowPlacement {
  uint32_t resolution = 0;  // 0: no shadow this frame
  bool moved = false;       // tiles differ from last frame's for this key: the map must be rendered
};

struct AtlasStats {
  uint32_t pages_used = 0;  // the highest page holding a tile, plus one
  uint64_t texels_used = 0;
  std::vector<std::pair<uint32_t, uint32_t>> lights_per_resolution;  // (resolution, lights), largest first
  uint32_t lights_without_shadow = 0;
  uint32_t demoted_by_budget = 0;  // shadowed at a lower resolution than they want
  uint32_t dropped_by_budget = 0;  // without shadow because of the budget
  uint32_t demoted_by_time = 0;    // wanting less than their importance asks (lowered_tiers)
  // Above their quality floor, so that more lowered tiers would lower them, and (redraw_cost)
  // redrawn often enough that it would save time.
  uint32_t lowerable_by_time = 0;
  // Lights placed in the previous plan too whose resolution differs now (a shadow gained or
  // lost included): the tiers that changed, which the time budget's hysteresis keeps few.
  uint32_t lights_changed_tier = 0;
  uint32_t lights_retiled = 0;  // given tiles other than last plan's (new lights too): maps to draw anew
  // Placed below the resolution the budget gave them: the free tiles were smaller (a light going
  // up keeps its tiles, a new or lowered light takes a smaller tile). Counted in demoted_by_budget.
  uint32_t held_back_by_free_space = 0;
  bool repacked = false;  // every tile placed anew (lights_retiled: most lights)
};

class ShadowAtlasPlanner {
 public:
  explicit ShadowAtlasPlanner(AtlasConfig config, ShadowTimePolicy policy = ShadowTimePolicy::redraw_cost);

  // Fills out[i] for requests[i]; out.size() must equal requests.size(). Requests need not come
  // in the same order every frame. A key requested twice in one plan() gets a shadow only once.
  // With `pool`, the per-light passes that need no shared state run on it (same result).
  // `lowered_tiers` >= 0: the time budget's (see above); 0: none. With `slots` > 0 the requests'
  // slots hold their lights from plan to plan; 0: each request's place is its slot. `clock`, when
  // given, times the match, budget, tiles and placements steps.
  void plan(std::span<const ShadowRequest> requests, std::span<ShadowPlacement> out,
            jobs::ThreadPool* pool = nullptr, float lowered_tiers = 0.0f, size_t slots = 0,
            StepClock* clock = nullptr);
  // What became of the last plan()'s requests' maps this frame, per request: redraws[i] is
  // map_redrawn when request i's map was drawn for a change of its light or its casters,
  // map_kept when it was kept, no_redraw_sample when it tells nothing of the rate (no tile,
  // or drawn because its tiles are new). Each light's redraw rate follows them.
  enum RedrawSample : uint8_t { map_kept, map_redrawn, no_redraw_sample };
  void record_redraws(std::span<const uint8_t> redraws, jobs::ThreadPool* pool = nullptr);
  // Request i's tiles as the last plan() placed them: [0] for a 2D map; +X, -X, +Y, -Y, +Z, -Z
  // faces for a cube. Only where its placement's resolution is above 0, until the next plan().
  const std::array<AtlasTile, 6>& tiles_of(size_t request) const {
    return light_tiles_[light_of_request_[request]];
  }
  // The last plan()'s.
  const AtlasStats& stats() const { return stats_; }
  // A line for the log when the budget's effect (lights demoted or dropped) differs from the last
  // line's, at most one every budget_message_interval plan() calls, summarising; else nullopt.
  std::optional<std::string> take_budget_message();
  // Takes effect at the next plan(), which repacks every tile (tiles may move).
  void set_config(AtlasConfig config);
  const AtlasConfig& config() const { return config_; }

  static constexpr uint64_t budget_message_interval = 60;
  // How far log2(importance) may stray from log2 of the resolution a light has before it changes.
  static constexpr float hysteresis_tiers = 0.75f;

 private:
  // What a plan's passes over every light read and write, in 48 bytes. Its tiles (96 bytes) are
  // apart, in light_tiles_, written where they change and read where a view takes its map: with
  // them inside, each of those passes moved 152 bytes a light, and they wait on memory.
  struct Light {
    uint64_t key = 0;
    uint64_t requested_in_plan = 0;
    uint64_t placed_in_plan = 0;  // the last plan that placed it; 0: none (plans count from 1)
    uint32_t full = 0;            // what its importance asks, after hysteresis; 0: cannot have a shadow
    uint32_t wanted = 0;          // full lowered by the time budget
    float held = 0.0f;            // log2 of what it gets, with a backlash (see the header)
    float redraw_rate = 1.0f;     // the share of recent frames its map was redrawn in (record_redraws())
    uint32_t resolution = 0;      // as placed, in light_tiles_
    bool cube = false;
    bool lowerable = false;  // wanted is above its quality floor
  };
  struct BudgetEffect {
    uint32_t demoted = 0;
    uint32_t dropped = 0;
    friend bool operator==(const BudgetEffect&, const BudgetEffect&) = default;
  };

  uint32_t tier_count() const;
  uint32_t tier_of(uint32_t resolution) const;
  // A light's full and wanted resolutions and its held tiers, from last plan's (0, nullopt: none),
  // its redraw rate and lowered_tiers.
  struct Wanted {
    uint32_t full = 0;
    uint32_t lowered = 0;
    bool lowerable = false;
    float held = 0.0f;
  };
  Wanted wanted_resolution(const ShadowRequest& request, uint32_t previous_full,
                           std::optional<float> previous_held, float redraw_rate, float lowered_tiers) const;
  void match_lights(std::span<const ShadowRequest> requests, jobs::ThreadPool* pool, float lowered_tiers);
  // Request i's slot in the current plan().
  uint32_t slot_of(std::span<const ShadowRequest> requests, size_t i) const {
    return slots_ > 0 ? requests[i].slot : static_cast<uint32_t>(i);
  }
  void release_lights_not_requested();
  void fit_budget(std::span<const ShadowRequest> requests, jobs::ThreadPool* pool);
  // What fit_budget does to its lights: halve them down to their quality floor, then to
  // min_resolution, then drop them.
  enum class BudgetStage { to_quality_floor, to_smallest_tier, dropping };
  // The resolution below which `stage` does not halve the request (dropping ignores it).
  uint32_t stage_floor(const ShadowRequest& request, BudgetStage stage) const;
  // What taking one light in `stage` saves (0: it is at its floor).
  uint64_t step_saving(const ShadowRequest& request, uint32_t resolution, BudgetStage stage) const;
  // Takes the pass's lights not taken yet (not marked in by_importance_), least important first,
  // until they saved `room` or none is left; returns what they saved (0: none was demoted).
  uint64_t take_least_important(std::span<const ShadowRequest> requests, BudgetStage stage, uint64_t room,
                                jobs::ThreadPool* pool);
  // What the lights one piece of take_least_important took changed, the lights per tier (2D
  // maps, cubes) among it; fit_budget counts its lights per tier in them too, as changes from
  // none.
  static constexpr size_t max_tiers = 11;  // page_size / min_resolution <= 1024
  struct StepTally {
    uint64_t saved = 0;
    size_t taken = 0;
    std::array<std::array<int64_t, max_tiers>, 2> tier_changes{};
  };
  StepTally summed_step_tallies() const;  // over step_tallies_' pieces
  uint64_t texels_that_do_not_fit() const;
  // fit_budget's whole passes of a halving `stage` at once (see there): what they saved, and
  // whether a pass would demote no light, which ends the stage.
  struct WholePasses {
    uint64_t saved = 0;
    bool stage_done = false;
  };
  WholePasses whole_passes(std::span<const ShadowRequest> requests, BudgetStage stage, uint64_t room,
                           jobs::ThreadPool* pool);
  // Request indices ordered by decreasing resolution, cubes before 2D maps of the same size.
  std::vector<uint32_t> largest_first(std::span<const ShadowRequest> requests,
                                      std::span<const uint32_t> indices) const;
  // Request i's light (which it has) keeps its resolution and kind, and so its tiles, before the
  // plan places the changed lights; after it, until the light's tiles are written, unless the
  // atlas was repacked.
  bool keeps_tiles(std::span<const ShadowRequest> requests, size_t i) const;
  // Request i's light has tiles and goes up a size: it keeps them unless the larger ones are free.
  bool grows(std::span<const ShadowRequest> requests, uint32_t i) const;
  // False when a light found no free tile even at min_resolution: the plan must repack. Counts
  // the lights it holds back into stats_.
  bool place_changed_lights(std::span<const ShadowRequest> requests, std::span<const uint32_t> changed);
  void repack(std::span<const ShadowRequest> requests);
  // What a plan() counts for its stats, per piece of requests on the pool, summed after.
  struct Tally {
    uint32_t without_shadow = 0;
    uint32_t dropped = 0;
    uint32_t demoted = 0;
    uint32_t demoted_by_time = 0;
    uint32_t lowerable_by_time = 0;
    uint32_t changed_tier = 0;
    uint32_t retiled = 0;
    uint64_t texels = 0;
    std::array<uint32_t, max_tiers> lights_per_tier{};
  };
  // Counts one request: `light` its light (null for a key's second request) as placed.
  void count_into(Tally& tally, const Light* light, uint32_t resolution) const;
  void update_stats();

  AtlasConfig config_;
  ShadowTimePolicy policy_;
  ShadowAtlasPages pages_;
  bool repack_pending_ = false;  // set_config() made the allocator new
  uint64_t plans_ = 0;

  std::vector<Light> lights_;
  std::vector<std::array<AtlasTile, 6>> light_tiles_;  // lights_[i]'s tiles as placed
  std::vector<uint32_t> unused_lights_;
  std::unordered_map<uint64_t, uint32_t> light_of_key_;
  size_t lights_requested_ = 0;  // by the current plan(): its requests less the keys' second ones

  // Per request of the current plan(), kept to reuse their storage.
  static constexpr uint32_t no_light = ~0u;
  std::vector<uint32_t> light_of_request_;
  // Per slot, the light the last plan() gave its request (no_light: none), and the same for the
  // current plan(), swapped at its end.
  std::vector<uint32_t> light_of_slot_;
  std::vector<uint32_t> next_light_of_slot_;
  size_t slots_ = 0;  // the current plan()'s `slots`
  std::vector<uint32_t> resolution_;
  std::vector<uint32_t> unmatched_;  // requests not matched by their place in the last plan
  std::vector<uint32_t> retiled_;    // by rank: the requests whose light changed resolution or kind
  jobs::KeepScratch keep_scratch_;
  // Per request whose light changed resolution or kind (retiled_), its new tiles.
  std::vector<std::array<AtlasTile, 6>> tiles_;
  // Per tier (0: page_size, 1: half that, ...): the 2D maps and cubes the budget holds.
  std::vector<uint64_t> maps_per_tier_;
  std::vector<uint64_t> cubes_per_tier_;
  // fit_budget's requests with a shadow (importance bits << 32 | request index), unordered: taken
  // least important first, ties by key, so that the order does not depend on the order of requests.
  std::vector<uint64_t> by_importance_;
  size_t taken_in_pass_ = 0;               // how many the pass took
  std::vector<uint64_t> piece_savings_;    // take_least_important's histograms, one a piece
  std::vector<uint32_t> boundary_lights_;  // and its boundary bucket's places in by_importance_
  std::vector<StepTally> step_tallies_;
  std::vector<uint64_t> lights_by_tier_and_halvings_;  // whole_passes' counts
  std::vector<uint64_t> piece_counts_;                 // and each piece's
  std::vector<Tally> tallies_;

  AtlasStats stats_;
  BudgetReport<BudgetEffect> budget_report_{budget_message_interval};
};

}  // namespace sg::shadows
