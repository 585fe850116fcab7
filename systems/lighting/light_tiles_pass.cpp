// SPDX-License-Identifier: MIT
#include "systems/lighting/light_tiles_pass.h"

#include <array>
#include <cstring>
#include <span>
#include <stdexcept>
#include <vector>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/light_tiles.comp.spv.h"
#include "shaders/light_tiles_coarse.comp.spv.h"
#include "shaders/light_tiles_coarse_transparent.comp.spv.h"
#include "shaders/light_tiles_serial.comp.spv.h"
#include "shaders/light_tiles_serial_transparent.comp.spv.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadows/light_groups.h"

namespace sg {
namespace {

using namespace bindings;
using shadows::light_group_count;
constexpr VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;

// light_tiles_interface.glsl's Feedback.
struct Feedback {
  uint32_t dropped_pairs = 0;
  uint32_t entries_wanted = 0;
  uint32_t coarse_wanted = 0;
  uint32_t tiles_cut = 0;
  TilesByGroups tiles_by_groups{};
};

// The groups' dispatches, then the group sets'.
constexpr uint32_t dispatch_count = light_group_count + tiles::LIGHT_GROUP_SETS;

// The most entries the pool may hold: what one storage buffer binding reaches, and at most 1 GiB
// (a quarter of a billion (tile, light) pairs; 1,024 lights in every tile of a 3840x2160 frame
// take 127 MiB).
uint64_t device_pool_entries(const vk::VulkanContext& context) {
  const uint64_t bytes =
      std::min<uint64_t>(context.properties().limits.maxStorageBufferRange, uint64_t{1} << 30);
  return bytes / sizeof(uint32_t);
}

// Every dispatch starts at zero workgroups (the culling counts them) of height and depth 1.
std::array<glm::uvec4, dispatch_count> empty_commands() {
  std::array<glm::uvec4, dispatch_count> commands;
  commands.fill(glm::uvec4(0u, 1u, 1u, 0u));
  return commands;
}

// Measured on lavapipe (2026-11-30), `default` scene at 1280x720: a workgroup per tile 14.5-14.7 ms (4 x 4
// threads; 17.8 with 8 x 8), an invocation per tile 3.4-6.2 ms; 1,024 lights at 640x360: 9.6
// against 3.6 ms. On the H200 with 1,024 lights, 8 x 8 threads per tile take 0.11 ms.
LightCullingShape resolve(LightCullingShape shape, const vk::VulkanContext& context) {
  if (shape != LightCullingShape::automatic) return shape;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
             ? LightCullingShape::thread_per_tile
             : LightCullingShape::workgroup_per_tile;
}

using Spirv = std::span<const uint32_t>;

vk::UniquePipeline culling_pipeline(vk::VulkanContext& context, LightCullingShape shape,
                                    bool transparent_bounds, VkPipelineLayout layout) {
  const Spirv spirv = shape == LightCullingShape::workgroup_per_tile ? Spirv(light_tiles_comp)
                      : transparent_bounds ? Spirv(light_tiles_serial_transparent_comp)
                                           : Spirv(light_tiles_serial_comp);
  return vk::create_compute_pipeline(context, {spirv, {}, layout, "light tiles"});
}

vk::UniquePipeline coarse_pipeline(vk::VulkanContext& context, bool transparent_bounds,
                                   VkPipelineLayout layout) {
  const Spirv spirv =
      transparent_bounds ? Spirv(light_tiles_coarse_transparent_comp) : Spirv(light_tiles_coarse_comp);
  return vk::create_compute_pipeline(context, {spirv, {}, layout, "light tiles coarse"});
}

// The descriptors each culling shader declares, and no others: a CPU driver reads every descriptor
// of a bound set, written or not.
VkDescriptorSetLayoutBinding storage_buffer(int binding) {
  return {uint32_t(binding), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute, nullptr};
}

// shaders/light_tile_bounds.glsl's: the scene's depth, and the transparent surfaces' bounds.
void add_bounds_bindings(std::vector<VkDescriptorSetLayoutBinding>& bindings, bool transparent_bounds) {
  bindings.push_back({scene_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute, nullptr});
  if (transparent_bounds) bindings.push_back(storage_buffer(transparent_bounds_binding));
}

// shaders/light_tiles_coarse.glsl's.
void add_coarse_bindings(std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  for (const int binding : {tile_volumes_binding, coarse_lights_binding, coarse_ranges_binding}) {
    bindings.push_back(storage_buffer(binding));
  }
}

std::vector<VkDescriptorSetLayoutBinding> culling_bindings(LightCullingShape shape, bool transparent_bounds) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const int binding : {lights_binding, light_tiles_feedback_binding, tile_lights_binding,
                            tile_ranges_binding, group_tiles_binding, group_commands_binding}) {
    bindings.push_back(storage_buffer(binding));
  }
  if (shape == LightCullingShape::workgroup_per_tile) {
    add_coarse_bindings(bindings);
  } else {
    add_bounds_bindings(bindings, transparent_bounds);
  }
  return bindings;
}

std::vector<VkDescriptorSetLayoutBinding> coarse_bindings(bool transparent_bounds) {
  std::vector<VkDescriptorSetLayoutBinding> bindings{storage_buffer(lights_binding),
                                                     storage_buffer(light_tiles_feedback_binding)};
  add_bounds_bindings(bindings, transparent_bounds);
  add_coarse_bindings(bindings);
  return bindings;
}

const Feedback no_feedback{};

// shaders/light_tiles.glsl's TileVolume: eleven 16-byte vectors.
constexpr uint64_t tile_volume_bytes = 11 * sizeof(glm::vec4);

}  // namespace

// light_tiles_interface.glsl's push constants.
struct LightTilesPass::Constants {
  glm::mat4 inverse_view_projection;
  glm::uvec4 screen;  // width, height, tiles across, tiles in all
  glm::uvec4 counts;  // lights, entries in the pool, entries in the coarse pool, coarse segments
  GroupSets sets;
};
static_assert(sizeof(GroupSets) % sizeof(glm::uvec4) == 0);

// The coarse pass's outputs (shaders/light_tiles_coarse.glsl).
struct LightTilesPass::CoarseLists {
  rg::BufferHandle volumes;  // per tile (TileVolume)
  rg::BufferHandle lights;   // the pool of the coarse tiles' lists
  rg::BufferHandle ranges;   // per coarse tile
};

LightTileGrid LightTileGrid::coarse() const {
  return {(across + tiles::LIGHT_COARSE_SIDE - 1) / tiles::LIGHT_COARSE_SIDE,
          (down + tiles::LIGHT_COARSE_SIDE - 1) / tiles::LIGHT_COARSE_SIDE};
}

LightTileGrid LightTileGrid::of(uint32_t width, uint32_t height) {
  return {(width + tiles::LIGHT_TILE_SIZE - 1) / tiles::LIGHT_TILE_SIZE,
          (height + tiles::LIGHT_TILE_SIZE - 1) / tiles::LIGHT_TILE_SIZE};
}

uint64_t LightTilesPass::ranges_bytes(LightTileGrid grid) {
  return uint64_t{grid.count()} * light_group_count * sizeof(glm::uvec2);
}
uint64_t LightTilesPass::tiles_bytes(LightTileGrid grid) {
  return uint64_t{grid.count()} * dispatch_count * sizeof(uint32_t);
}
uint64_t LightTilesPass::commands_bytes() { return dispatch_count * sizeof(glm::uvec4); }
uint64_t LightTilesPass::dispatch_offset(uint32_t group) { return group * sizeof(glm::uvec4); }

LightTilesPass::LightTilesPass(vk::VulkanContext& context, uint32_t frames_in_flight, LightCullingShape shape,
                               bool transparent_bounds, uint64_t most_pool_entries,
                               uint64_t most_coarse_entries)
    : shape_(resolve(shape, context)),
      transparent_bounds_(transparent_bounds),
      feedback_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "light tiles feedback",
                VK_FORMAT_UNDEFINED, vk::MemoryUsage::readback),
      pool_(most_pool_entries > 0 ? most_pool_entries : device_pool_entries(context)),
      coarse_pool_(most_coarse_entries > 0 ? most_coarse_entries : device_pool_entries(context)),
      nearest_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      layout_(context.device(), culling_bindings(shape_, transparent_bounds),
              vk::push_constants<Constants>(compute)),
      pipeline_(culling_pipeline(context, shape_, transparent_bounds, layout_.get())) {
  if (shape_ == LightCullingShape::workgroup_per_tile) {
    coarse_layout_ = vk::PipelineLayout(context.device(), coarse_bindings(transparent_bounds),
                                        vk::push_constants<Constants>(compute));
    coarse_pipeline_ = coarse_pipeline(context, transparent_bounds, coarse_layout_.get());
  }
  // The slots' buffers start with whatever their memory held: nothing culled yet.
  for (uint32_t slot = 0; slot < frames_in_flight; ++slot) feedback_.write(slot, std::span(&no_feedback, 1));
}

uint64_t LightTilesPass::take_dropped_pairs(uint32_t slot) {
  Feedback feedback;
  std::memcpy(&feedback, feedback_.buffer(slot).mapped(), sizeof(feedback));
  feedback_.write(slot, std::span(&no_feedback, 1));
  pool_.asked(feedback.entries_wanted);
  coarse_pool_.asked(feedback.coarse_wanted);
  listed_pairs_ = feedback.entries_wanted;
  tiles_cut_ = feedback.tiles_cut;
  tiles_by_groups_ = feedback.tiles_by_groups;
  return feedback.dropped_pairs;
}

LightTiles LightTilesPass::add_to(rg::RenderGraph& graph, uint32_t slot, rg::ImageHandle depth,
                                  const vk::Buffer& lights, uint32_t light_count,
                                  const glm::mat4& view_projection, const LightTiles* outputs,
                                  const vk::Buffer* transparent_bounds, const GroupSets& group_sets) const {
  if ((transparent_bounds != nullptr) != transparent_bounds_) {
    throw std::logic_error(
        "LightTilesPass::add_to: transparent bounds given to a pass made without them, or "
        "missing on one made with them");
  }
  const rg::ImageDesc& screen = graph.resources()[depth.index].image;
  const LightTileGrid grid = LightTileGrid::of(screen.width, screen.height);
  const uint64_t pool_entries = outputs
                                    ? graph.resources()[outputs->lights.index].buffer.size / sizeof(uint32_t)
                                    : pool_.entries(grid.count(), light_count);
  const rg::BufferHandle reset_commands = [&] {
    rg::BufferHandle commands;
    graph.add_pass(
        "light tiles reset",
        [&](rg::PassBuilder& b) {
          commands =
              b.write(outputs ? outputs->commands : b.create_buffer("tile commands", {commands_bytes()}),
                      rg::Usage::transfer);
          return commands;
        },
        [](rg::BufferHandle written, const vk::PassRecorder& rec) {
          const auto commands = empty_commands();
          vkCmdUpdateBuffer(rec.cmd(), rec.buffer(written), 0, sizeof(commands), commands.data());
        });
    return commands;
  }();
  const bool serial = shape_ == LightCullingShape::thread_per_tile;
  const uint64_t coarse_entries = serial ? 0 : coarse_pool_.entries(grid.coarse().count(), light_count);
  const uint32_t coarse_segments =
      light_count >= tiles::LIGHT_COARSE_SEGMENT_LIGHTS ? tiles::LIGHT_COARSE_SEGMENTS : 1u;
  const Constants constants{glm::inverse(view_projection),
                            {screen.width, screen.height, grid.across, grid.count()},
                            {light_count, uint32_t(pool_entries), uint32_t(coarse_entries), coarse_segments},
                            group_sets};
  CoarseLists lists;
  if (!serial) lists = add_coarse_pass(graph, slot, depth, lights, constants, transparent_bounds, grid);
  LightTiles out;
  graph.add_pass(
      "light tiles",
      [&](rg::PassBuilder& b) {
        if (serial) {
          b.read(depth, rg::Usage::sampled_compute);
        } else {
          for (const rg::BufferHandle read : {lists.volumes, lists.lights, lists.ranges}) {
            b.read(read, rg::Usage::storage_compute);
          }
        }
        const auto output = [&](const rg::BufferHandle* given, const char* name, uint64_t bytes) {
          return b.write(given ? *given : b.create_buffer(name, {bytes}), rg::Usage::storage_compute);
        };
        out.lights =
            output(outputs ? &outputs->lights : nullptr, "tile lights", pool_entries * sizeof(uint32_t));
        out.ranges = output(outputs ? &outputs->ranges : nullptr, "tile ranges", ranges_bytes(grid));
        out.tiles = output(outputs ? &outputs->tiles : nullptr, "group tiles", tiles_bytes(grid));
        out.commands = b.write(reset_commands, rg::Usage::storage_compute);
        return out;
      },
      [this, slot, depth, transparent_bounds, grid, &lights, constants, serial, lists](
          const LightTiles& written, const vk::PassRecorder& rec) {
        vk::DescriptorWriter writer = layout_.write(rec.allocate_set(layout_));
        writer.buffer(lights_binding, lights.handle())
            .buffer(tile_lights_binding, rec.buffer(written.lights))
            .buffer(tile_ranges_binding, rec.buffer(written.ranges))
            .buffer(group_tiles_binding, rec.buffer(written.tiles))
            .buffer(group_commands_binding, rec.buffer(written.commands))
            .buffer(light_tiles_feedback_binding, feedback_.buffer(slot).handle());
        if (serial) {
          writer.image(scene_depth_binding, rec.view(depth), nearest_.get());
          if (transparent_bounds) writer.buffer(transparent_bounds_binding, transparent_bounds->handle());
        } else {
          writer.buffer(tile_volumes_binding, rec.buffer(lists.volumes))
              .buffer(coarse_lights_binding, rec.buffer(lists.lights))
              .buffer(coarse_ranges_binding, rec.buffer(lists.ranges));
        }
        const VkDescriptorSet set = writer.update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
        layout_.bind_compute(rec.cmd(), set);
        layout_.push(rec.cmd(), constants);
        if (serial) {
          vkCmdDispatch(rec.cmd(), (grid.count() + 7) / 8, 1, 1);  // light_tiles_serial.comp: 8 tiles a group
        } else {
          vkCmdDispatch(rec.cmd(), grid.across, grid.down, 1);
        }
      });
  return out;
}

LightTilesPass::CoarseLists LightTilesPass::add_coarse_pass(rg::RenderGraph& graph, uint32_t slot,
                                                            rg::ImageHandle depth, const vk::Buffer& lights,
                                                            const Constants& constants,
                                                            const vk::Buffer* transparent_bounds,
                                                            LightTileGrid grid) const {
  const LightTileGrid coarse = grid.coarse();
  CoarseLists out;
  graph.add_pass(
      "light tiles coarse",
      [&](rg::PassBuilder& b) {
        b.read(depth, rg::Usage::sampled_compute);
        const auto output = [&](const char* name, uint64_t bytes) {
          return b.write(b.create_buffer(name, {bytes}), rg::Usage::storage_compute);
        };
        out.volumes = output("tile volumes", uint64_t{grid.count()} * tile_volume_bytes);
        out.lights = output("coarse lights", uint64_t{constants.counts.z} * sizeof(uint32_t));
        out.ranges = output("coarse ranges",
                            uint64_t{coarse.count()} * tiles::LIGHT_COARSE_SEGMENTS * sizeof(glm::uvec2));
        return out;
      },
      [this, slot, depth, transparent_bounds, coarse, &lights, constants](const CoarseLists& written,
                                                                          const vk::PassRecorder& rec) {
        vk::DescriptorWriter writer = coarse_layout_.write(rec.allocate_set(coarse_layout_));
        writer.buffer(lights_binding, lights.handle())
            .image(scene_depth_binding, rec.view(depth), nearest_.get())
            .buffer(tile_volumes_binding, rec.buffer(written.volumes))
            .buffer(coarse_lights_binding, rec.buffer(written.lights))
            .buffer(coarse_ranges_binding, rec.buffer(written.ranges))
            .buffer(light_tiles_feedback_binding, feedback_.buffer(slot).handle());
        if (transparent_bounds) writer.buffer(transparent_bounds_binding, transparent_bounds->handle());
        const VkDescriptorSet set = writer.update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, coarse_pipeline_.get());
        coarse_layout_.bind_compute(rec.cmd(), set);
        coarse_layout_.push(rec.cmd(), constants);
        vkCmdDispatch(rec.cmd(), coarse.across, coarse.down, constants.counts.w);
      });
  return out;
}

}  // namespace sg
