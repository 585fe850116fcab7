// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_atlas_planner.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>

#include "ecs/jobs/parallel_pieces.h"

namespace sg::shadows {
namespace {

// Requests a piece of the pool's work handles: a thousand lights keep 16 threads busy.
constexpr size_t lights_per_piece = 64;
// Requests fit_budget's passes count on a thread: each piece's counts are summed after. 80,000
// requests are 78 pieces, five rounds of 16 threads (20 pieces of 4096 were two rounds, the
// second a quarter full).
constexpr size_t requests_per_count = 1024;

// Power-of-two sizes, and a quadtree per page of at most 1024 x 1024 leaves.
AtlasConfig sanitized(AtlasConfig config) {
  config.page_size = std::bit_floor(std::max(config.page_size, 1u));
  config.min_resolution = std::bit_ceil(std::clamp(config.min_resolution, 1u, config.page_size));
  config.min_resolution = std::max(config.min_resolution, std::max(config.page_size >> 10, 1u));
  return config;
}

uint32_t tile_count(bool cube) { return cube ? 6 : 1; }
uint64_t area(uint32_t side) { return uint64_t(side) * side; }
// fit_budget's entries are importance bits << 32 | request index. Importances are not negative,
// so the float's sign bit marks the lights the current pass took.
constexpr uint64_t taken_bit = uint64_t{1} << 63;
// Importance as bits that sort as the floats do: NaN and negative importances count as 0.
uint64_t importance_bits(const ShadowRequest& request) {
  return std::bit_cast<uint32_t>(request.importance > 0.0f ? request.importance : 0.0f);
}

}  // namespace

ShadowAtlasPlanner::ShadowAtlasPlanner(AtlasConfig config, ShadowTimePolicy policy)
    : config_(sanitized(config)),
      policy_(policy),
      pages_(config_.page_size, config_.min_resolution, config_.max_pages) {}

void ShadowAtlasPlanner::set_config(AtlasConfig config) {
  const AtlasConfig next = sanitized(config);
  if (next == config_) return;
  config_ = next;
  pages_ = ShadowAtlasPages(config_.page_size, config_.min_resolution, config_.max_pages);
  repack_pending_ = true;
}

uint32_t ShadowAtlasPlanner::tier_count() const {
  return uint32_t(std::countr_zero(config_.page_size / config_.min_resolution)) + 1;
}

uint32_t ShadowAtlasPlanner::tier_of(uint32_t resolution) const {
  return uint32_t(std::countr_zero(config_.page_size) - std::countr_zero(resolution));  // powers of two
}

ShadowAtlasPlanner::Wanted ShadowAtlasPlanner::wanted_resolution(const ShadowRequest& request,
                                                                 uint32_t previous_full,
                                                                 std::optional<float> previous_held,
                                                                 float redraw_rate,
                                                                 float lowered_tiers) const {
  uint32_t cap = request.cube ? config_.page_size / 4 : config_.page_size;
  if (cap < config_.min_resolution) return {};  // six faces of the smallest tile do not fit a page
  if (request.max_resolution != 0) {
    cap = std::clamp(std::bit_floor(request.max_resolution), config_.min_resolution, cap);
  }
  if (request.pinned) return {cap, cap, false, 0.0f};
  // NaN, negative and tiny importances want the smallest tile, infinite ones the largest.
  const float importance = std::clamp(request.importance > 1.0f ? request.importance : 1.0f, 1.0f, 0x1p31f);
  const float tiers = std::log2(importance);
  uint32_t full = std::clamp(1u << uint32_t(std::round(tiers)), config_.min_resolution, cap);
  if (previous_full >= config_.min_resolution && previous_full <= cap &&
      std::abs(tiers - float(std::countr_zero(previous_full))) <= hysteresis_tiers) {
    full = previous_full;
  }
  // Held from what the light gets: a light capped below its importance (or inside the camera's
  // view of it) drops with the first lowered tier too; and from the tiers its redraw rate spares.
  const float got = std::min(tiers, float(std::countr_zero(cap))) + spared_tiers(policy_, redraw_rate);
  const float held =
      previous_held ? std::clamp(*previous_held, got - hysteresis_tiers, got + hysteresis_tiers) : got;
  const uint32_t floor =
      std::min(full, std::bit_ceil(std::max(config_.min_resolution, request.quality_floor)));
  const bool saves_time = lowering_saves_time(policy_, redraw_rate);
  if (lowered_tiers <= 0.0f) return {full, full, full > floor && saves_time, held};
  const float lowered_log2 = std::clamp(held - lowered_tiers, 0.0f, 31.0f);
  const uint32_t lowered = std::clamp(1u << uint32_t(std::round(lowered_log2)), floor, full);
  return {full, lowered, lowered > floor && saves_time, held};
}

void ShadowAtlasPlanner::plan(std::span<const ShadowRequest> requests, std::span<ShadowPlacement> out,
                              jobs::ThreadPool* pool, float lowered_tiers, size_t slots, StepClock* clock) {
  assert(out.size() == requests.size());
  ++plans_;
  slots_ = slots;
  match_lights(requests, pool, lowered_tiers);
  lap(clock, ScheduleStep::match);
  release_lights_not_requested();
  fit_budget(requests, pool);
  lap(clock, ScheduleStep::budget);

  // Lights whose resolution or kind changed need new tiles (tiles_); the others keep theirs.
  // Which did is found on the pool. Lights going down or out give their tiles back here; a light
  // going up, when it is placed (grows()).
  tiles_.resize(requests.size());
  retiled_.resize(requests.size());
  const size_t retiled_count = jobs::keep_in_pieces(
      pool, requests.size(), lights_per_piece, keep_scratch_,
      [&](size_t i) { return light_of_request_[i] != no_light && !keeps_tiles(requests, i); },
      [&](size_t i, size_t rank) { retiled_[rank] = static_cast<uint32_t>(i); });
  size_t changed_count = 0;  // retiled_ keeps, in front, those that still have a shadow
  for (size_t r = 0; r < retiled_count; ++r) {
    const uint32_t i = retiled_[r];
    const Light& light = lights_[light_of_request_[i]];
    if (light.resolution > 0 && !repack_pending_ && !grows(requests, i)) {
      for (uint32_t k = 0; k < tile_count(light.cube); ++k)
        pages_.free(light_tiles_[light_of_request_[i]][k]);
    }
    if (resolution_[i] > 0) retiled_[changed_count++] = i;
  }
  const std::span<const uint32_t> changed(retiled_.data(), changed_count);
  stats_.held_back_by_free_space = 0;  // counted by place_changed_lights
  stats_.repacked = repack_pending_ || !place_changed_lights(requests, changed);
  if (stats_.repacked) repack(requests);
  repack_pending_ = false;
  lap(clock, ScheduleStep::tiles);

  // Each request writes its placement and its own light (a key's second request has none), and
  // counts into its piece's tally.
  tallies_.assign(jobs::piece_count(requests.size(), lights_per_piece), Tally{});
  jobs::run_in_pieces(pool, requests.size(), lights_per_piece, [&](size_t begin, size_t end) {
    Tally& tally = tallies_[begin / lights_per_piece];
    for (size_t i = begin; i < end; ++i) {
      if (const uint32_t slot = slot_of(requests, i); slot < next_light_of_slot_.size()) {
        next_light_of_slot_[slot] = light_of_request_[i];
      }
      const uint32_t index = light_of_request_[i];
      if (index == no_light) {
        out[i] = {};
        count_into(tally, nullptr, 0);
        continue;
      }
      Light& own = lights_[index];
      std::array<AtlasTile, 6>& own_tiles = light_tiles_[index];
      const uint32_t resolution = resolution_[i];
      // A light that kept its resolution and kind kept its tiles, unless the atlas was repacked;
      // the others' are in tiles_.
      const bool kept = !stats_.repacked && keeps_tiles(requests, i);
      const bool moved =
          resolution > 0 && !kept &&
          (resolution != own.resolution || requests[i].cube != own.cube || tiles_[i] != own_tiles);
      out[i] = {resolution, moved};
      const bool placed_last_plan = own.placed_in_plan != 0 && own.placed_in_plan + 1 == plans_;
      if (placed_last_plan && resolution != own.resolution) ++tally.changed_tier;
      tally.retiled += moved ? 1 : 0;
      own.placed_in_plan = plans_;
      own.resolution = resolution;
      own.cube = requests[i].cube;
      if (!kept && resolution > 0) own_tiles = tiles_[i];
      count_into(tally, &own, resolution);
    }
  });
  light_of_slot_.swap(next_light_of_slot_);
  update_stats();
  lap(clock, ScheduleStep::placements);
}

void ShadowAtlasPlanner::record_redraws(std::span<const uint8_t> redraws, jobs::ThreadPool* pool) {
  assert(redraws.size() <= light_of_request_.size());
  jobs::run_in_pieces(pool, redraws.size(), lights_per_piece, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      if (redraws[i] == no_redraw_sample || light_of_request_[i] == no_light) continue;
      float& rate = lights_[light_of_request_[i]].redraw_rate;
      rate += (float(redraws[i] == map_redrawn) - rate) * redraw_rate_weight;
    }
  });
}

uint32_t ShadowAtlasPlanner::stage_floor(const ShadowRequest& request, BudgetStage stage) const {
  return stage == BudgetStage::to_quality_floor ? std::max(config_.min_resolution, request.quality_floor)
                                                : config_.min_resolution;
}

uint64_t ShadowAtlasPlanner::step_saving(const ShadowRequest& request, uint32_t resolution,
                                         BudgetStage stage) const {
  const uint64_t tiles = tile_count(request.cube);
  if (stage == BudgetStage::dropping) return tiles * area(resolution);
  return resolution / 2 < stage_floor(request, stage) ? 0 : tiles * (area(resolution) - area(resolution / 2));
}

// What walking the pass light by light would take, without ordering what it walks: a histogram
// of the savings over the top 16 bits of the importances' bits (a float's sign, exponent and 7
// bits of mantissa) finds the bucket where they reach `room`; the lights below it are all
// taken, in any order and on the pool, and only that bucket's are sorted and walked. Sorting
// the 52,000 lights a pass walked from the street camera (100,000 lights, a 2 GiB atlas) and
// walking them one by one took 12.9 ms a frame on an H200 host (2026-12-03).
uint64_t ShadowAtlasPlanner::take_least_important(std::span<const ShadowRequest> requests, BudgetStage stage,
                                                  uint64_t room, jobs::ThreadPool* pool) {
  const auto bucket = [](uint64_t value) { return size_t(value >> 48); };
  // The histogram in two passes on the pool, each of 256 buckets a piece: the top 8 bits, then
  // the low 8 within the top bucket where the savings reach the room. On one thread, one pass of
  // 65,536 buckets took 0.34 ms of an H200 host's frame at 100,000 lights (2026-12-04).
  constexpr size_t digits = 256;  // buckets of a pass; digit() gives `digits` for none
  const size_t pieces = jobs::piece_count(by_importance_.size(), requests_per_count);
  const auto savings_by = [&](const auto& digit) {
    piece_savings_.assign(pieces * digits, 0);
    jobs::run_in_pieces(pool, by_importance_.size(), requests_per_count, [&](size_t begin, size_t end) {
      uint64_t* savings = &piece_savings_[begin / requests_per_count * digits];
      for (size_t k = begin; k < end; ++k) {
        const uint64_t value = by_importance_[k];
        const size_t d = (value & taken_bit) != 0 ? digits : digit(value);
        if (d == digits) continue;
        const uint32_t i = uint32_t(value);
        savings[d] += step_saving(requests[i], resolution_[i], stage);
      }
    });
    std::array<uint64_t, digits> sums{};
    for (size_t p = 0; p < pieces; ++p) {
      for (size_t d = 0; d < digits; ++d) sums[d] += piece_savings_[p * digits + d];
    }
    return sums;
  };
  uint64_t saved = 0;
  const auto first_reaching_room = [&](const std::array<uint64_t, digits>& savings) {
    size_t d = 0;
    for (; d < savings.size(); ++d) {
      if (saved + savings[d] >= room) break;
      saved += savings[d];
    }
    return d;
  };
  size_t boundary = size_t{1} << 16;  // the first bucket whose savings reach the room, or past the last
  const size_t top = first_reaching_room(savings_by([](uint64_t value) { return size_t(value >> 56); }));
  if (top < digits) {
    boundary = top << 8 | first_reaching_room(savings_by([top](uint64_t value) {
                 return value >> 56 == top ? size_t(value >> 48) & 255 : digits;
               }));
  }
  // Each piece takes its lights below the boundary and counts what that changed; the boundary
  // bucket's are listed.
  const auto take = [&](uint64_t& value, StepTally& tally) {
    value |= taken_bit;
    ++tally.taken;
    const uint32_t i = uint32_t(value);
    uint32_t& resolution = resolution_[i];
    const uint64_t saving = step_saving(requests[i], resolution, stage);
    if (saving == 0) return;
    std::array<int64_t, max_tiers>& per_tier = tally.tier_changes[requests[i].cube ? 1 : 0];
    --per_tier[tier_of(resolution)];
    resolution = stage == BudgetStage::dropping ? 0 : resolution / 2;
    if (resolution > 0) ++per_tier[tier_of(resolution)];
    tally.saved += saving;
  };
  step_tallies_.assign(pieces, StepTally{});
  boundary_lights_.resize(by_importance_.size());
  boundary_lights_.resize(jobs::keep_in_pieces(
      pool, by_importance_.size(), requests_per_count, keep_scratch_,
      [&](size_t k) {
        uint64_t& value = by_importance_[k];
        if ((value & taken_bit) != 0 || bucket(value) > boundary) return false;
        if (bucket(value) == boundary) return true;
        take(value, step_tallies_[k / requests_per_count]);
        return false;
      },
      [&](size_t k, size_t rank) { boundary_lights_[rank] = uint32_t(k); }));
  StepTally total = summed_step_tallies();
  // The boundary bucket's in order, ties by key (so that the order does not depend on the order
  // of requests), until the room is saved.
  std::sort(boundary_lights_.begin(), boundary_lights_.end(), [&](uint32_t a, uint32_t b) {
    const uint64_t x = by_importance_[a];
    const uint64_t y = by_importance_[b];
    return x >> 32 != y >> 32 ? x >> 32 < y >> 32 : requests[uint32_t(x)].key < requests[uint32_t(y)].key;
  });
  for (const uint32_t k : boundary_lights_) {
    if (total.saved >= room) break;
    take(by_importance_[k], total);
  }
  for (uint32_t tier = 0; tier < tier_count(); ++tier) {
    maps_per_tier_[tier] = uint64_t(int64_t(maps_per_tier_[tier]) + total.tier_changes[0][tier]);
    cubes_per_tier_[tier] = uint64_t(int64_t(cubes_per_tier_[tier]) + total.tier_changes[1][tier]);
  }
  taken_in_pass_ += total.taken;
  return total.saved;
}

void ShadowAtlasPlanner::match_lights(std::span<const ShadowRequest> requests, jobs::ThreadPool* pool,
                                      float lowered_tiers) {
  const size_t slot_count = slots_ > 0 ? slots_ : requests.size();
  light_of_slot_.resize(slot_count, no_light);
  next_light_of_slot_.assign(slot_count, no_light);
  light_of_request_.resize(requests.size());
  resolution_.assign(requests.size(), 0);
  const auto take = [&](uint32_t i, uint32_t index) {
    Light& light = lights_[index];
    light_of_request_[i] = index;
    light.requested_in_plan = plans_;
    const bool same_kind = requests[i].cube == light.cube;
    const Wanted wanted =
        wanted_resolution(requests[i], same_kind ? light.full : 0,
                          same_kind && light.full > 0 ? std::optional(light.held) : std::nullopt,
                          light.redraw_rate, lowered_tiers);
    light.full = wanted.full;
    light.held = wanted.held;
    light.wanted = wanted.lowered;
    light.lowerable = wanted.lowerable;
    resolution_[i] = light.wanted;
  };
  // Usually a request's slot holds the light its request had in the last plan, found there
  // without a lookup by key, on the pool (the last plan gave each light to one request, so no two
  // requests take the same light here). The rest are listed for a lookup by key after, on one
  // thread. Matched by their places among the requests instead, 16,000 of 79,000 requests a frame
  // missed at 100,000 lights from the street camera (a light leaving or entering sight moves every
  // later request), and their lookups took a millisecond of an H200 host's frame (2026-12-04).
  unmatched_.resize(requests.size());
  const size_t unmatched_count = jobs::keep_in_pieces(
      pool, requests.size(), lights_per_piece, keep_scratch_,
      [&](size_t i) {
        const uint32_t slot = slot_of(requests, i);
        const uint32_t index = slot < slot_count ? light_of_slot_[slot] : no_light;
        if (index == no_light || lights_[index].key != requests[i].key ||
            lights_[index].requested_in_plan == 0) {
          return true;
        }
        take(static_cast<uint32_t>(i), index);
        return false;
      },
      [&](size_t i, size_t rank) { unmatched_[rank] = static_cast<uint32_t>(i); });
  lights_requested_ = requests.size();
  for (size_t u = 0; u < unmatched_count; ++u) {
    const uint32_t i = unmatched_[u];
    const ShadowRequest& request = requests[i];
    const auto [found, inserted] = light_of_key_.try_emplace(request.key, 0);
    if (inserted) {
      if (unused_lights_.empty()) {
        found->second = uint32_t(lights_.size());
        lights_.emplace_back();
        light_tiles_.emplace_back();
      } else {
        found->second = unused_lights_.back();
        unused_lights_.pop_back();
        lights_[found->second] = {};
        light_tiles_[found->second] = {};
      }
      lights_[found->second].key = request.key;
    }
    if (lights_[found->second].requested_in_plan == plans_) {  // the key's second request
      light_of_request_[i] = no_light;
      --lights_requested_;
      continue;
    }
    take(i, found->second);
  }
}

void ShadowAtlasPlanner::release_lights_not_requested() {
  // Each request took a light of its own, so when as many lights are in use as were requested,
  // none is left to release; the usual frame skips reading every light, each written by another
  // core in the last plan.
  if (lights_requested_ == lights_.size() - unused_lights_.size()) return;
  for (uint32_t index = 0; index < lights_.size(); ++index) {
    Light& light = lights_[index];
    // requested_in_plan is 0 for unused entries: plans count from 1.
    if (light.requested_in_plan == 0 || light.requested_in_plan == plans_) continue;
    if (light.resolution > 0 && !repack_pending_) {
      for (uint32_t k = 0; k < tile_count(light.cube); ++k) pages_.free(light_tiles_[index][k]);
    }
    light_of_key_.erase(light.key);
    light = {};
    unused_lights_.push_back(index);
  }
}

ShadowAtlasPlanner::StepTally ShadowAtlasPlanner::summed_step_tallies() const {
  StepTally total;
  for (const StepTally& tally : step_tallies_) {
    total.saved += tally.saved;
    total.taken += tally.taken;
    for (size_t cube = 0; cube < 2; ++cube) {
      for (size_t tier = 0; tier < max_tiers; ++tier)
        total.tier_changes[cube][tier] += tally.tier_changes[cube][tier];
    }
  }
  return total;
}

void ShadowAtlasPlanner::fit_budget(std::span<const ShadowRequest> requests, jobs::ThreadPool* pool) {
  // The lights per kind and tier (each piece's counted as changes from none), and the requests
  // with a shadow listed, unordered, in one pass on the pool: on one thread the two took 0.56 ms
  // of an H200 host's frame at 100,000 lights (2026-12-04).
  step_tallies_.assign(jobs::piece_count(requests.size(), requests_per_count), StepTally{});
  by_importance_.resize(requests.size());
  by_importance_.resize(jobs::keep_in_pieces(
      pool, requests.size(), requests_per_count, keep_scratch_,
      [&](size_t i) {
        if (resolution_[i] == 0) return false;
        ++step_tallies_[i / requests_per_count]
              .tier_changes[requests[i].cube ? 1 : 0][tier_of(resolution_[i])];
        return true;
      },
      [&](size_t i, size_t rank) { by_importance_[rank] = importance_bits(requests[i]) << 32 | i; }));
  const StepTally counted = summed_step_tallies();
  maps_per_tier_.assign(tier_count(), 0);
  cubes_per_tier_.assign(tier_count(), 0);
  for (uint32_t tier = 0; tier < tier_count(); ++tier) {
    maps_per_tier_[tier] = uint64_t(counted.tier_changes[0][tier]);
    cubes_per_tier_[tier] = uint64_t(counted.tier_changes[1][tier]);
  }
  uint64_t excess = texels_that_do_not_fit();
  if (excess == 0) return;

  // Passes from the least important light upward, each demoting every light above its floor by
  // one tier: the quality floor while any light is above it, then the smallest tier; once a pass
  // finds none, lights are dropped from the least important upward.
  // Whole passes that save less than what is still to be saved are applied at once from counts
  // (whole_passes); a pass that would save that much takes lights until it has
  // (take_least_important).
  BudgetStage stage = BudgetStage::to_quality_floor;
  taken_in_pass_ = 0;  // listed, none is marked taken
  bool demoted_in_pass = false;
  bool passes_counted = false;  // whole_passes ran where this pass begins
  const auto next_stage = [&] {
    stage = stage == BudgetStage::to_quality_floor ? BudgetStage::to_smallest_tier : BudgetStage::dropping;
  };
  // Texels one more step (lights of a pass, or whole passes) saves, `room` being what is still
  // to save; 0 when every light is dropped.
  const auto take_one_step = [&](uint64_t room) -> uint64_t {
    for (;;) {
      if (taken_in_pass_ == 0 && !passes_counted && stage != BudgetStage::dropping) {
        passes_counted = true;
        const WholePasses passes = whole_passes(requests, stage, room, pool);
        if (passes.stage_done) {
          next_stage();
          passes_counted = false;
        }
        if (passes.saved > 0) return passes.saved;
        continue;
      }
      if (taken_in_pass_ == by_importance_.size()) {
        if (stage == BudgetStage::dropping) return 0;
        if (!demoted_in_pass) next_stage();
        demoted_in_pass = false;
        taken_in_pass_ = 0;
        for (uint64_t& value : by_importance_) value &= ~taken_bit;
        passes_counted = false;
        continue;
      }
      const uint64_t saved = take_least_important(requests, stage, room, pool);
      demoted_in_pass = demoted_in_pass || saved > 0;
      if (saved > 0) return saved;
    }
  };
  // Packing is checked only once the steps have saved the area that did not fit, so a plan()
  // packs a few times, not once a light.
  while (excess > 0) {
    for (uint64_t saved = 0; saved < excess;) {
      const uint64_t step = take_one_step(excess - saved);
      if (step == 0) return;
      saved += step;
    }
    excess = texels_that_do_not_fit();
  }
}

// A pass halves every light above its floor, so after p passes a light of resolution r that can
// halve h times before reaching its floor has r >> min(p, h), and a pass's saving is a sum over
// the lights counted by kind, tier and h: a few hundred counts instead of a walk over every light
// in importance order. With 100,000 lights the walks were ten passes over scattered requests a
// frame, half of what scheduling them took (9.5 of 18.6 ms of the atlas plan on the 2-core VM
// with two threads, tools/light-bench, 2026-12-03).
ShadowAtlasPlanner::WholePasses ShadowAtlasPlanner::whole_passes(std::span<const ShadowRequest> requests,
                                                                 BudgetStage stage, uint64_t room,
                                                                 jobs::ThreadPool* pool) {
  const uint32_t tiers = tier_count();
  const auto halvings = [&](uint32_t i) {
    const uint32_t floor = std::bit_ceil(stage_floor(requests[i], stage));
    return resolution_[i] > floor ? uint32_t(std::countr_zero(resolution_[i]) - std::countr_zero(floor)) : 0u;
  };
  // Counted in pieces on the pool, each into counts of its own, then summed: 2 ms a frame on one
  // thread of the 2-core VM with 77,000 requests (2026-12-03).
  const size_t per_piece = size_t{2} * tiers * tiers;  // [(cube * tiers + tier) * tiers + h]
  const size_t pieces = jobs::piece_count(requests.size(), requests_per_count);
  piece_counts_.assign(pieces * per_piece, 0);
  jobs::run_in_pieces(pool, requests.size(), requests_per_count, [&](size_t begin, size_t end) {
    uint64_t* counts = &piece_counts_[begin / requests_per_count * per_piece];
    for (size_t i = begin; i < end; ++i) {
      if (resolution_[i] == 0) continue;
      ++counts[((requests[i].cube ? tiers : 0) + tier_of(resolution_[i])) * tiers + halvings(uint32_t(i))];
    }
  });
  std::vector<uint64_t>& counts = lights_by_tier_and_halvings_;
  counts.assign(per_piece, 0);
  for (size_t p = 0; p < pieces; ++p) {
    for (size_t k = 0; k < per_piece; ++k) counts[k] += piece_counts_[p * per_piece + k];
  }
  const auto pass_saving = [&](uint32_t pass) {  // of pass number `pass` (from 1)
    uint64_t saving = 0;
    for (uint32_t cube = 0; cube < 2; ++cube) {
      for (uint32_t tier = 0; tier < tiers; ++tier) {
        const uint32_t side = config_.page_size >> (tier + pass - 1);
        for (uint32_t h = pass; h < tiers; ++h) {
          saving += counts[(cube * tiers + tier) * tiers + h] * tile_count(cube != 0) *
                    (area(side) - area(side / 2));
        }
      }
    }
    return saving;
  };
  WholePasses done;
  uint32_t passes = 0;
  for (;;) {
    const uint64_t saving = pass_saving(passes + 1);
    if (saving == 0) {
      done.stage_done = true;
      break;
    }
    if (done.saved + saving >= room) break;
    done.saved += saving;
    ++passes;
  }
  if (passes == 0) return done;
  jobs::run_in_pieces(pool, requests.size(), requests_per_count, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      if (resolution_[i] > 0) resolution_[i] >>= std::min(passes, halvings(uint32_t(i)));
    }
  });
  std::fill(maps_per_tier_.begin(), maps_per_tier_.end(), 0);
  std::fill(cubes_per_tier_.begin(), cubes_per_tier_.end(), 0);
  // A light of tier t halves at most tiers - 1 - t times (its floor is min_resolution or more).
  for (uint32_t cube = 0; cube < 2; ++cube) {
    for (uint32_t tier = 0; tier < tiers; ++tier) {
      for (uint32_t h = 0; tier + h < tiers; ++h) {
        (cube != 0 ? cubes_per_tier_ : maps_per_tier_)[tier + std::min(passes, h)] +=
            counts[(cube * tiers + tier) * tiers + h];
      }
    }
  }
  return done;
}

uint64_t ShadowAtlasPlanner::texels_that_do_not_fit() const {
  // The repack's packing, counted rather than done: largest tier first, cubes before 2D maps,
  // each on the lowest page with room. Power-of-two squares packed largest first leave no gaps,
  // so a page's room is its free area, here in tiles of the current tier.
  std::vector<uint64_t> free_tiles(config_.max_pages, 1);
  uint64_t unplaced = 0;
  for (uint32_t tier = 0; tier < tier_count(); ++tier) {
    if (tier > 0) {
      for (uint64_t& free : free_tiles) free *= 4;
    }
    uint64_t cubes = cubes_per_tier_[tier];
    uint64_t maps = maps_per_tier_[tier];
    for (uint64_t& free : free_tiles) {
      const uint64_t placed = std::min(cubes, free / 6);
      free -= 6 * placed;
      cubes -= placed;
    }
    for (uint64_t& free : free_tiles) {
      const uint64_t placed = std::min(maps, free);
      free -= placed;
      maps -= placed;
    }
    unplaced += (6 * cubes + maps) * area(config_.page_size >> tier);
  }
  return unplaced;
}

std::vector<uint32_t> ShadowAtlasPlanner::largest_first(std::span<const ShadowRequest> requests,
                                                        std::span<const uint32_t> indices) const {
  // A counting sort on (tier, 2D after cube): a plan() may place 100,000 lights.
  const auto bucket = [&](uint32_t i) { return 2 * tier_of(resolution_[i]) + (requests[i].cube ? 0 : 1); };
  std::vector<uint32_t> starts(2 * tier_count() + 1, 0);
  for (const uint32_t i : indices) ++starts[bucket(i) + 1];
  for (size_t b = 1; b < starts.size(); ++b) starts[b] += starts[b - 1];
  std::vector<uint32_t> ordered(indices.size());
  for (const uint32_t i : indices) ordered[starts[bucket(i)]++] = i;
  return ordered;
}

bool ShadowAtlasPlanner::keeps_tiles(std::span<const ShadowRequest> requests, size_t i) const {
  const Light& light = lights_[light_of_request_[i]];
  return resolution_[i] == light.resolution && requests[i].cube == light.cube;
}

bool ShadowAtlasPlanner::grows(std::span<const ShadowRequest> requests, uint32_t i) const {
  const Light& light = lights_[light_of_request_[i]];
  return light.resolution > 0 && resolution_[i] > light.resolution && requests[i].cube == light.cube;
}

bool ShadowAtlasPlanner::place_changed_lights(std::span<const ShadowRequest> requests,
                                              std::span<const uint32_t> changed) {
  // A full atlas's free space is in pieces (the tiles of lights that went down or out): a light
  // that finds none of its size takes a smaller one, and a light going up keeps its tiles, both
  // counted as demoted, instead of every light moving. A repack moves every tile, and every
  // moved map must be drawn again: with 100,000 lights that full atlas repacked most frames and
  // left 66,880 lights without a map at frame 300 (H200, 2026-12-02).
  for (const uint32_t i : largest_first(requests, changed)) {
    const std::span<AtlasTile> tiles(tiles_[i].data(), tile_count(requests[i].cube));
    const Light& light = lights_[light_of_request_[i]];
    if (grows(requests, i)) {
      // Its own tiles may be part of the larger one: given back first, taken again if not (the
      // light then keeps its tiles, keeps_tiles()).
      const std::span<const AtlasTile> own(light_tiles_[light_of_request_[i]].data(), tiles.size());
      for (const AtlasTile& tile : own) pages_.free(tile);
      if (!pages_.allocate(resolution_[i], tiles)) {
        for (const AtlasTile& tile : own) {
          [[maybe_unused]] const bool claimed = pages_.claim(tile);
          assert(claimed);
        }
        resolution_[i] = light.resolution;
        ++stats_.held_back_by_free_space;
      }
      continue;
    }
    uint32_t size = resolution_[i];
    while (!pages_.allocate(size, tiles)) {
      if (size == config_.min_resolution) return false;
      size /= 2;
    }
    stats_.held_back_by_free_space += size < resolution_[i] ? 1 : 0;
    resolution_[i] = size;
  }
  return true;
}

void ShadowAtlasPlanner::repack(std::span<const ShadowRequest> requests) {
  pages_.clear();
  std::vector<uint32_t> shadowed;
  for (uint32_t i = 0; i < requests.size(); ++i) {
    if (light_of_request_[i] != no_light && resolution_[i] > 0) shadowed.push_back(i);
  }
  for (const uint32_t i : largest_first(requests, shadowed)) {
    tiles_[i] = {};
    // fit_budget() counted this very packing, so every light fits; were one not to, it would
    // lose its shadow rather than overlap another.
    if (!pages_.allocate(resolution_[i], std::span(tiles_[i].data(), tile_count(requests[i].cube)))) {
      resolution_[i] = 0;
    }
  }
}

void ShadowAtlasPlanner::count_into(Tally& tally, const Light* light, uint32_t resolution) const {
  if (light) {
    if (light->wanted < light->full) ++tally.demoted_by_time;
    if (light->lowerable) ++tally.lowerable_by_time;
  }
  if (resolution == 0) {
    ++tally.without_shadow;
    if (light && light->wanted > 0) ++tally.dropped;
    return;
  }
  ++tally.lights_per_tier[tier_of(resolution)];
  tally.texels += tile_count(light->cube) * area(resolution);
  if (resolution < light->wanted) ++tally.demoted;
}

void ShadowAtlasPlanner::update_stats() {
  Tally total;
  for (const Tally& tally : tallies_) {
    total.without_shadow += tally.without_shadow;
    total.dropped += tally.dropped;
    total.demoted += tally.demoted;
    total.demoted_by_time += tally.demoted_by_time;
    total.lowerable_by_time += tally.lowerable_by_time;
    total.changed_tier += tally.changed_tier;
    total.retiled += tally.retiled;
    total.texels += tally.texels;
    for (size_t tier = 0; tier < total.lights_per_tier.size(); ++tier)
      total.lights_per_tier[tier] += tally.lights_per_tier[tier];
  }
  stats_.pages_used = pages_.pages_used();
  stats_.texels_used = total.texels;
  stats_.lights_without_shadow = total.without_shadow;
  stats_.demoted_by_budget = total.demoted;
  stats_.dropped_by_budget = total.dropped;
  stats_.demoted_by_time = total.demoted_by_time;
  stats_.lowerable_by_time = total.lowerable_by_time;
  stats_.lights_changed_tier = total.changed_tier;
  stats_.lights_retiled = total.retiled;
  stats_.lights_per_resolution.clear();
  for (uint32_t tier = 0; tier < tier_count(); ++tier) {
    if (total.lights_per_tier[tier] > 0) {
      stats_.lights_per_resolution.emplace_back(config_.page_size >> tier, total.lights_per_tier[tier]);
    }
  }
}

std::optional<std::string> ShadowAtlasPlanner::take_budget_message() {
  const BudgetEffect effect{stats_.demoted_by_budget, stats_.dropped_by_budget};
  const std::optional<BudgetEffect> was = budget_report_.due(effect, plans_);
  if (!was) return std::nullopt;
  std::string line = "shadow atlas budget (" + std::to_string(config_.max_pages) + " pages of " +
                     std::to_string(config_.page_size) + "^2): ";
  if (effect == BudgetEffect{}) {
    line += "every light has its wanted shadow resolution again";
  } else {
    line += std::to_string(effect.demoted) + " lights at a lower resolution, " +
            std::to_string(effect.dropped) + " without shadow";
  }
  line += " (was " + std::to_string(was->demoted) + " lower, " + std::to_string(was->dropped) + " without)";
  return line;
}

}  // namespace sg::shadows
