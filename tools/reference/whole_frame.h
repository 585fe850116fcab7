// SPDX-License-Identifier: MIT
#pragma once
// shadowgraph-reference --whole-frame: the frame as the engine draws it, every light on, at the
// tiers, caching and update caps of that frame, against ray-traced visibility.
//
//   1. render `frames` frames (animation advancing 1/60 s each, as the sandbox's headless runs),
//      the last with a shadow probe (systems/lighting/shadow_probe.h): every (pixel, light) pair
//      whose shadow can change the pixel, with the shade the frame gave it and its weight;
//   2. trace each pair's visibility from the same surface point (visibility.h) against the
//      casters where they stand in that frame, so that maps drawn in earlier frames (cached, or
//      waiting their turn) count as error where they are out of date;
//   3. frame_error.h's figures, and the lights that add most to them.
//
// Where the frame has more pairs than `pairs_per_pixel` times its pixels, the run is repeated
// keeping a random share of the pairs (the same share of every light's), and the report says so.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rendergraph/device/fwd.h"
#include "systems/frame/frame_settings.h"
#include "tools/reference/frame_error.h"
#include "tools/reference/progress.h"
#include "tools/reference/reference_lights.h"

namespace sg::reference {

struct WholeFrameSettings {
  uint32_t frames = 1;            // rendered; the last is measured
  uint32_t soft_samples = 16;     // rays a pair of a PCSS light's soft reference; 0: hard for all
  int edge_band = 2;              // as frame_error's band_radius
  uint32_t pairs_per_pixel = 64;  // the probe's room, per pixel of the frame
  uint32_t worst_lights = 20;     // light rows reported
  // Not empty: only shadowed lights whose name contains this stay on (the others' intensity is
  // set to 0, their shadows still drawn), to measure lights one at a time in the frame's setting.
  std::string light_filter;
};

struct FrameLightRow {
  std::string name;
  LightType type = LightType::point;
  std::string algorithm;
  uint32_t resolution = 0;  // the map (cube face) it had this frame; 0: none
  LightError error;
};

struct WholeFrameReport {
  std::string device;
  std::string scene;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t frames = 0;
  // The GPU frame's median over the frames before the probed one (0 with one frame): the cost of
  // the shadows measured.
  double gpu_frame_ms = 0.0;
  uint64_t lights = 0;           // in the frame
  uint64_t shadowed_lights = 0;  // of them, casting a shadow by their settings
  uint64_t lights_without_map =
      0;                      // of those, with no map this frame (out of sight, or over the memory budget)
  uint64_t frame_pairs = 0;   // (pixel, shadowed light) pairs the frame shaded
  uint64_t traced_pairs = 0;  // of them, traced
  // The (tile, light) pairs of the light lists, and of them those that light at least one pixel
  // (where the frame's pairs were not sampled): how tightly the culling lists the lights.
  uint64_t list_pairs = 0;
  std::optional<uint64_t> lighting_list_pairs;
  double sampled_fraction = 1.0;  // the share of pairs kept
  uint32_t soft_samples = 0;
  int edge_band = 0;
  double trace_seconds = 0.0;
  FrameError error;  // its lights cut to the worst rows
  std::vector<FrameLightRow> worst;
};

WholeFrameReport run_whole_frame(vk::VulkanContext& context, const FrameSettings& frame,
                                 const WholeFrameSettings& settings, const Progress& progress = {});

}  // namespace sg::reference
