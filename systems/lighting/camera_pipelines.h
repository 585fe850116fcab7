// SPDX-License-Identifier: MIT
#pragma once
// What the passes that draw the scene from the camera share in setting up their pipelines: the
// lit passes' bindings, the camera pipeline, and a pass's pipelines, one per draw class
// (gpu_scene.h: double-sided, masked, transparent), each made the first time the scene has
// instances of its class: most scenes draw only single-sided, unmasked surfaces, and a pipeline
// that culls nothing or may discard costs raster work on every surface it draws.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/pipeline.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/lighting/lighting_path.h"
#include "systems/shadows/light_groups.h"

namespace sg {

class GpuTextures;

// The descriptor bindings of a pass that draws the scene from the camera and lights its surfaces
// in the fragment shader (material.glsl, light_shading.glsl): the light resources, the instances
// and the material textures, then `more`.
std::vector<VkDescriptorSetLayoutBinding> lit_camera_bindings(
    std::vector<VkDescriptorSetLayoutBinding> more = {});

// A pipeline that draws the scene from the camera (shaders/scene.vert, draw_camera_pass) into
// `color_formats` with `fragment`, depth-tested against camera_depth_format; callers may
// adjust the rest.
vk::GraphicsPipelineDesc camera_pipeline_desc(std::span<const uint32_t> fragment,
                                              std::vector<VkFormat> color_formats, VkPipelineLayout layout,
                                              std::string name);

class CameraPipelines {
 public:
  // `desc_of` gives the pipeline of a draw class (for_draw_class, where the pass needs nothing
  // else), of the opaque classes or, with `transparent`, of the transparent ones
  // (TransparentPass).
  explicit CameraPipelines(std::function<vk::GraphicsPipelineDesc(uint32_t draw_class)> desc_of,
                           bool transparent = false)
      : desc_of_(std::move(desc_of)), transparent_(transparent) {}

  // Makes the pipelines of the classes (of its kind) `scene` draws that are not made yet.
  void prepare(vk::VulkanContext& context, const GpuScene& scene);
  // By draw class; VK_NULL_HANDLE for a class not prepared.
  std::array<VkPipeline, draw_class_count> get() const;

 private:
  std::function<vk::GraphicsPipelineDesc(uint32_t)> desc_of_;
  bool transparent_;
  std::array<vk::UniquePipeline, draw_class_count> pipelines_;
};

// `desc`, a pipeline for single-sided unmasked surfaces whose fragment specialization came from
// material_pass_constants (gpu_textures.h), made to draw `draw_class`: no culling for double-sided
// surfaces, the cut-out for masked ones.
vk::GraphicsPipelineDesc for_draw_class(vk::GraphicsPipelineDesc desc, uint32_t draw_class);

// The fragment shader of a pass that shades every light group at once (shaders/scene_fused.frag
// and its transparent variant, shaders/transparent_tiled.frag) for the groups present, `groups`
// (bit g for group g): `few[n - 1]`, its variant that calls the shading for n groups alone
// (shaders/group_slots.glsl), where there are n <= 4 groups; `every` otherwise.
std::span<const uint32_t> for_groups(uint32_t groups, std::span<const uint32_t> every,
                                     const std::array<std::span<const uint32_t>, 4>& few);

// The fragment specialization of such a pass: material_pass_constants with GROUPS_PRESENT and
// `view`, then LIGHT_TYPES (constant_id 3), GROUPS_SINGLE (4), GROUP_TYPES (5) and
// GROUP_SLOT_LIST (6), the groups present in order, four bits each.
std::vector<uint32_t> all_groups_pass_constants(const shadows::GroupsPresent& groups, LightingView view,
                                                const GpuTextures& textures);

// `desc` shading only what a depth prepass kept (DepthPrepass, the same positions): tested for the
// prepass's depth without writing it.
vk::GraphicsPipelineDesc after_depth_prepass(vk::GraphicsPipelineDesc desc);

}  // namespace sg
