// SPDX-License-Identifier: MIT
// Times what the CPU does for lights each frame, as SceneRenderer does it but without a device:
// animate and update transforms, gather the lights, schedule their shadow maps (place cascades,
// importances, atlas plan, cache, the moving crates' boxes), sort the records by group (into an
// array that stands for the frame's mapped light buffer). The stress hall, its lights and its
// street camera are the sandbox's (--scene stress --camera street), so the phases read against
// the sandbox's --stats cpu_phases_ms. The shadow cache fills over the first frames (at 4,096
// views a frame, about 63 of them for 100,000 lights), and the schedule costs less after: compare
// runs of the same --frames.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <CLI/CLI.hpp>

#include "ecs/jobs/thread_pool.h"
#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "systems/frame/scene_view.h"
#include "systems/gpu/camera.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/scene_queries.h"
#include "systems/shadows/cascades.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/shadow_atlas_shape.h"
#include "systems/shadows/shadow_schedule.h"
#include "systems/shadows/shadow_view_path.h"

namespace {

using namespace sg;

struct Options {
  uint32_t point_lights = 50'000;
  uint32_t spot_lights = 50'000;
  float moving = 0.05f;
  uint32_t frames = 60;
  uint32_t threads = 0;  // 0: one per core
  uint32_t width = 1920;
  uint32_t height = 1080;
  std::string camera = "street";
  // The sandbox's default on the H200 (an eighth of its memory, capped): 16 pages of 4096 with
  // static layers. Few pages demote fewer lights than many: the budget's walk costs differ.
  uint32_t shadow_memory_mib = 2048;
};

// The boxes of the casters that moved, where they were and where they are, as the renderer
// passes them to the schedule each frame (SceneRenderer::caster_update): the stress scene's
// orbiting crates. The schedule tests every light not redrawn yet against them.
class MovedCasters {
 public:
  // The instances whose transform was written after `since`; none at the first frame.
  std::span<const scene::Aabb> update(const scene::Scene& scene, ecs::Tick since) {
    boxes_.clear();
    scene.world.query<const scene::MeshInstance, const ecs::WorldTransform>()
        .changed_since<ecs::WorldTransform>(since)
        .for_each([&](ecs::Entity entity, const scene::MeshInstance& instance,
                      const ecs::WorldTransform& world) {
          if (!instance.casts_shadow) return;
          const scene::Aabb now = scene::transformed(scene.meshes.meshes[instance.mesh].bounds, world.matrix);
          const auto [last, first_seen] = last_.try_emplace(ecs::entity_key(entity), now);
          if (first_seen || (last->second.min == now.min && last->second.max == now.max)) return;
          boxes_.push_back(last->second);
          boxes_.push_back(now);
          last->second = now;
        });
    return boxes_;
  }

 private:
  std::unordered_map<uint64_t, scene::Aabb> last_;  // by entity key
  std::vector<scene::Aabb> boxes_;
};

struct Phases {
  std::vector<double> update, gather, schedule, sort;
  std::array<std::vector<double>, shadows::schedule_step_count> schedule_steps;  // within schedule
};

double median(std::vector<double> samples) {
  if (samples.empty()) return 0.0;
  std::nth_element(samples.begin(), samples.begin() + std::ptrdiff_t(samples.size() / 2), samples.end());
  return samples[samples.size() / 2];
}

int run(const Options& options) {
  // Loaded as the sandbox loads it: the stress scene and the camera named, no sidecar.
  FrameSettings settings;
  settings.scene = "stress";
  settings.camera_name = options.camera;
  settings.scene_params.point_lights = options.point_lights;
  settings.scene_params.spot_lights = options.spot_lights;
  settings.scene_params.moving_fraction = options.moving;
  const float aspect = float(options.width) / float(options.height);
  SceneView view = load_scene_view(settings, aspect);
  ecs::World& world = view.scene.world;
  const scene::Aabb bounds = scene::scene_bounds(view.scene);
  const scene::CameraPose& pose = view.pose;
  const scene::Camera& lens = view.lens;
  const shadows::ShadowCamera camera{pose.eye, projection_matrix(lens, aspect) * view_matrix(pose),
                                     float(options.height) / lens.yfov};

  jobs::ThreadPool pool(options.threads == 0 ? jobs::ThreadPool::default_workers() : options.threads - 1);
  shadows::FrameLights lights;
  std::vector<shadows::GpuLight> sorted;  // the frame's light buffer, in the sandbox
  const shadows::AtlasShape shape = shadows::atlas_shape(uint64_t{options.shadow_memory_mib} << 20,
                                                         {.max_allocation_bytes = 4ull << 30,
                                                          .device_local_heap_bytes = 16ull << 30,
                                                          .max_storage_buffer_bytes = 4ull << 30},
                                                         true);
  shadows::ShadowSchedule schedule({shape.page_size, shape.max_pages, shadows::min_shadow_resolution}, true);
  Phases phases;
  // The first frame in which no shadowed light waited for its first map: the frames before draw
  // the maps' first fill (at 100,000 lights and 4,096 views a frame, 67-85 frames).
  std::optional<size_t> first_maps;
  MovedCasters moved_casters;
  ecs::Tick transforms_updated = 0;
  std::printf(
      "light-bench: %u point and %u spot lights, %.0f%% moving, %u threads, %ux%u, camera %s, atlas %u pages "
      "of %u\n",
      options.point_lights, options.spot_lights, 100.0 * options.moving, pool.thread_count(), options.width,
      options.height, options.camera.c_str(), shape.max_pages, shape.page_size);
  for (uint32_t frame = 0; frame < options.frames; ++frame) {
    auto mark = std::chrono::steady_clock::now();
    const auto lap = [&](std::vector<double>& samples) {
      const auto now = std::chrono::steady_clock::now();
      samples.push_back(std::chrono::duration<double, std::milli>(now - mark).count());
      mark = now;
    };
    pool.wake();
    scene::animate_orbits(world, float(frame) / 60.0f, &pool);
    ecs::update_world_transforms(world, transforms_updated, &pool);
    const std::span<const scene::Aabb> moved = moved_casters.update(view.scene, transforms_updated);
    transforms_updated = world.tick();
    world.advance_tick();
    lap(phases.update);
    shadows::gather_lights(world, bounds, {}, lights, &pool);
    lap(phases.gather);
    shadows::place_cascades(lights, shadows::cascade_camera(pose, lens, aspect), bounds);
    schedule.schedule(lights, camera, shadows::CasterUpdate::changes({}, moved),
                      shadows::default_shadow_view_budget, &pool);
    lap(phases.schedule);
    for (size_t step = 0; step < shadows::schedule_step_count; ++step) {
      phases.schedule_steps[step].push_back(schedule.step_times()[step]);
    }
    sorted.resize(lights.records.size());
    shadows::sort_by_group(lights, sorted, &pool);
    lap(phases.sort);
    if (!first_maps && schedule.stats().lights_waiting == 0) first_maps = frame;
  }
  // The medians are of the frames from the first in which every light had its map; where lights
  // waited in every frame, of them all, which the line says.
  const size_t settled_from = first_maps.value_or(0);
  const auto settled = [&](std::vector<double>& samples) {
    samples.erase(samples.begin(), samples.begin() + std::ptrdiff_t(settled_from));
    return median(samples);
  };
  const double update = settled(phases.update), gather = settled(phases.gather),
               scheduled = settled(phases.schedule), sort = settled(phases.sort);
  const std::string which =
      first_maps ? "from frame " + std::to_string(settled_from) + ", the first with every light's map"
                 : "(lights waited for a first map in every frame: these are the maps' first fill)";
  std::printf(
      "light-bench: medians over %zu frames %s, ms: update %.2f gather %.2f schedule %.2f sort %.2f "
      "(gather + schedule + sort %.2f)\n",
      phases.gather.size(), which.c_str(), update, gather, scheduled, sort, gather + scheduled + sort);
  shadows::ScheduleStepTimes steps{};
  for (size_t step = 0; step < shadows::schedule_step_count; ++step)
    steps[step] = settled(phases.schedule_steps[step]);
  std::printf("light-bench: the schedule's steps, medians of the same frames, ms: %s\n",
              shadows::schedule_steps_text(steps).c_str());
  const shadows::ShadowScheduleStats& stats = schedule.stats();
  std::printf(
      "light-bench: last frame: %u views drawn (%u of them moving casters only), %u cached, %u lights "
      "without a "
      "shadow\n",
      stats.views_rendered, stats.views_moving_only, stats.views_cached, stats.lights_without_shadow);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Times gathering and scheduling many lights on the CPU (no GPU)"};
  app.add_option("--point-lights", options.point_lights);
  app.add_option("--spot-lights", options.spot_lights);
  app.add_option("--moving-lights", options.moving, "fraction of lights and crates that orbit")
      ->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--frames", options.frames)->check(CLI::Range(1u, 100'000u));
  app.add_option("--threads", options.threads, "threads, the caller included; 0: one per core");
  app.add_option("--width", options.width)->check(CLI::Range(1u, 16384u));
  app.add_option("--height", options.height)->check(CLI::Range(1u, 16384u));
  app.add_option("--camera", options.camera, "a camera of the stress scene: street or overview");
  app.add_option("--shadow-memory", options.shadow_memory_mib, "the atlas's budget in MiB, as the sandbox's")
      ->check(CLI::Range(1u, 1u << 20));
  CLI11_PARSE(app, argc, argv);
  try {
    return run(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "light-bench: %s\n", error.what());
    return 1;
  }
}
