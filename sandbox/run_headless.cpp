// SPDX-License-Identifier: MIT
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "sandbox/run.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/script.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/interrupt.h"
#include "systems/frame/png.h"
#include "systems/frame/scene_view.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_requests.h"
#include "systems/scene/shadow_settings.h"

namespace sg::sandbox {

namespace {

// The light named `name` (lights are the entities with ShadowSettings).
ecs::Entity light_named(const ecs::World& world, const std::string& name, const std::string& where) {
  ecs::Entity found = ecs::null_entity;
  world.query<const scene::Name, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const scene::Name& light, const scene::ShadowSettings&) {
        if (light.value == name) found = entity;
      });
  if (found == ecs::null_entity) throw std::runtime_error(where + ": no light named \"" + name + "\"");
  return found;
}

// Runs `steps` (script.h) on `frame`, rendering where they wait; `open` replaces `scene` and
// `frame`.
RunRecord run_script(const Options& options, vk::VulkanContext& context, SceneView& scene,
                     std::unique_ptr<SandboxFrame>& frame, vk::FrameRing& frames, GpuTimeLog& gpu_times) {
  const std::vector<ScriptStep> steps = load_script(options.script);
  ecs::World& world = scene.scene.world;  // the same object after `open`, holding the new scene
  RunRecord record{{}, {}, &gpu_times};
  uint64_t rendered = 0;
  ecs::Entity selected = ecs::null_entity;
  for (const ScriptStep& step : steps) {
    if (interrupted()) break;
    const std::string where = options.script + ":" + std::to_string(step.line);
    const auto need_light = [&] {
      if (selected == ecs::null_entity)
        throw std::runtime_error(where + ": no light selected (select NAME first)");
      return selected;
    };
    std::visit(
        [&](const auto& command) {
          using Command = std::decay_t<decltype(command)>;
          if constexpr (std::is_same_v<Command, ScriptStep::Select>) {
            selected = light_named(world, command.name, where);
          } else if constexpr (std::is_same_v<Command, ScriptStep::Algorithm>) {
            world.get_mut<scene::ShadowSettings>(need_light()).algorithm = command.algorithm;
          } else if constexpr (std::is_same_v<Command, ScriptStep::Resolution>) {
            world.get_mut<scene::ShadowSettings>(need_light()).resolution = command.texels;
          } else if constexpr (std::is_same_v<Command, ScriptStep::Update>) {
            world.get_mut<scene::ShadowSettings>(need_light()).update = command.update;
          } else if constexpr (std::is_same_v<Command, ScriptStep::Priority>) {
            world.get_mut<scene::ShadowSettings>(need_light()).priority = command.tiers;
          } else if constexpr (std::is_same_v<Command, ScriptStep::RedrawShadow>) {
            scene::request_shadow_redraw(world, need_light());
          } else if constexpr (std::is_same_v<Command, ScriptStep::Move>) {
            world.get_mut<ecs::LocalTransform>(need_light()).translation = command.position;
          } else if constexpr (std::is_same_v<Command, ScriptStep::Camera>) {
            scene.pose = command.pose;
          } else if constexpr (std::is_same_v<Command, ScriptStep::Wait>) {
            record.append(render_headless_frames(frame->frame(), frames, command.frames, gpu_times, false,
                                                 rendered, &interrupted()));
            rendered = record.cpu_frame_ms.size();
          } else if constexpr (std::is_same_v<Command, ScriptStep::View>) {
            frame->set_view(command.view);
          } else if constexpr (std::is_same_v<Command, ScriptStep::Save>) {
            frame->save_edits();
          } else if constexpr (std::is_same_v<Command, ScriptStep::Open>) {
            const Options next = options_to_open(options, command.path);
            SceneView opened =
                load_scene_view(next.frame, float(next.frame.width) / float(next.frame.height));
            frames.wait_idle();
            frame.reset();
            scene = std::move(opened);
            frame = std::make_unique<SandboxFrame>(context, scene, next, frames.frames_in_flight());
            frame->fit({next.frame.width, next.frame.height}, false);
            selected = ecs::null_entity;
            std::printf("shadowgraph: opened %s\n", scene.scene.name.c_str());
          } else if constexpr (std::is_same_v<Command, ScriptStep::Screenshot>) {
            if (rendered == 0) throw std::runtime_error(where + ": nothing rendered yet (wait N first)");
            write_png(command.path, vk::read_rgba8(context, frame->frame().image()));
            std::printf("shadowgraph: wrote %s\n", command.path.c_str());
          }
        },
        step.command);
  }
  return record;
}

}  // namespace

int run_headless(const Options& options) {
  const FrameSettings& settings = options.frame;
  SceneView scene = load_scene_view(settings, float(settings.width) / float(settings.height));
  vk::VulkanContext context(context_options(settings));
  std::printf("shadowgraph: headless on %s, %ux%u, scene %s, camera from %s\n", context.device_name().c_str(),
              settings.width, settings.height, scene.scene.name.c_str(), scene.camera_source.c_str());

  vk::FrameRing frames(context);
  auto frame = std::make_unique<SandboxFrame>(context, scene, options, frames.frames_in_flight());
  frame->fit({settings.width, settings.height}, false);
  GpuTimeLog gpu_times;
  const RunRecord record = options.script.empty()
                               ? render_headless_frames(frame->frame(), frames, options.frames.value_or(3),
                                                        gpu_times, true, 0, &interrupted())
                               : run_script(options, context, scene, frame, frames, gpu_times);
  return finish_run(options, context, scene, *frame, record);
}

}  // namespace sg::sandbox
