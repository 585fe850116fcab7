#include "systems/shadow_atlas.h"

#include <algorithm>

#include "rendergraph/core/format.h"
#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/plan_translation.h"

namespace sg {
namespace {

constexpr VkImageUsageFlags usage =
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

uint64_t image_bytes(const rg::ImageDesc& desc) {
  return uint64_t{desc.width} * desc.height * desc.layers * rg::bytes_per_texel(desc.format);
}

// Room for `needed`, growing by half again beyond it, so that a scene gaining lights one at a
// time recreates (and waits for the GPU) a logarithmic number of times, not once per light.
uint32_t capacity(uint32_t needed, uint32_t current) {
  return needed <= current ? current : std::max(needed, current + current / 2);
}

}  // namespace

ShadowAtlas::ShadowAtlas(vk::VulkanContext& context) : context_(context) { fit(1, 16, 1, 16); }

ShadowAtlas::Changes ShadowAtlas::fit(uint32_t map_layers, uint32_t map_size, uint32_t cubes,
                                      uint32_t cube_size) {
  Changes changes;
  const rg::ImageDesc maps{std::max(map_size, maps_desc_.width), std::max(map_size, maps_desc_.width),
                           depth_format, capacity(std::max(map_layers, 1u), maps_desc_.layers)};
  const rg::ImageDesc cube_desc{std::max(cube_size, cubes_desc_.width),
                                std::max(cube_size, cubes_desc_.width), depth_format,
                                6 * capacity(std::max(cubes, 1u), cubes_desc_.layers / 6), 1, true};
  changes.maps = maps != maps_desc_;
  changes.cubes = cube_desc != cubes_desc_;
  if ((changes.maps && maps_.handle() != VK_NULL_HANDLE) ||
      (changes.cubes && cubes_.handle() != VK_NULL_HANDLE)) {
    vkDeviceWaitIdle(context_.device());
  }
  if (changes.maps) {
    maps_desc_ = maps;
    maps_ = vk::Image(context_, {{maps.width, maps.height}, vk::to_vk(depth_format), usage, 1,
                                 maps.layers, VK_IMAGE_VIEW_TYPE_2D_ARRAY, "shadow atlas"});
  }
  if (changes.cubes) {
    cubes_desc_ = cube_desc;
    cubes_ = vk::Image(context_, {{cube_desc.width, cube_desc.height}, vk::to_vk(depth_format), usage,
                                  1, cube_desc.layers, VK_IMAGE_VIEW_TYPE_CUBE_ARRAY, "shadow cubes"});
  }
  return changes;
}

uint64_t ShadowAtlas::bytes() const { return image_bytes(maps_desc_) + image_bytes(cubes_desc_); }

}  // namespace sg
