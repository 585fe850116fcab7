// SPDX-License-Identifier: MIT
#include "rendergraph/core/render_graph.h"

namespace sg::rg {
namespace {

std::string quoted(const std::string& name) { return "'" + name + "'"; }

std::string version_text(const ResourceDeclaration& resource, std::uint32_t version) {
  return quoted(resource.name) + " v" + std::to_string(version);
}

}  // namespace

ImageHandle PassBuilder::create_image(std::string name, const ImageDesc& desc) {
  const std::uint32_t index = graph_.add_resource(std::move(name), ResourceKind::image);
  graph_.resources_[index].image = desc;
  return {index, 0};
}

BufferHandle PassBuilder::create_buffer(std::string name, const BufferDesc& desc) {
  const std::uint32_t index = graph_.add_resource(std::move(name), ResourceKind::buffer);
  graph_.resources_[index].buffer = desc;
  return {index, 0};
}

void PassBuilder::read(ImageHandle image, Usage usage, SubresourceRange range) {
  declare(image.index, image.version, ResourceKind::image, usage, Direction::read, range);
}

void PassBuilder::read(BufferHandle buffer, Usage usage) {
  declare(buffer.index, buffer.version, ResourceKind::buffer, usage, Direction::read,
          SubresourceRange::all());
}

ImageHandle PassBuilder::write(ImageHandle image, Usage usage, SubresourceRange range) {
  const auto version =
      declare(image.index, image.version, ResourceKind::image, usage, Direction::write, range);
  return version ? ImageHandle{image.index, *version} : image;
}

ImageHandle PassBuilder::write(ImageHandle image, Usage usage, ClearValue clear, SubresourceRange range) {
  const auto version =
      declare(image.index, image.version, ResourceKind::image, usage, Direction::write, range, clear);
  return version ? ImageHandle{image.index, *version} : image;
}

BufferHandle PassBuilder::write(BufferHandle buffer, Usage usage) {
  const auto version = declare(buffer.index, buffer.version, ResourceKind::buffer, usage, Direction::write,
                               SubresourceRange::all());
  return version ? BufferHandle{buffer.index, *version} : buffer;
}

void PassBuilder::mark_side_effects() { graph_.passes_[pass_].side_effects = true; }

std::optional<std::uint32_t> PassBuilder::declare(std::uint32_t resource_index, std::uint32_t version,
                                                  ResourceKind kind, Usage usage, Direction direction,
                                                  const SubresourceRange& range,
                                                  std::optional<ClearValue> clear) {
  PassDeclaration& pass = graph_.passes_[pass_];
  const std::string pass_text = "pass " + quoted(pass.name);
  const auto fail = [&](ErrorKind error, const std::string& message) -> std::optional<std::uint32_t> {
    graph_.report(error, pass_text + " " + message);
    return std::nullopt;
  };

  if (resource_index >= graph_.resources_.size() || graph_.resources_[resource_index].kind != kind ||
      version >= graph_.resources_[resource_index].producers.size()) {
    return fail(ErrorKind::invalid_handle,
                "uses a handle that does not name a resource version of this graph");
  }
  ResourceDeclaration& resource = graph_.resources_[resource_index];
  const auto state = usage_state(usage, direction, kind);
  if (!state) {
    return fail(ErrorKind::invalid_usage, "cannot " + std::string(direction_name(direction)) + " " +
                                              quoted(resource.name) + " as " +
                                              std::string(usage_name(usage)));
  }
  if (clear && usage != Usage::color_attachment && usage != Usage::depth_attachment) {
    return fail(ErrorKind::invalid_usage, "clears " + quoted(resource.name) + " used as " +
                                              std::string(usage_name(usage)) +
                                              "; only attachment writes can clear");
  }
  const auto resolved = resolve(range, resource);
  if (!resolved) {
    return fail(ErrorKind::invalid_range, "uses " + quoted(resource.name) + " at " + to_string(range) +
                                              ", outside its " + std::to_string(resource.mip_count()) +
                                              " mips and " + std::to_string(resource.layer_count()) +
                                              " layers");
  }

  const auto latest = static_cast<std::uint32_t>(resource.producers.size() - 1);
  const auto producer_name = [&](std::uint32_t v) {
    return quoted(graph_.passes_[resource.producers[v]].name);
  };
  if (direction == Direction::read) {
    // A pass may read the version its own write consumes (its input), never the one it produces.
    const bool own_input = version + 1 == latest && resource.producers[latest] == pass_;
    if (version < latest && !own_input) {
      return fail(ErrorKind::stale_version, "reads " + version_text(resource, version) + ", but pass " +
                                                producer_name(version + 1) + " already wrote v" +
                                                std::to_string(version + 1) + "; read the newest handle");
    }
    if (version > 0 && resource.producers[version] == pass_) {
      return fail(ErrorKind::cycle, "reads " + version_text(resource, version) +
                                        ", which it writes itself: a dependency cycle");
    }
    if (version == 0 && !resource.imported) {
      return fail(ErrorKind::read_before_write,
                  "reads transient " + quoted(resource.name) + " before any pass writes it");
    }
  } else {
    if (version < latest) {
      return fail(ErrorKind::stale_version, "writes " + version_text(resource, version) + ", but pass " +
                                                producer_name(version + 1) + " already wrote v" +
                                                std::to_string(version + 1) + "; versions form one chain");
    }
    if (resource.imported && !resource.final_state) {
      return fail(ErrorKind::missing_final_state,
                  "writes imported " + quoted(resource.name) +
                      ", which was imported without a final state; the next frame needs to know its layout");
    }
  }

  for (const ResourceAccess& other : pass.accesses) {
    const bool compatible = other.direction == Direction::read && direction == Direction::read &&
                            other.state.layout == state->layout;
    if (other.resource == resource_index && !compatible && overlaps(other.range, *resolved)) {
      return fail(ErrorKind::conflicting_usage,
                  "uses " + quoted(resource.name) + " as " + std::string(usage_name(other.usage)) + " (" +
                      std::string(direction_name(other.direction)) + ", " + to_string(other.range) +
                      ") and as " + std::string(usage_name(usage)) + " (" +
                      std::string(direction_name(direction)) + ", " + to_string(*resolved) +
                      "): the subresources overlap");
    }
  }

  if (direction == Direction::write) {
    resource.producers.push_back(pass_);
    version = latest + 1;
  }
  pass.accesses.push_back({resource_index, version, usage, direction, *resolved, *state, clear});
  return version;
}

}  // namespace sg::rg
