// SPDX-License-Identifier: MIT
#pragma once
// shadowgraph-reference's run: the engine's shadows of a scene, light by light and
// algorithm by algorithm, against ray-traced visibility from the same surface points.
//
//   1. render the scene's frame and take its depth buffer back to world-space surface points;
//   2. per shadowed light: trace the hard and the soft reference (visibility.h), then render the
//      light alone once without its shadow and once per (algorithm, resolution) with it
//      (engine_shade.h), and compare (metrics.h); optionally write the pictures;
//   3. optionally, the GPU cost of each algorithm on the whole scene (systems/frame/frame_cost.h).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rendergraph/device/fwd.h"
#include "systems/frame/frame_cost.h"
#include "systems/frame/frame_settings.h"
#include "systems/scene/shadow_settings.h"
#include "tools/reference/metrics.h"
#include "tools/reference/progress.h"
#include "tools/reference/reference_lights.h"

namespace sg::reference {

struct ReferenceSettings {
  std::vector<scene::ShadowAlgorithm> algorithms{std::begin(scene::all_shadow_algorithms),
                                                 std::end(scene::all_shadow_algorithms)};
  std::vector<uint32_t> resolutions;   // requested map sizes to try; empty: each light's own
  std::optional<float> constant_bias;  // replaces every light's own
  std::optional<float> slope_bias;
  uint32_t soft_samples = 64;               // rays per pixel of the soft reference
  int edge_band = 2;                        // pixels each side of the hard reference's edge
  std::string light_filter;                 // only lights whose name contains this
  std::vector<std::string> no_shadow_from;  // meshes named like these cast no shadow (stop_casting)
  uint32_t max_lights = 0;                  // at most this many lights (0: all), in scene order
  std::string image_folder;                 // PNGs per light go here; empty: none
  uint32_t cost_frames = 0;                 // frames per algorithm for the GPU cost; 0: not measured
};

struct AlgorithmRun {
  scene::ShadowAlgorithm algorithm = scene::ShadowAlgorithm::hard;
  uint32_t requested_resolution = 0;
  uint32_t resolution = 0;  // what the atlas gave the light (0: no map this frame)
  ShadowMetrics metrics;
};

struct LightReport {
  std::string name;
  LightType type = LightType::point;
  double trace_seconds = 0.0;  // both references
  std::vector<AlgorithmRun> runs;
};

struct AlgorithmCost {
  std::string algorithm;  // a ShadowAlgorithm's name, or "off" (no shadows)
  FrameCost cost;
};

struct ReferenceReport {
  std::string device;
  std::string scene;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t soft_samples = 0;
  int edge_band = 0;
  std::vector<LightReport> lights;
  std::vector<AlgorithmCost> costs;  // "off" first, when measured
  // A signal (interrupt.h) ended the run after `lights`, before the rest and the costs.
  bool interrupted = false;
};

// Runs the whole comparison; `progress` (may be empty) hears one line per step. Throws
// std::exception with a message for a scene that cannot be loaded or has no shadowed light
// left after the filters.
ReferenceReport run_reference(vk::VulkanContext& context, const FrameSettings& frame,
                              const ReferenceSettings& settings, const Progress& progress = {});

}  // namespace sg::reference
