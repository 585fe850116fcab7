// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_cache.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <stdexcept>

#include "ecs/jobs/parallel_pieces.h"

#include "systems/shadows/align_by_key.h"
#include "systems/shadows/radix_sort.h"

namespace sg::shadows {

namespace {

// Lights a piece of the cache's passes handles on the pool.
constexpr size_t lights_per_piece = 256;

// Dirty lights are few below one in this many: choose_renders sorts them by key on their own.
// Sorting tens of thousands of them each frame while the maps were first drawn (100,000 lights)
// took longer than reading every light's key order, sorted once.
constexpr size_t few_dirty_lights = 8;
// Dirty lights choose_renders counts on a thread, into a histogram of its own per piece.
constexpr size_t dirty_per_count = 4096;

}  // namespace

void ShadowCache::plan(std::span<const ShadowCacheLight> lights, const CasterChanges& changes,
                       uint32_t view_budget, bool static_layers, std::span<uint8_t> render,
                       std::span<uint8_t> usable, jobs::ThreadPool* pool, StepClock* clock) {
  if (render.size() != lights.size() || usable.size() != lights.size()) {
    throw std::invalid_argument(
        "sg::shadows::ShadowCache::plan: render and usable need one element per light");
  }
  ++frame_;
  // Each pass over the lights runs in pieces on the pool: read one after another on one thread,
  // 100,000 lights' states took about a millisecond a pass on an H200 host (2026-12-03).
  if (!same_keys(lights, pool)) {
    align_by_key(lights, states_, places_, matched_);
    by_key_.clear();
  }
  jobs::run_in_pieces(pool, lights.size(), lights_per_piece, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      LightState& state = states_[i];
      if (!lights[i].placed) {
        state = {.key = lights[i].key, .dirty = false};  // valid = false makes it dirty once placed
        continue;
      }
      if (lights[i].invalid) state.valid = false;
      state.dirty = state.dirty || lights[i].changed || !state.valid ||
                    lights[i].update == scene::ShadowUpdate::every_frame;
    }
  });
  lap(clock, ScheduleStep::dirty);
  mark_by_casters(lights, changes.still, &LightState::dirty, pool);
  mark_by_casters(lights, changes.moving, &LightState::moving_dirty, pool);
  lap(clock, ScheduleStep::casters);
  choose_renders(lights, view_budget, render, pool);
  lap(clock, ScheduleStep::choose);

  // How each chosen light renders, what is usable, and the counts, each piece into a tally of its
  // own; the due lights' lags listed in order.
  const size_t pieces = jobs::piece_count(lights.size(), lights_per_piece);
  tallies_.assign(pieces, ShadowCacheStats{});
  lags_.resize(lights.size());
  const size_t due_count = jobs::keep_in_pieces(
      pool, lights.size(), lights_per_piece, keep_scratch_,
      [&](size_t i) {
        if (!lights[i].placed) {  // neither dirty nor rendered
          usable[i] = 0;
          return false;
        }
        ShadowCacheStats& tally = tallies_[i / lights_per_piece];
        LightState& state = states_[i];
        const uint32_t views = lights[i].views;
        const bool due = state.dirty || state.moving_dirty;
        if (due && state.wrong_since == 0) state.wrong_since = frame_;
        if (render[i] != keep_map) {
          if (state.dirty || !state.static_kept || !static_layers) {
            render[i] = draw_all_casters;
            state.drawn_all_frame = frame_;
            state.static_kept = static_layers;
          } else {
            render[i] = draw_moving_casters;
            tally.views_moving_only += views;
          }
          state.rendered_frame = frame_;
          state.wrong_since = 0;
          state.dirty = false;
          state.moving_dirty = false;
          state.valid = true;
          tally.views_rendered += views;
          ++tally.lights_rendered;
        } else if (state.valid) {
          tally.views_cached += views;
        }
        usable[i] = state.valid ? 1 : 0;
        const bool waiting = state.dirty || state.moving_dirty;
        tally.lights_waiting += waiting ? 1 : 0;
        tally.views_waiting += waiting ? views : 0;
        tally.lights_unavailable += state.valid ? 0 : 1;
        return due;
      },
      [&](size_t i, size_t rank) {
        const uint64_t wrong_since = states_[i].wrong_since;
        lags_[rank] = wrong_since == 0 ? 0u : uint32_t(frame_ - wrong_since + 1);
      });
  lags_.resize(due_count);
  stats_ = {};
  for (const ShadowCacheStats& tally : tallies_) {
    stats_.views_rendered += tally.views_rendered;
    stats_.views_moving_only += tally.views_moving_only;
    stats_.views_cached += tally.views_cached;
    stats_.lights_rendered += tally.lights_rendered;
    stats_.lights_waiting += tally.lights_waiting;
    stats_.views_waiting += tally.views_waiting;
    stats_.lights_unavailable += tally.lights_unavailable;
  }
  summarize_lags();
  lap(clock, ScheduleStep::renders);
}

bool ShadowCache::same_keys(std::span<const ShadowCacheLight> lights, jobs::ThreadPool* pool) {
  if (lights.size() != states_.size()) return false;
  const size_t pieces = jobs::piece_count(lights.size(), lights_per_piece);
  piece_flags_.assign(pieces, 1);
  jobs::run_in_pieces(pool, lights.size(), lights_per_piece, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      if (states_[i].key != lights[i].key) {
        piece_flags_[begin / lights_per_piece] = 0;
        return;
      }
    }
  });
  return std::find(piece_flags_.begin(), piece_flags_.end(), 0) == piece_flags_.end();
}

// Lags are frame counts, mostly short: counted by value in one pass, where two nth_element
// passes over the 68,000 due lights at 100,000 lights took 0.3-0.4 ms of an H200 host's frame, on
// one thread (2026-12-04). Lags of counted_lags frames or more are sorted apart.
void ShadowCache::summarize_lags() {
  constexpr uint32_t counted_lags = 1024;
  stats_.lights_due = uint32_t(lags_.size());
  if (lags_.empty()) return;
  lag_counts_.assign(counted_lags, 0);
  long_lags_.clear();
  for (const uint32_t lag : lags_) {
    if (lag < counted_lags) {
      ++lag_counts_[lag];
    } else {
      long_lags_.push_back(lag);
    }
  }
  std::sort(long_lags_.begin(), long_lags_.end());
  // The lag at `fraction` of the way through them in order (rank floor(fraction * (due - 1))).
  const auto at_rank = [&](double fraction) {
    auto rank = uint64_t(fraction * double(lags_.size() - 1));
    for (uint32_t lag = 0; lag < counted_lags; ++lag) {
      if (rank < lag_counts_[lag]) return lag;
      rank -= lag_counts_[lag];
    }
    return long_lags_[rank];
  };
  stats_.lag_max = at_rank(1.0);
  stats_.lag_p99 = at_rank(0.99);
  stats_.lag_p50 = at_rank(0.5);
}

void ShadowCache::invalidate_all() {
  for (LightState& state : states_) {
    state.valid = false;
    state.static_kept = false;
  }
}

void ShadowCache::forget_static_layers() {
  for (LightState& state : states_) state.static_kept = false;
}

void ShadowCache::static_layers_not_kept() {
  for (LightState& state : states_) {
    if (state.drawn_all_frame == frame_) state.static_kept = false;
  }
}

// Only lights not dirty already are worth testing; unbounded ones are marked on any change.
void ShadowCache::mark_by_casters(std::span<const ShadowCacheLight> lights,
                                  std::span<const scene::Aabb> boxes, bool LightState::*flag,
                                  jobs::ThreadPool* pool) {
  if (boxes.empty()) return;
  // Of the lights not dirty yet, the unbounded ones are marked, the bounded ones listed for the test.
  candidates_.resize(lights.size());
  candidate_reach_.resize(lights.size());
  const size_t count = jobs::keep_in_pieces(
      pool, lights.size(), lights_per_piece, keep_scratch_,
      [&](size_t i) {
        LightState& state = states_[i];
        if (state.dirty || state.*flag || !lights[i].placed ||
            lights[i].update == scene::ShadowUpdate::on_demand) {
          return false;
        }
        if (lights[i].reach.w >= 0.0f) return true;
        state.*flag = true;
        return false;
      },
      [&](size_t i, size_t k) {
        candidates_[k] = uint32_t(i);
        candidate_reach_[k] = lights[i].reach;
      });
  candidates_.resize(count);
  candidate_reach_.resize(count);
  candidate_met_.assign(count, 0);
  spheres_meeting_boxes_.find(candidate_reach_, boxes, candidate_met_, pool);
  jobs::run_in_pieces(pool, count, lights_per_piece, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      if (candidate_met_[k] != 0) states_[candidates_[k]].*flag = true;
    }
  });
}

void ShadowCache::choose_renders(std::span<const ShadowCacheLight> lights, uint32_t view_budget,
                                 std::span<uint8_t> render, jobs::ThreadPool* pool) {
  std::fill(render.begin(), render.end(), uint8_t{0});
  // The dirty lights, and each piece's tally of them: 68,000 of 100,000 lights are dirty while
  // the moving crates are near (the street camera), too many to sum on one thread after.
  dirty_tallies_.assign(jobs::piece_count(lights.size(), lights_per_piece), DirtyTally{});
  candidates_.resize(lights.size());
  candidates_.resize(jobs::keep_in_pieces(
      pool, lights.size(), lights_per_piece, keep_scratch_,
      [&](size_t i) {
        const LightState& state = states_[i];
        if (!state.dirty && !state.moving_dirty) return false;
        DirtyTally& tally = dirty_tallies_[i / lights_per_piece];
        tally.views += lights[i].views;
        tally.oldest = std::min(tally.oldest, state.rendered_frame);
        tally.newest = std::max(tally.newest, state.rendered_frame);
        return true;
      },
      [&](size_t i, size_t k) { candidates_[k] = uint32_t(i); }));
  DirtyTally dirty;
  for (const DirtyTally& tally : dirty_tallies_) {
    dirty.views += tally.views;
    dirty.oldest = std::min(dirty.oldest, tally.oldest);
    dirty.newest = std::max(dirty.newest, tally.newest);
  }
  if (view_budget == 0 || dirty.views <= view_budget) {
    for (const uint32_t i : candidates_) render[i] = 1;
    return;
  }

  // Lights without a valid map, then the stalest (each of the two by staleness), ties by key
  // (the header's order): the dirty lights listed in key order, then ordered by rank (how long
  // ago each was rendered) as far as the budget reaches (below). The key order is the dirty
  // lights' own, radix-sorted, when they are few (a few thousand of 100,000 once the maps are
  // drawn); when many are (while the maps are first drawn, or moving casters near most lights),
  // it is read from every light's key order, sorted once while the lights stay the same, in
  // pieces on the pool.
  const uint64_t span = dirty.newest - dirty.oldest + 1;  // some are dirty: they are over the budget
  const auto ranked = [&](uint32_t i) {
    const LightState& state = states_[i];
    return ((state.valid ? span : 0) + state.rendered_frame - dirty.oldest) << 32 | i;
  };
  order_.resize(candidates_.size());
  if (candidates_.size() * few_dirty_lights < lights.size()) {
    dirty_by_key_.clear();
    for (const uint32_t i : candidates_) dirty_by_key_.push_back({lights[i].key, i});
    radix_sort(dirty_by_key_, by_key_scratch_, [](const KeyedLight& light) { return light.key; });
    for (size_t k = 0; k < dirty_by_key_.size(); ++k) order_[k] = ranked(dirty_by_key_[k].index);
  } else {
    if (by_key_.size() != lights.size()) {
      by_key_.resize(lights.size());
      for (uint32_t i = 0; i < lights.size(); ++i) by_key_[i] = {lights[i].key, i};
      radix_sort(by_key_, by_key_scratch_, [](const KeyedLight& light) { return light.key; });
    }
    jobs::keep_in_pieces(
        pool, by_key_.size(), lights_per_piece, keep_scratch_,
        [&](size_t k) { return states_[by_key_[k].index].dirty || states_[by_key_[k].index].moving_dirty; },
        [&](size_t k, size_t rank) { order_[rank] = ranked(by_key_[k].index); });
  }
  // Only the rank bucket where the budget runs out is ordered: a histogram of the views by rank
  // (at most 4,096 buckets) finds it; the lights before it all render, in any order. A radix
  // sort of all 68,000 dirty lights by rank took 0.44 ms on one thread of an H200 host at
  // 100,000 lights (2026-12-04).
  const auto rank_bits = static_cast<uint32_t>(std::bit_width(2 * span - 1));
  const uint32_t shift = rank_bits > 12 ? rank_bits - 12 : 0;
  const size_t buckets = size_t(((2 * span - 1) >> shift) + 1);
  const auto bucket = [shift](uint64_t ordered) { return size_t(ordered >> 32 >> shift); };
  const size_t pieces = jobs::piece_count(order_.size(), dirty_per_count);
  piece_views_.assign(pieces * buckets, 0);
  jobs::run_in_pieces(pool, order_.size(), dirty_per_count, [&](size_t begin, size_t end) {
    uint64_t* views = &piece_views_[begin / dirty_per_count * buckets];
    for (size_t k = begin; k < end; ++k) views[bucket(order_[k])] += lights[uint32_t(order_[k])].views;
  });
  size_t boundary = 0;  // dirty.views > view_budget: some bucket reaches it
  uint64_t views_before = 0;
  for (;; ++boundary) {
    uint64_t views = 0;
    for (size_t p = 0; p < pieces; ++p) views += piece_views_[p * buckets + boundary];
    if (views_before + views >= view_budget) break;
    views_before += views;
  }
  // The lights before the boundary render. The boundary bucket's, in key order, are ordered by
  // rank and walked; the later buckets' only when a light too large for what was left was skipped.
  auto views_left = static_cast<uint32_t>(view_budget - views_before);
  bool rendered_any = views_before > 0;  // every light has a view at least
  rest_.resize(order_.size());
  rest_.resize(jobs::keep_in_pieces(
      pool, order_.size(), dirty_per_count, keep_scratch_,
      [&](size_t k) {
        if (bucket(order_[k]) < boundary) render[uint32_t(order_[k])] = 1;
        return bucket(order_[k]) == boundary;
      },
      [&](size_t k, size_t rank) { rest_[rank] = order_[k]; }));
  radix_sort(
      rest_, order_scratch_, [](uint64_t ordered) { return ordered >> 32; }, rank_bits);
  // Skipping a light with more views than are left, the walk goes on to the stalest that fits.
  for (const uint64_t ordered : rest_) {
    if (views_left == 0) break;
    const auto i = static_cast<uint32_t>(ordered);
    const uint32_t views = lights[i].views;
    if (views > views_left && rendered_any) continue;
    render[i] = 1;
    views_left -= std::min(views, views_left);
    rendered_any = true;
  }

  // What is left is less than a light the walk skipped needs (a view or two where a cube did not
  // fit): the stalest later lights that fit take it, as the walk would go on. Each takes a view or
  // more, so at most views_left of them render: one pass over the order keeps that many, in
  // walking order, and they are walked. Only a skip among them (lights of several sizes under
  // a cube's) takes another pass. Sorting every later light instead (99,000 with every light
  // moving) took 0.2-0.36 ms of one thread of the 2-core VM to render one (2026-12-05).
  while (views_left > 0) {
    std::array<uint64_t, 8> stalest;  // rank << 32 | index, by rank, then in key order
    const size_t most = std::min<size_t>(views_left, stalest.size());
    size_t kept = 0;
    for (const uint64_t ordered : order_) {
      const auto i = static_cast<uint32_t>(ordered);
      if (bucket(ordered) <= boundary || (kept == most && (ordered >> 32) >= (stalest[kept - 1] >> 32)) ||
          render[i] != 0 || lights[i].views > views_left) {
        continue;
      }
      size_t at = std::min(kept, most - 1);  // after the lights of its rank, dropping the last
      for (; at > 0 && (stalest[at - 1] >> 32) > (ordered >> 32); --at) stalest[at] = stalest[at - 1];
      stalest[at] = ordered;
      kept = std::min(kept + 1, most);
    }
    if (kept == 0) break;
    for (size_t k = 0; k < kept && views_left > 0; ++k) {
      const auto i = static_cast<uint32_t>(stalest[k]);
      if (lights[i].views > views_left) continue;
      render[i] = 1;
      views_left -= lights[i].views;
    }
  }
}

}  // namespace sg::shadows
