// SPDX-License-Identifier: MIT
#include "systems/gpu/gpu_textures.h"

#include <algorithm>
#include <bit>
#include <span>
#include <stdexcept>
#include <vector>

#include <stb_image_resize.h>

#include "rendergraph/device/context.h"
#include "rendergraph/device/upload.h"

namespace sg {

GpuTextures::GpuTextures(vk::VulkanContext& context, const scene::TextureLibrary& textures)
    : sampler_(
          vk::create_sampler(context.device(), VK_FILTER_LINEAR, false, VK_SAMPLER_ADDRESS_MODE_REPEAT)) {
  uint32_t size = 1;
  for (const scene::Texture& texture : textures.textures) {
    size = std::max({size, texture.width, texture.height});
  }
  size = std::min(std::bit_ceil(size), max_layer_size);
  layers_ = std::max<uint32_t>(1, static_cast<uint32_t>(textures.textures.size()));
  has_images_ = !textures.textures.empty();

  const size_t layer_bytes = size_t{size} * size * 4;
  std::vector<uint8_t> texels(layer_bytes * layers_, 255);  // white when there is no texture
  for (size_t layer = 0; layer < textures.textures.size(); ++layer) {
    const scene::Texture& texture = textures.textures[layer];
    uint8_t* destination = texels.data() + layer * layer_bytes;
    if (texture.width == size && texture.height == size) {
      std::copy(texture.pixels.begin(), texture.pixels.end(), destination);
    } else if (!stbir_resize_uint8_srgb(texture.pixels.data(), int(texture.width), int(texture.height), 0,
                                        destination, int(size), int(size), 0, 4, 3, 0)) {
      throw std::runtime_error("cannot resample texture '" + texture.name + "'");
    }
  }
  array_ = vk::Image(context, {{size, size},
                               VK_FORMAT_R8G8B8A8_SRGB,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               1,
                               layers_,
                               VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                               "material textures"});
  vk::UploadBatch upload(context);
  upload.copy_to_image(array_, layers_, std::as_bytes(std::span(texels)));
  upload.submit();
}

}  // namespace sg
