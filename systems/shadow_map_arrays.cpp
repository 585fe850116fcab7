#include "systems/shadow_map_arrays.h"

#include "rendergraph/core/format.h"
#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/shadows/frame_lights.h"

namespace sg {
namespace {

constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

uint64_t array_bytes(const shadows::ShadowArraySize& size, uint32_t layers_per_entry) {
  return uint64_t{size.resolution} * size.resolution * size.count * layers_per_entry *
         rg::bytes_per_texel(ShadowMapArrays::depth_format);
}

}  // namespace

ShadowMapArrays::ShadowMapArrays(vk::VulkanContext& context) : context_(context) { fit({}); }

void ShadowMapArrays::fit(const shadows::ShadowStorageSize& needed) {
  const shadows::ShadowStorageSize size =
      shadows::fit_shadow_storage(size_, needed, shadows::min_shadow_resolution);
  const bool new_maps = size.maps != size_.maps;
  const bool new_cubes = size.cubes != size_.cubes;
  if ((new_maps && maps_.handle() != VK_NULL_HANDLE) || (new_cubes && cubes_.handle() != VK_NULL_HANDLE)) {
    vkDeviceWaitIdle(context_.device());
  }
  const VkFormat format = vk::to_vk(depth_format);
  if (new_maps) {
    maps_ = vk::Image(context_, {{size.maps.resolution, size.maps.resolution},
                                 format,
                                 usage,
                                 1,
                                 size.maps.count,
                                 VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                                 "shadow maps"});
  }
  if (new_cubes) {
    cubes_ = vk::Image(context_, {{size.cubes.resolution, size.cubes.resolution},
                                  format,
                                  usage,
                                  1,
                                  6 * size.cubes.count,
                                  VK_IMAGE_VIEW_TYPE_CUBE_ARRAY,
                                  "shadow cubes"});
  }
  size_ = size;
}

uint64_t ShadowMapArrays::bytes() const { return array_bytes(size_.maps, 1) + array_bytes(size_.cubes, 6); }

}  // namespace sg
