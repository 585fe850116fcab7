// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_accessor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "systems/scene/gltf_json.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

template <typename T>
T load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);  // glTF data need not be aligned for us
  return value;
}

// Normalized integers map to [0, 1] (unsigned) or [-1, 1] (signed), as the glTF spec says.
template <typename T>
double read_integer(const unsigned char* bytes, bool normalized) {
  const double value = load<T>(bytes);
  return normalized ? std::max(value / std::numeric_limits<T>::max(), -1.0) : value;
}

double read_component(const unsigned char* bytes, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return read_integer<std::int8_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return read_integer<std::uint8_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return read_integer<std::int16_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return read_integer<std::uint16_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return read_integer<std::uint32_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(bytes);
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return load<double>(bytes);
    default: return 0.0;  // rejected by validation
  }
}

// Reads `count` elements of `components` components into `out`, element i at out[i * components].
void read_elements(const tinygltf::Model& model, int view_index, std::size_t byte_offset, std::size_t count,
                   std::size_t components, int component_type, bool normalized, std::size_t stride,
                   double* out) {
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(view_index)];
  const unsigned char* base =
      model.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset + byte_offset;
  const std::size_t component_bytes =
      static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(component_type)));
  for (std::size_t i = 0; i < count; ++i) {
    const unsigned char* element = base + i * stride;
    for (std::size_t c = 0; c < components; ++c) {
      out[i * components + c] = read_component(element + c * component_bytes, component_type, normalized);
    }
  }
}

}  // namespace

std::vector<double> read_accessor(const tinygltf::Model& model, std::size_t index, const std::string& where) {
  const tinygltf::Accessor& accessor = model.accessors[index];
  const auto components =
      static_cast<std::size_t>(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
  const std::size_t element_bytes = components * static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(
                                                     static_cast<std::uint32_t>(accessor.componentType)));
  std::vector<double> values(accessor.count * components, 0.0);
  if (accessor.bufferView >= 0) {
    const std::size_t declared_stride =
        model.bufferViews[static_cast<std::size_t>(accessor.bufferView)].byteStride;
    read_elements(model, accessor.bufferView, accessor.byteOffset, accessor.count, components,
                  accessor.componentType, accessor.normalized,
                  declared_stride != 0 ? declared_stride : element_bytes, values.data());
  }
  if (!accessor.sparse.isSparse) return values;

  const auto& sparse = accessor.sparse;
  const auto count = static_cast<std::size_t>(sparse.count);
  std::vector<double> targets(count);
  const std::size_t index_bytes = static_cast<std::size_t>(
      tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(sparse.indices.componentType)));
  read_elements(model, sparse.indices.bufferView, static_cast<std::size_t>(sparse.indices.byteOffset), count,
                1, sparse.indices.componentType, false, index_bytes, targets.data());
  std::vector<double> replacements(count * components);
  read_elements(model, sparse.values.bufferView, static_cast<std::size_t>(sparse.values.byteOffset), count,
                components, accessor.componentType, accessor.normalized, element_bytes, replacements.data());
  for (std::size_t i = 0; i < count; ++i) {
    if (targets[i] >= static_cast<double>(accessor.count)) {
      throw SceneError(where, indexed("accessors", index) + ".sparse.indices",
                       "index " + std::to_string(static_cast<std::uint64_t>(targets[i])) +
                           " is not below the accessor's count " + std::to_string(accessor.count));
    }
    std::copy_n(
        replacements.begin() + static_cast<std::ptrdiff_t>(i * components), components,
        values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(targets[i]) * components));
  }
  return values;
}

}  // namespace sg::scene
