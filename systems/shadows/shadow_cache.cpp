#include "systems/shadows/shadow_cache.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "ecs/parallel_pieces.h"

#include "systems/shadows/align_by_key.h"

namespace sg::shadows {

void ShadowCache::plan(std::span<const ShadowCacheLight> lights, const CasterChanges& changes,
                       uint32_t view_budget, bool static_layers, std::span<uint8_t> render,
                       std::span<uint8_t> usable, ecs::ThreadPool* pool) {
  if (render.size() != lights.size() || usable.size() != lights.size()) {
    throw std::invalid_argument(
        "sg::shadows::ShadowCache::plan: render and usable need one element per light");
  }
  ++frame_;
  align_by_key(lights, states_, index_of_key_, matched_);
  for (size_t i = 0; i < lights.size(); ++i) {
    LightState& state = states_[i];
    if (lights[i].invalid) state.valid = false;
    state.dirty = state.dirty || lights[i].changed || !state.valid;
  }
  mark_by_casters(lights, changes.still, &LightState::dirty, pool);
  mark_by_casters(lights, changes.moving, &LightState::moving_dirty, pool);
  choose_renders(lights, view_budget, render, pool);

  stats_ = {};
  for (size_t i = 0; i < lights.size(); ++i) {
    LightState& state = states_[i];
    const uint32_t views = lights[i].views;
    if (render[i] != keep_map) {
      if (state.dirty || !state.static_kept || !static_layers) {
        render[i] = draw_all_casters;
        state.drawn_all_frame = frame_;
        state.static_kept = static_layers;
      } else {
        render[i] = draw_moving_casters;
        stats_.views_moving_only += views;
      }
      state.rendered_frame = frame_;
      state.dirty = false;
      state.moving_dirty = false;
      state.valid = true;
      stats_.views_rendered += views;
      ++stats_.lights_rendered;
    } else if (state.valid) {
      stats_.views_cached += views;
    }
    usable[i] = state.valid ? 1 : 0;
    stats_.lights_waiting += state.dirty || state.moving_dirty ? 1 : 0;
    stats_.lights_unavailable += state.valid ? 0 : 1;
  }
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
                                  ecs::ThreadPool* pool) {
  if (boxes.empty()) return;
  candidates_.clear();
  candidate_reach_.clear();
  for (uint32_t i = 0; i < lights.size(); ++i) {
    if (states_[i].dirty || states_[i].*flag) continue;
    if (lights[i].reach.w < 0.0f) {
      states_[i].*flag = true;
    } else {
      candidates_.push_back(i);
      candidate_reach_.push_back(lights[i].reach);
    }
  }
  candidate_met_.assign(candidates_.size(), 0);
  spheres_meeting_boxes_.find(candidate_reach_, boxes, candidate_met_, pool);
  for (size_t k = 0; k < candidates_.size(); ++k) {
    if (candidate_met_[k] != 0) states_[candidates_[k]].*flag = true;
  }
}

void ShadowCache::choose_renders(std::span<const ShadowCacheLight> lights, uint32_t view_budget,
                                 std::span<uint8_t> render, ecs::ThreadPool* pool) {
  std::fill(render.begin(), render.end(), uint8_t{0});
  candidates_.clear();
  uint64_t dirty_views = 0;
  for (uint32_t i = 0; i < lights.size(); ++i) {
    if (!states_[i].dirty && !states_[i].moving_dirty) continue;
    candidates_.push_back(i);
    dirty_views += lights[i].views;
  }
  if (view_budget == 0 || dirty_views <= view_budget) {
    for (const uint32_t i : candidates_) render[i] = 1;
    return;
  }

  // Lights without a valid map, then the stalest, ties by key (the header's order): sort keys
  // side by side rather than looked up through the lights, so thousands of them sort quickly.
  order_.clear();
  for (const uint32_t i : candidates_) {
    const LightState& state = states_[i];
    order_.push_back({(state.valid ? uint64_t{1} << 63 : 0) | state.rendered_frame, state.key, i});
  }
  const auto comes_first = [](const Ordered& a, const Ordered& b) {
    return a.stale < b.stale || (a.stale == b.stale && a.key < b.key);
  };
  uint32_t views_left = view_budget;
  bool rendered_any = false;
  const auto take_in_order = [&](auto begin, auto end) {
    for (auto it = begin; it != end && views_left > 0; ++it) {
      const uint32_t views = lights[it->light].views;
      if (views > views_left && rendered_any) continue;
      render[it->light] = 1;
      views_left -= std::min(views, views_left);
      rendered_any = true;
    }
  };
  // Every light has a view at least, so no more than views_left lights fit: ordering that many
  // is enough, unless lights were skipped for having more views than were left.
  const ptrdiff_t head_count = std::min<ptrdiff_t>(views_left, std::ssize(order_));
  if (head_count == std::ssize(order_)) {
    // All of them (partial_sort would heap-sort them all), in pieces on the pool: with
    // thousands of dirty lights the choice was the cache's largest step (0.16 of 0.27 ms). The
    // merges may leave order_ in what was the scratch's storage.
    ecs::sort_in_pieces(pool, order_, order_scratch_, 256, comes_first);
  } else {
    std::partial_sort(order_.begin(), order_.begin() + head_count, order_.end(), comes_first);
  }
  const auto head = order_.begin() + head_count;
  take_in_order(order_.begin(), head);
  // Then fewer views are left than the skipped light had, a handful: the stalest of the rest that
  // still fits, one scan each, costs less than sorting the rest (100,000 lights).
  while (views_left > 0) {
    auto next = order_.end();
    for (auto it = head; it != order_.end(); ++it) {
      if (render[it->light] == 0 && lights[it->light].views <= views_left &&
          (next == order_.end() || comes_first(*it, *next)))
        next = it;
    }
    if (next == order_.end()) break;
    render[next->light] = 1;
    views_left -= lights[next->light].views;
  }
}

}  // namespace sg::shadows
