// SPDX-License-Identifier: MIT
#include "tools/reference/whole_frame.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "ecs/jobs/thread_pool.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/frame/scene_view.h"
#include "systems/lighting/shadow_probe.h"
#include "tools/reference/ray_scene.h"
#include "tools/reference/scene_triangles.h"
#include "tools/reference/surface_points.h"
#include "tools/reference/visibility.h"

namespace sg::reference {
namespace {

// A shadowed light of the frame as the reference needs it; `shadowed` false for lights whose
// settings cast no shadow (their pairs are not measured).
struct FrameLight {
  bool shadowed = false;
  ReferenceLight ray;  // where rays go, from the record: the light where it is this frame
  std::string name;
  scene::ShadowAlgorithm algorithm = scene::ShadowAlgorithm::hard;
  uint32_t resolution = 0;
  scene::LayerMask caster_mask = scene::all_layers;
};

constexpr LightType record_types[] = {LightType::point, LightType::spot, LightType::directional,
                                      LightType::cylinder};  // GpuLight::info.x's order

std::vector<FrameLight> frame_lights(const shadows::FrameLights& lights) {
  // By the records' places on the GPU, where the probe's pairs name them.
  std::vector<FrameLight> out(lights.records.size());
  const auto add = [&](uint32_t record, const std::string& view_name, uint32_t resolution,
                       scene::LayerMask caster_mask) {
    const shadows::GpuLight& gpu = lights.records[record];
    FrameLight& light = out[lights.sorted_place[record]];
    light.shadowed = true;
    light.ray.type = record_types[std::min(gpu.info.x, 3u)];
    light.ray.position = glm::vec3(gpu.position_range);
    light.ray.direction = glm::vec3(gpu.direction_type);
    light.ray.light_size = gpu.shadow_bias.w;
    light.name = view_name.rfind("shadow ", 0) == 0 ? view_name.substr(7) : view_name;
    light.ray.name = light.name;
    light.algorithm = shadows::algorithm_of(gpu);
    light.resolution = resolution;
    light.caster_mask = caster_mask;
  };
  for (const shadows::ShadowMapView& map : lights.maps) {
    if (map.cascade == shadows::no_cascade) add(map.light, map.name, map.resolution, map.caster_mask);
  }
  // A cascaded light is one row, named as the light, at its nearest cascade's resolution.
  for (const shadows::FrameLights::CascadedLight& light : lights.cascaded) {
    const shadows::ShadowMapView& nearest = lights.maps[light.first_view];
    add(light.record, nearest.name.substr(0, nearest.name.rfind(" cascade ")), nearest.resolution,
        nearest.caster_mask);
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    add(cube.light, cube.name, cube.resolution, cube.caster_mask);
  }
  return out;
}

// What the probed frame left: the scene as it stood, its surface depths, lights and pairs.
struct ProbedFrame {
  std::unique_ptr<SceneView> view;
  vk::DepthImage depth;
  std::vector<FrameLight> lights;
  ShadowProbeResult probe;
  double gpu_frame_ms = 0.0;  // the median of the frames before the probed one
};

ProbedFrame probe_frame(vk::VulkanContext& context, const FrameSettings& settings,
                        const WholeFrameSettings& frame_mode, uint64_t capacity, float keep,
                        const Progress& progress) {
  ProbedFrame out;
  out.view =
      std::make_unique<SceneView>(load_scene_view(settings, float(settings.width) / float(settings.height)));
  if (!frame_mode.light_filter.empty()) {
    size_t on = 0;
    for (const ReferenceLight& light : shadowed_lights(out.view->scene)) {
      const bool kept = light.name.find(frame_mode.light_filter) != std::string::npos;
      if (!kept) set_intensity(out.view->scene.world, light.entity, 0.0f);
      on += kept ? 1 : 0;
    }
    if (on == 0) {
      throw std::runtime_error("scene '" + out.view->scene.name +
                               "' has no shadow-casting light named like '" + frame_mode.light_filter + "'");
    }
  }
  const uint32_t frames = frame_mode.frames;
  vk::FrameRing ring(context);
  Frame frame(context, *out.view, settings, ring.frames_in_flight());
  frame.resize({settings.width, settings.height});
  frame.capture_depth();
  GpuTimeLog times;
  render_headless_frames(frame, ring, frames - 1, times, true);  // progress on runs of 100 frames or more
  std::vector<double> unprobed = times.frame_ms();
  if (!unprobed.empty()) {
    std::nth_element(unprobed.begin(), unprobed.begin() + std::ptrdiff_t(unprobed.size() / 2),
                     unprobed.end());
    out.gpu_frame_ms = unprobed[unprobed.size() / 2];
  }
  // Each step says so: the probed frame builds the probe's pipeline (every light type and
  // algorithm in one shader) and reads back up to a few hundred MB.
  say(progress, "probing frame " + std::to_string(frames) + " (the probe's pipeline is built first)");
  ShadowProbe probe(context, capacity, keep);
  frame.renderer().probe_shadows(&probe);
  render_headless_frames(frame, ring, 1, times, false, frames - 1);
  frame.renderer().probe_shadows(nullptr);
  say(progress, "reading the probed frame back");
  out.depth = frame.read_captured_depth();
  out.lights = frame_lights(frame.renderer().lights());
  out.probe = probe.read();
  return out;
}

// Each measured pair's references, traced on `pool` in batches with a progress line each.
std::vector<TracedPair> trace_pairs(const std::vector<ShadowProbePair>& pairs,
                                    const std::vector<FrameLight>& lights, const SurfacePoints& points,
                                    const CasterScenes& casters, uint32_t soft_samples,
                                    jobs::ThreadPool& pool, const Progress& progress) {
  std::vector<TracedPair> out;
  out.reserve(pairs.size());
  for (const ShadowProbePair& pair : pairs) {
    if (pair.light < lights.size() && lights[pair.light].shadowed && points.points[pair.pixel].valid) {
      out.push_back({pair.pixel, pair.light, pair.shade, pair.weight, 0.0f, 0.0f});
    }
  }
  constexpr size_t chunk = 4096;
  const size_t chunks = (out.size() + chunk - 1) / chunk;
  const size_t batch = std::max<size_t>(1, chunks / 20);  // a progress line every 5%
  const auto start = std::chrono::steady_clock::now();
  for (size_t first = 0; first < chunks; first += batch) {
    const size_t count = std::min(batch, chunks - first);
    pool.run(count, [&](size_t c) {
      const size_t begin = (first + c) * chunk;
      for (size_t i = begin; i < std::min(begin + chunk, out.size()); ++i) {
        TracedPair& pair = out[i];
        const FrameLight& light = lights[pair.light];
        const SurfacePoint& point = points.points[pair.pixel];
        const RayScene& light_casters = casters.of(light.caster_mask);
        pair.hard = hard_visible(light_casters, point, points.eye, light.ray);
        const bool soft = soft_samples > 0 && (light.algorithm == scene::ShadowAlgorithm::pcss ||
                                               light.algorithm == scene::ShadowAlgorithm::pcss_noise);
        const glm::uvec2 pixel{pair.pixel % points.width, pair.pixel / points.width};
        pair.reference =
            soft ? soft_visible(light_casters, point, points.eye, light.ray, soft_samples, pixel) : pair.hard;
      }
    });
    const double done = double(first + count) / double(chunks);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char line[128];
    std::snprintf(line, sizeof(line), "  traced %3.0f%% of %zu pairs, %.1f s, about %.1f s left",
                  100.0 * done, out.size(), elapsed, elapsed / done * (1.0 - done));
    say(progress, line);
  }
  return out;
}

}  // namespace

WholeFrameReport run_whole_frame(vk::VulkanContext& context, const FrameSettings& frame,
                                 const WholeFrameSettings& settings, const Progress& progress) {
  if (settings.frames == 0) throw std::invalid_argument("--frames: at least one frame");
  FrameSettings lit = frame;
  lit.renderer.lighting = LightingPath::deferred;  // the probe walks the deferred lighting's lists
  lit.renderer.view = LightingView::lit;
  const uint64_t capacity = uint64_t(frame.width) * frame.height * std::max(settings.pairs_per_pixel, 1u);

  say(progress, "rendering " + std::to_string(settings.frames) + " frame(s), probing the last");
  ProbedFrame probed = probe_frame(context, lit, settings, capacity, 1.0f, progress);
  float keep = 1.0f;
  if (!probed.probe.complete()) {
    keep = float(std::min(1.0, 0.9 * double(capacity) / double(probed.probe.wanted)));
    char line[160];
    std::snprintf(line, sizeof(line),
                  "the frame has %llu (pixel, light) pairs, more than the %llu the probe holds: rendering "
                  "again, keeping %.1f%% of them at random",
                  static_cast<unsigned long long>(probed.probe.wanted),
                  static_cast<unsigned long long>(capacity), 100.0 * keep);
    say(progress, line);
    probed = probe_frame(context, lit, settings, capacity, keep, progress);
    if (!probed.probe.complete()) {
      throw std::runtime_error("the probed frame still had more pairs than fit; raise --pairs-per-pixel");
    }
  }

  const SceneTriangles triangles = scene_triangles(probed.view->scene);
  std::vector<scene::LayerMask> masks;
  for (const FrameLight& light : probed.lights) masks.push_back(light.caster_mask);
  const CasterScenes casters(triangles, masks);
  const RayScene surfaces(triangles.surfaces);
  jobs::ThreadPool pool;
  const SurfacePoints points =
      surface_points(probed.depth, probed.view->pose, probed.view->lens, surfaces, pool);

  WholeFrameReport report;
  report.device = context.device_name();
  report.scene = frame.scene;
  report.width = frame.width;
  report.height = frame.height;
  report.frames = settings.frames;
  report.gpu_frame_ms = probed.gpu_frame_ms;
  report.lights = probed.lights.size();
  for (const FrameLight& light : probed.lights) {
    report.shadowed_lights += light.shadowed ? 1 : 0;
    report.lights_without_map += light.shadowed && light.resolution == 0 ? 1 : 0;
  }
  report.frame_pairs = probed.probe.wanted;
  report.list_pairs = probed.probe.listed;
  if (keep == 1.0f) report.lighting_list_pairs = probed.probe.lighting_list_pairs(frame.width);
  report.sampled_fraction = keep;
  report.soft_samples = settings.soft_samples;
  report.edge_band = settings.edge_band;
  say(progress, "scene: " + std::to_string(triangles.surfaces.size() / 3) + " triangles, " +
                    std::to_string(report.shadowed_lights) + " shadowed lights of " +
                    std::to_string(report.lights) + "; tracing on " + std::to_string(pool.thread_count()) +
                    " threads");

  const auto start = std::chrono::steady_clock::now();
  std::vector<TracedPair> traced =
      trace_pairs(probed.probe.pairs, probed.lights, points, casters, settings.soft_samples, pool, progress);
  report.trace_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.traced_pairs = traced.size();
  report.error = frame_error(std::move(traced), frame.width, frame.height, settings.edge_band);
  if (report.error.lights.size() > settings.worst_lights) report.error.lights.resize(settings.worst_lights);
  for (const LightError& error : report.error.lights) {
    const FrameLight& light = probed.lights[error.light];
    report.worst.push_back(
        {light.name, light.ray.type, std::string(to_string(light.algorithm)), light.resolution, error});
  }
  return report;
}

}  // namespace sg::reference
