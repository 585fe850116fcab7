// SPDX-License-Identifier: MIT
#include "systems/frame/depth_capture.h"

#include <stdexcept>

#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/pass_recorder.h"

namespace sg {
namespace {

constexpr rg::ResourceState transfer_source{rg::PipelineStage::all_transfer, rg::Access::transfer_read,
                                            rg::ImageLayout::transfer_src_optimal};

}  // namespace

void DepthCapture::add_to(vk::VulkanContext& context, rg::RenderGraph& graph, vk::GraphImports& imports,
                          rg::ImageHandle depth) {
  const rg::ImageDesc& source = graph.resources()[depth.index].image;
  const VkExtent2D extent{source.width, source.height};
  if (!image_ || image_->extent().width != extent.width || image_->extent().height != extent.height) {
    // Only copies touch it, but vk::Image makes a view, and a view needs a usage that views have.
    image_.emplace(context, vk::ImageDesc{extent, VK_FORMAT_D32_SFLOAT,
                                          VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                              VK_IMAGE_USAGE_SAMPLED_BIT,
                                          1, 1, VK_IMAGE_VIEW_TYPE_2D, "captured depth"});
  }
  rg::ImageHandle copy = imports.import_image(graph, "captured depth", *image_, transfer_source);
  graph.add_pass(
      "capture depth",
      [&](rg::PassBuilder& b) {
        b.read(depth, rg::Usage::transfer);
        copy = b.write(copy, rg::Usage::transfer);
      },
      [depth, copy, extent](const vk::PassRecorder& rec) {
        VkImageCopy region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        region.extent = {extent.width, extent.height, 1};
        vkCmdCopyImage(rec.cmd(), rec.image(depth), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, rec.image(copy),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      });
}

vk::DepthImage DepthCapture::read(vk::VulkanContext& context) const {
  if (!image_) throw std::logic_error("DepthCapture::read: no frame was captured");
  return vk::read_depth_layer(context, *image_, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

}  // namespace sg
