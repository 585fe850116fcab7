#include "systems/depth_prepass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/depth_prepass.vert.spv.h"
#include "systems/gpu_scene.h"
#include "systems/shader_bindings.h"

namespace sg {

DepthPrepass::DepthPrepass(vk::VulkanContext& context)
    : layout_(context.device(),
              {{bindings::instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<FrameConstants>(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT)) {
  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = depth_prepass_vert;
  scene_vertex_input(desc, false);
  desc.depth_format = vk::to_vk(camera_depth_format);
  desc.depth_compare = camera_depth_test;
  desc.layout = layout_.get();
  desc.name = "depth prepass";
  pipeline_ = vk::create_graphics_pipeline(context, desc);
}

rg::ImageHandle DepthPrepass::add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height,
                                     const GpuScene& scene, uint32_t slot,
                                     const FrameConstants& constants) const {
  rg::ImageHandle depth;
  graph.add_pass(
      "depth prepass",
      [&](rg::PassBuilder& b) {
        depth = b.write(b.create_image("depth", {width, height, camera_depth_format}),
                        rg::Usage::depth_attachment, camera_depth_clear);
      },
      [this, &scene, slot, constants](const vk::PassRecorder& rec) {
        const VkDescriptorSet set = layout_.write(rec.allocate_set(layout_))
                                        .buffer(bindings::instances_binding, scene.instances(slot).handle())
                                        .update();
        scene.draw_camera_pass(rec, pipeline_.get(), layout_, set, constants, slot);
      });
  return depth;
}

}  // namespace sg
