// SPDX-License-Identifier: MIT
#include "tools/reference/run_reference.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "ecs/jobs/thread_pool.h"
#include "rendergraph/device/context.h"
#include "systems/frame/interrupt.h"
#include "systems/frame/png.h"
#include "systems/frame/scene_view.h"
#include "tools/reference/engine_shade.h"
#include "tools/reference/ray_scene.h"
#include "tools/reference/scene_triangles.h"
#include "tools/reference/shade_images.h"
#include "tools/reference/surface_points.h"
#include "tools/reference/visibility.h"

namespace sg::reference {
namespace {

// A light's name as part of a file name: letters and digits kept, anything else '_'.
std::string file_stem(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return out;
}

std::vector<ReferenceLight> chosen_lights(const scene::Scene& scene, const ReferenceSettings& settings) {
  std::vector<ReferenceLight> out;
  for (ReferenceLight& light : shadowed_lights(scene)) {
    if (settings.max_lights && out.size() == settings.max_lights) break;
    if (light.name.find(settings.light_filter) != std::string::npos) out.push_back(std::move(light));
  }
  if (out.empty()) {
    throw std::runtime_error(
        "scene '" + scene.name + "' has no shadow-casting light" +
        (settings.light_filter.empty() ? "" : " named like '" + settings.light_filter + "'"));
  }
  return out;
}

scene::ShadowSettings run_settings(scene::ShadowSettings shadow, const ReferenceSettings& settings,
                                   scene::ShadowAlgorithm algorithm, uint32_t resolution) {
  shadow.algorithm = algorithm;
  shadow.resolution = resolution;
  shadow.casts_shadow = true;
  if (settings.constant_bias) shadow.constant_bias = *settings.constant_bias;
  if (settings.slope_bias) shadow.slope_bias = *settings.slope_bias;
  return shadow;
}

// The light's references traced from `points`, then its render for each resolution and
// algorithm of `settings` measured against them (and pictured, with an image folder).
LightReport compare_light(EngineShade& engine, const SurfacePoints& points, const RayScene& casters,
                          const ReferenceLight& light, const ReferenceSettings& settings,
                          jobs::ThreadPool& pool, const Progress& progress) {
  LightReport result{light.name, light.type, 0.0, {}};
  const auto start = std::chrono::steady_clock::now();
  const std::vector<float> hard = hard_visibility(casters, points, light, pool);
  const std::vector<float> soft = soft_visibility(casters, points, light, settings.soft_samples, pool);
  result.trace_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char line[160];
  std::snprintf(line, sizeof(line), "  references traced in %.2f s", result.trace_seconds);
  say(progress, line);

  engine.isolate(light);
  const scene::ShadowSettings own = engine.isolated_settings();
  const std::vector<uint32_t> resolutions =
      settings.resolutions.empty() ? std::vector<uint32_t>{own.resolution} : settings.resolutions;
  const uint32_t w = points.width;
  const uint32_t h = points.height;
  const std::string stem = settings.image_folder + "/" + file_stem(light.name);
  for (const uint32_t resolution : resolutions) {
    for (const scene::ShadowAlgorithm algorithm : settings.algorithms) {
      const EngineVisibility render = engine.visibility(run_settings(own, settings, algorithm, resolution));
      ShadowImages images{w, h, render.measured, hard, soft, render.visibility};
      for (size_t i = 0; i < images.measured.size(); ++i) {
        images.measured[i] = images.measured[i] && points.points[i].valid;
      }
      const ShadowMetrics metrics = shadow_metrics(images, settings.edge_band);
      result.runs.push_back({algorithm, resolution, render.resolution, metrics});
      const std::string name(to_string(algorithm));
      std::snprintf(line, sizeof(line),
                    "  %-10s map %4u: misclassified %.2f%%, penumbra MAE %.3f, acne %.2f%%", name.c_str(),
                    render.resolution, 100.0 * metrics.misclassified, metrics.penumbra.mean_absolute,
                    100.0 * metrics.acne);
      say(progress, line);
      if (settings.image_folder.empty()) continue;
      if (result.runs.size() == 1) {
        write_png(stem + "_reference_hard.png", visibility_image(w, h, hard, images.measured));
        write_png(stem + "_reference_soft.png", visibility_image(w, h, soft, images.measured));
      }
      const std::string run = stem + "_" + name + "_" + std::to_string(resolution);
      write_png(run + "_engine.png", visibility_image(w, h, render.visibility, images.measured));
      // Hard shadows are compared with the hard reference, the filtered ones with the soft.
      const std::vector<float>& truth = algorithm == scene::ShadowAlgorithm::hard ? hard : soft;
      write_png(run + "_difference.png", difference_image(w, h, render.visibility, truth, images.measured));
    }
  }
  return result;
}

std::vector<AlgorithmCost> measure_costs(vk::VulkanContext& context, const FrameSettings& frame,
                                         const ReferenceSettings& settings, const Progress& progress) {
  // Every map redrawn every frame: the cost of a frame whose lights or casters all move.
  FrameSettings timed = frame;
  timed.renderer.cache_shadows = false;
  timed.renderer.view = LightingView::lit;
  std::vector<AlgorithmCost> out;
  FrameSettings off = timed;
  off.renderer.lights.shadows = false;
  say(progress, "cost: shadows off");
  out.push_back({"off", measure_frame_cost(context, off, settings.cost_frames)});
  for (const scene::ShadowAlgorithm algorithm : settings.algorithms) {
    FrameSettings run = timed;
    run.algorithm = algorithm;
    say(progress, "cost: " + std::string(to_string(algorithm)));
    out.push_back(
        {std::string(to_string(algorithm)), measure_frame_cost(context, run, settings.cost_frames)});
  }
  return out;
}

}  // namespace

ReferenceReport run_reference(vk::VulkanContext& context, const FrameSettings& frame,
                              const ReferenceSettings& settings, const Progress& progress) {
  SceneView scene = load_scene_view(frame, float(frame.width) / float(frame.height));
  for (const std::string& name : settings.no_shadow_from) {
    if (stop_casting(scene.scene, name) == 0) {
      throw std::runtime_error("scene '" + scene.scene.name + "' has no shadow-casting mesh named like '" +
                               name + "'");
    }
  }
  const std::vector<ReferenceLight> lights = chosen_lights(scene.scene, settings);
  if (!settings.image_folder.empty()) std::filesystem::create_directories(settings.image_folder);

  ReferenceReport report;
  report.device = context.device_name();
  report.scene = frame.scene;
  report.width = frame.width;
  report.height = frame.height;
  report.soft_samples = settings.soft_samples;
  report.edge_band = settings.edge_band;

  const SceneTriangles triangles = scene_triangles(scene.scene);
  say(progress, "scene: " + std::to_string(triangles.surfaces.size() / 3) + " triangles, " +
                    std::to_string(lights.size()) + " shadowed lights to compare");
  std::vector<scene::LayerMask> masks;
  for (const ReferenceLight& light : lights) masks.push_back(light.caster_mask);
  const CasterScenes casters(triangles, masks);
  const RayScene surfaces(triangles.surfaces);
  jobs::ThreadPool pool;
  {
    EngineShade engine(context, scene, frame);
    const SurfacePoints points = surface_points(engine.depth(), scene.pose, scene.lens, surfaces, pool);
    for (size_t l = 0; l < lights.size() && !interrupted(); ++l) {
      say(progress, "light " + std::to_string(l + 1) + "/" + std::to_string(lights.size()) + " '" +
                        lights[l].name + "' (" + std::string(to_string(lights[l].type)) + ")");
      report.lights.push_back(compare_light(engine, points, casters.of(lights[l].caster_mask), lights[l],
                                            settings, pool, progress));
    }
  }
  report.interrupted = interrupted();
  if (settings.cost_frames > 0 && !report.interrupted) {
    report.costs = measure_costs(context, frame, settings, progress);
  }
  return report;
}

}  // namespace sg::reference
