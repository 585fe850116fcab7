// SPDX-License-Identifier: MIT
#pragma once
// Transparent surfaces (glTF alphaMode BLEND, the draw classes with draw_blended), after the
// opaque lighting and before tone mapping, on every lighting path. Where the opaque surfaces
// were lit from light lists per screen tile (deferred), so are these:
//
//   light tiles   (compute)  light culling bounded by the opaque depths and by where the
//                            transparent instances' boxes lie on screen (transparent_tile_bounds,
//                            on the CPU), so that each tile's lights reach its transparent
//                            surfaces too
//   transparent   (raster)   the surfaces back to front (GpuScene::order_transparent), each lit
//                            by its tile's lights and their shadows as the opaque surfaces are
//                            (shaders/transparent_tiled.frag), blended over the
//                            target by its alpha, depth-tested against the opaque depth, not
//                            writing it
//
// Where every light lit every pixel (fused, every light), the last pass alone, lighting with
// every light as they did (shaders/scene_fused.frag's transparent variant): a frame of a few
// lights pays no second culling for a few transparent pixels.
//
// The target is a lit sum, or the frame where the path tone-maps as it lights (fused).
// Surfaces are sorted as wholes, by their bounds' centres: intersecting or nested transparent
// meshes, and the faces within one mesh, blend in whatever order they come (no
// order-independent transparency).
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/lighting/camera_pipelines.h"
#include "systems/lighting/light_resources.h"
#include "systems/lighting/light_tiles_pass.h"
#include "systems/lighting/lighting_path.h"
#include "systems/scene/aabb.h"
#include "systems/shadows/light_groups.h"

namespace sg {

class GpuScene;
class GpuTextures;

class TransparentPass {
 public:
  // `textures` must outlive the pass.
  TransparentPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures);

  // Makes the pipelines for a target of `format`, lit from tile lists (`tiled`) or by every
  // light, for the frame's light groups (shadows::groups_present), `view` and the transparent
  // classes `scene` has. Tiled, writes the slot's tile bounds for a camera of `view_projection`
  // over `screen` pixels, from `scene`'s transparent instances.
  void prepare(rg::Format format, bool tiled, const shadows::GroupsPresent& groups, LightingView view,
               const GpuScene& scene, uint32_t slot, const glm::mat4& view_projection, glm::uvec2 screen);

  // LightTilesPass::take_dropped_pairs of the transparent surfaces' light tiles.
  uint64_t take_dropped_pairs(uint32_t slot) { return light_tiles_.take_dropped_pairs(slot); }
  // LightTilesPass::tiles_cut of the same.
  uint32_t tiles_cut() const { return light_tiles_.tiles_cut(); }

  // Blends the transparent surfaces of `scene` (as ordered for this frame) over `target`, as
  // prepared, tone-mapping them first where `constants.counts.w` is 1; returns its new version.
  // `depth`: the opaque surfaces'. `lights` (the first `light_count` records) and `scene` are
  // read when the passes record.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle target, rg::ImageHandle depth,
                         rg::ImageHandle atlas, const vk::Buffer& lights, uint32_t light_count,
                         const GpuScene& scene, uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  LightResources light_resources_;
  LightTilesPass light_tiles_;
  vk::FrameBuffers tile_bounds_;  // transparent_tile_bounds, per slot
  std::vector<scene::Aabb> boxes_;
  std::vector<glm::vec2> bounds_;
  vk::PipelineLayout tiled_layout_;        // transparent_tiled.frag's: the lights, the tile lists
  vk::PipelineLayout every_light_layout_;  // scene_fused.frag's: the lights
  std::unordered_map<uint64_t, CameraPipelines> pipelines_;  // by pipeline_key
  uint64_t key_ = 0;                                         // this frame's
  bool tiled_ = false;                                       // this frame's
};

}  // namespace sg
