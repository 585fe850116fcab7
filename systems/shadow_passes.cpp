#include "systems/shadow_passes.h"

#include <cstring>
#include <span>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_cube.frag.spv.h"
#include "shaders/shadow_cube_layered.vert.spv.h"
#include "shaders/shadow_map.vert.spv.h"
#include "systems/gpu_scene.h"
#include "systems/scene/mesh_library.h"
#include "systems/shader_bindings.h"
#include "systems/shadow_map_arrays.h"

namespace sg {
namespace {

using namespace bindings;
using shadows::CubeShadowMode;
using shadows::FrameLights;
using shadows::ShadowCubeView;
using shadows::ShadowMapView;

constexpr VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// shadow_map.vert reads bytes 0..63 (the view-projection), shadow_cube.frag bytes 64..79.
struct PassConstants {
  glm::mat4 view_projection;
  glm::vec4 light_position_far;
};

constexpr VkDeviceSize cube_faces_bytes = 6 * sizeof(glm::mat4);

}  // namespace

ShadowPasses::ShadowPasses(vk::VulkanContext& context, uint32_t frames_in_flight)
    : layout_(context.device(),
              {{instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT},
               {cube_faces_binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, VK_SHADER_STAGE_VERTEX_BIT},
               {view_instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}},
              vk::push_constants<PassConstants>(stages)),
      slot_sets_(layout_.allocate_sets(frames_in_flight)),
      casters_(context, frames_in_flight),
      cube_faces_(context, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, frames_in_flight, "cube face matrices") {
  const VkDeviceSize alignment = context.properties().limits.minUniformBufferOffsetAlignment;
  cube_faces_stride_ = (cube_faces_bytes + alignment - 1) / alignment * alignment;

  vk::GraphicsPipelineDesc desc;
  scene_vertex_input(desc, false);
  desc.depth_format = vk::to_vk(ShadowMapArrays::depth_format);
  // Receivers apply each light's own bias (ALGORITHMS.md section 4), so casters are drawn as
  // they are, both faces: thin and open meshes cast too.
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = layout_.get();
  desc.vertex_spirv = shadow_map_vert;
  desc.name = "shadow map";
  map_pipeline_ = vk::create_graphics_pipeline(context, desc);
  desc.fragment_spirv = shadow_cube_frag;
  desc.name = "shadow cube face";
  face_pipeline_ = vk::create_graphics_pipeline(context, desc);
  if (context.optional_features().shader_output_layer) {
    desc.vertex_spirv = shadow_cube_layered_vert;
    desc.name = "shadow cube layered";
    layered_pipeline_ = vk::create_graphics_pipeline(context, desc);
  }
}

void ShadowPasses::prepare(uint32_t slot, const FrameLights& lights, const GpuScene& scene,
                           CubeShadowMode mode, bool cull_casters) {
  constexpr glm::vec4 everywhere{0.0f, 0.0f, 0.0f, -1.0f};  // a view with no reach keeps every caster
  // Grid cells as large as the lights' mean reach (views without one do not use the grid).
  float reach_sum = 0.0f;
  uint32_t bounded = 0;
  const auto add_reach = [&](const glm::vec4& reach) {
    if (reach.w < 0.0f) return;
    reach_sum += reach.w;
    ++bounded;
  };
  for (const ShadowMapView& map : lights.maps) add_reach(map.reach);
  for (const ShadowCubeView& cube : lights.cubes) add_reach(cube.position_far);
  casters_.begin_frame(scene, bounded > 0 ? reach_sum / float(bounded) : 0.0f);
  map_casters_.clear();
  for (const ShadowMapView& map : lights.maps) {
    map_casters_.push_back(casters_.add_view(scene, cull_casters ? map.reach : everywhere, 1));
  }
  const uint32_t copies = mode == CubeShadowMode::layered && layered_supported() ? 6 : 1;
  cube_casters_.clear();
  for (const ShadowCubeView& cube : lights.cubes) {
    cube_casters_.push_back(casters_.add_view(scene, cull_casters ? cube.position_far : everywhere, copies));
  }
  casters_.upload(slot);

  cube_faces_scratch_.assign(std::max<size_t>(1, lights.cubes.size()) * cube_faces_stride_, std::byte{0});
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    std::memcpy(cube_faces_scratch_.data() + c * cube_faces_stride_,
                lights.cubes[c].views.view_projection.data(), cube_faces_bytes);
  }
  const vk::Buffer& faces = cube_faces_.write(slot, std::span<const std::byte>(cube_faces_scratch_));

  layout_.write(slot_sets_.sets[slot])
      .buffer(instances_binding, scene.instances(slot).handle())
      .buffer(cube_faces_binding, faces.handle(), 0, cube_faces_bytes)
      .buffer(view_instances_binding, casters_.ids(slot).handle())
      .update();
}

void ShadowPasses::draw_casters(VkCommandBuffer cmd, uint32_t slot, VkPipeline pipeline,
                                const glm::mat4& view_projection, const glm::vec4& position_far,
                                uint32_t cube_faces_offset, const GpuScene& scene, CasterView view) const {
  if (view.command_count == 0 || !scene.bind_geometry(cmd)) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  layout_.bind(cmd, slot_sets_.sets[slot], {&cube_faces_offset, 1});
  layout_.push(cmd, PassConstants{view_projection, position_far});
  casters_.draw(cmd, slot, view);
}

ShadowPasses::Targets ShadowPasses::add_to(rg::RenderGraph& graph, Targets targets, const FrameLights& lights,
                                           const GpuScene& scene, uint32_t slot, CubeShadowMode mode) const {
  const rg::ClearValue far = rg::ClearValue::depth_of(1.0f);
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    const ShadowMapView& map = lights.maps[m];
    const CasterView view = map_casters_[m];
    graph.add_pass(
        map.name,
        [&](rg::PassBuilder& b) {
          targets.maps =
              b.write(targets.maps, rg::Usage::depth_attachment, far, rg::SubresourceRange::layer(map.layer));
        },
        [this, &map, &scene, slot, view](const vk::PassRecorder& rec) {
          rec.set_viewport({{0, 0}, {map.resolution, map.resolution}});  // the light's square
          draw_casters(rec.cmd(), slot, map_pipeline_.get(), map.view.view_projection(), glm::vec4(0.0f), 0,
                       scene, view);
        });
  }

  const bool layered = mode == CubeShadowMode::layered && layered_supported();
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    const ShadowCubeView& cube = lights.cubes[c];
    const CasterView view = cube_casters_[c];
    const auto faces_offset = static_cast<uint32_t>(cube.cube * cube_faces_stride_);
    if (layered) {
      graph.add_pass(
          cube.name,
          [&](rg::PassBuilder& b) {
            targets.cubes = b.write(targets.cubes, rg::Usage::depth_attachment, far,
                                    rg::SubresourceRange::cube(cube.cube));
          },
          [this, &cube, &scene, slot, faces_offset, view](const vk::PassRecorder& rec) {
            rec.set_full_viewport();
            draw_casters(rec.cmd(), slot, layered_pipeline_.get(), glm::mat4(1.0f), cube.position_far,
                         faces_offset, scene, view);
          });
      continue;
    }
    for (uint32_t face = 0; face < 6; ++face) {
      graph.add_pass(
          cube.name + " face " + std::to_string(face),
          [&](rg::PassBuilder& b) {
            targets.cubes = b.write(targets.cubes, rg::Usage::depth_attachment, far,
                                    rg::SubresourceRange::cube_face(cube.cube, face));
          },
          [this, &cube, &scene, slot, face, faces_offset, view](const vk::PassRecorder& rec) {
            rec.set_full_viewport();
            draw_casters(rec.cmd(), slot, face_pipeline_.get(), cube.views.view_projection[face],
                         cube.position_far, faces_offset, scene, view);
          });
    }
  }
  return targets;
}

}  // namespace sg
