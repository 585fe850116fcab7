// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_validate.h"

#include <cstdint>
#include <type_traits>
#include <vector>

#include "systems/scene/gltf_json.h"
#include "systems/scene/gltf_limits.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

// Sparse byte offsets are int in tinygltf 2.7 (Debian 12) and unsigned in 2.9 (Debian 13).
template <typename Offset>
bool negative(Offset offset) {
  if constexpr (std::is_signed_v<Offset>) return offset < 0;
  return false;
}

bool is_unsigned_index_type(int component_type) {
  return component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

struct Validator {
  const tinygltf::Model& model;
  const std::string& where;

  [[noreturn]] void fail(const std::string& object, const std::string& problem) const {
    throw SceneError(where, object, problem);
  }

  template <typename T>
  void require_index(int index, const std::vector<T>& items, const std::string& object, const char* what,
                     const char* array) const {
    if (index < 0 || static_cast<std::size_t>(index) >= items.size()) {
      fail(object, std::string(what) + " " + std::to_string(index) + " is not an index into " + array + " (" +
                       std::to_string(items.size()) + " entries)");
    }
  }

  // `count` elements of `element_bytes` each, `stride` apart, starting at `offset` in view
  // `view`, must end inside the view. Sizes are compared without overflow: count is first
  // bounded by the view's byteLength (which preflight bounded by a file size).
  void require_in_view(int view, std::uint64_t offset, std::uint64_t count, std::uint64_t element_bytes,
                       std::uint64_t stride, const std::string& object) const {
    require_index(view, model.bufferViews, object, "bufferView", "bufferViews");
    const std::uint64_t length = model.bufferViews[static_cast<std::size_t>(view)].byteLength;
    const std::uint64_t needed = count > length ? UINT64_MAX : offset + (count - 1) * stride + element_bytes;
    if (offset > length || needed > length) {
      fail(object, "byteOffset " + std::to_string(offset) + " + " + std::to_string(count) + " elements of " +
                       std::to_string(element_bytes) + " bytes, stride " + std::to_string(stride) +
                       ", exceed bufferViews[" + std::to_string(view) + "].byteLength " +
                       std::to_string(length));
    }
  }

  void accessor(std::size_t index) const {
    const tinygltf::Accessor& accessor = model.accessors[index];
    const std::string object = indexed("accessors", index);
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    const int component_bytes =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    if (components <= 0 || component_bytes <= 0) fail(object, "unknown type or componentType");
    if (accessor.count == 0) fail(object, "count is 0");
    const std::uint64_t element_bytes = static_cast<std::uint64_t>(components) * component_bytes;
    if (accessor.bufferView >= 0) {
      require_index(accessor.bufferView, model.bufferViews, object, "bufferView", "bufferViews");
      const std::uint64_t declared_stride =
          model.bufferViews[static_cast<std::size_t>(accessor.bufferView)].byteStride;
      if (declared_stride != 0 && declared_stride < element_bytes) {
        fail(object, "bufferViews[" + std::to_string(accessor.bufferView) + "].byteStride " +
                         std::to_string(declared_stride) + " is smaller than the element size " +
                         std::to_string(element_bytes));
      }
      require_in_view(accessor.bufferView, accessor.byteOffset, accessor.count, element_bytes,
                      declared_stride != 0 ? declared_stride : element_bytes, object);
    } else if (accessor.count > gltf_limits::max_implicit_accessor_elements) {
      fail(object, "count " + std::to_string(accessor.count) + " without a bufferView is over the limit of " +
                       std::to_string(gltf_limits::max_implicit_accessor_elements));
    }
    if (!accessor.sparse.isSparse) return;
    const auto& sparse = accessor.sparse;
    const std::string sparse_object = object + ".sparse";
    if (sparse.count < 1 || static_cast<std::uint64_t>(sparse.count) > accessor.count) {
      fail(sparse_object, "count " + std::to_string(sparse.count) + " is outside [1, " +
                              std::to_string(accessor.count) + "]");
    }
    if (!is_unsigned_index_type(sparse.indices.componentType)) {
      fail(sparse_object + ".indices", "componentType is not an unsigned integer type");
    }
    if (negative(sparse.indices.byteOffset) || negative(sparse.values.byteOffset)) {
      fail(sparse_object, "negative byteOffset");
    }
    const std::uint64_t index_bytes = static_cast<std::uint64_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(sparse.indices.componentType)));
    const auto count = static_cast<std::uint64_t>(sparse.count);
    require_in_view(sparse.indices.bufferView, static_cast<std::uint64_t>(sparse.indices.byteOffset), count,
                    index_bytes, index_bytes, sparse_object + ".indices");
    require_in_view(sparse.values.bufferView, static_cast<std::uint64_t>(sparse.values.byteOffset), count,
                    element_bytes, element_bytes, sparse_object + ".values");
  }

  void primitive(const tinygltf::Primitive& primitive, const std::string& object) const {
    std::uint64_t vertex_count = 0;
    for (const auto& [name, index] : primitive.attributes) {
      const std::string attribute = object + ".attributes." + name;
      require_index(index, model.accessors, attribute, "accessor", "accessors");
      const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
      const int expected = name == "POSITION" || name == "NORMAL" ? TINYGLTF_TYPE_VEC3
                           : name == "TEXCOORD_0"                 ? TINYGLTF_TYPE_VEC2
                                                                  : accessor.type;
      if (accessor.type != expected) fail(attribute, "has the wrong accessor type");
      if (vertex_count != 0 && accessor.count != vertex_count) {
        fail(attribute, "count " + std::to_string(accessor.count) +
                            " differs from the primitive's other attributes (" +
                            std::to_string(vertex_count) + ")");
      }
      vertex_count = accessor.count;
    }
    if (primitive.indices >= 0) {
      require_index(primitive.indices, model.accessors, object + ".indices", "accessor", "accessors");
      const tinygltf::Accessor& indices = model.accessors[static_cast<std::size_t>(primitive.indices)];
      if (indices.type != TINYGLTF_TYPE_SCALAR || !is_unsigned_index_type(indices.componentType)) {
        fail(indexed("accessors", static_cast<std::size_t>(primitive.indices)),
             "used as indices but is not SCALAR unsigned byte, short or int");
      }
    }
    if (primitive.material >= 0) {
      require_index(primitive.material, model.materials, object, "material", "materials");
    }
  }

  void node_transform(const tinygltf::Node& node, const std::string& object) const {
    if ((!node.matrix.empty() && node.matrix.size() != 16) ||
        (!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3)) {
      fail(object, "transform property has the wrong number of components");
    }
  }

  void nodes() const {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      const tinygltf::Node& node = model.nodes[i];
      const std::string object = indexed("nodes", i);
      if (node.mesh >= 0) require_index(node.mesh, model.meshes, object, "mesh", "meshes");
      if (node.camera >= 0) require_index(node.camera, model.cameras, object, "camera", "cameras");
      if (node.skin >= 0) require_index(node.skin, model.skins, object, "skin", "skins");
      node_transform(node, object);
      for (const int child : node.children) {
        require_index(child, model.nodes, object, "child", "nodes");
        int& child_parent = parent[static_cast<std::size_t>(child)];
        if (child_parent != -1 || static_cast<std::size_t>(child) == i) {
          fail(object, "child " + std::to_string(child) +
                           " already has a parent (a node may "
                           "have only one, and never itself)");
        }
        child_parent = static_cast<int>(i);
      }
    }
    // With one parent each, a cycle is a walk up that never reaches a root.
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      std::uint32_t depth = 0;
      for (int at = parent[i]; at != -1; at = parent[static_cast<std::size_t>(at)]) {
        if (++depth > gltf_limits::max_node_depth) {
          fail(indexed("nodes", i),
               "is in a cycle or deeper than " + std::to_string(gltf_limits::max_node_depth) + " levels");
        }
      }
    }
  }

  void camera(std::size_t index) const {
    const tinygltf::Camera& camera = model.cameras[index];
    if (camera.type != "perspective") return;  // orthographic: skipped with a warning on import
    const tinygltf::PerspectiveCamera& p = camera.perspective;
    const std::string object = indexed("cameras", index);
    if (p.yfov <= 0.0 || p.znear <= 0.0 || p.aspectRatio < 0.0 || (p.zfar != 0.0 && p.zfar <= p.znear)) {
      fail(object,
           "needs yfov > 0, znear > 0, zfar > znear (or absent) and aspectRatio > 0 "
           "(or absent)");
    }
  }

  void material(std::size_t m) const {
    const tinygltf::Material& material = model.materials[m];
    const std::string object = indexed("materials", m);
    const int texture = material.pbrMetallicRoughness.baseColorTexture.index;
    if (texture >= 0) require_index(texture, model.textures, object, "baseColorTexture", "textures");
    if (material.alphaMode != "OPAQUE" && material.alphaMode != "MASK" && material.alphaMode != "BLEND") {
      fail(object, "alphaMode '" + material.alphaMode + "' is none of OPAQUE, MASK and BLEND");
    }
    if (!(material.alphaCutoff >= 0.0)) fail(object, "alphaCutoff must be 0 or more");
  }

  void run() const {
    for (std::size_t i = 0; i < model.accessors.size(); ++i) accessor(i);
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
      for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
        primitive(model.meshes[m].primitives[p], indexed("meshes", m) + "." + indexed("primitives", p));
      }
    }
    nodes();
    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
      for (const int node : model.scenes[s].nodes) {
        require_index(node, model.nodes, indexed("scenes", s), "node", "nodes");
      }
    }
    for (std::size_t m = 0; m < model.materials.size(); ++m) material(m);
    for (std::size_t t = 0; t < model.textures.size(); ++t) {
      if (model.textures[t].source >= 0) {
        require_index(model.textures[t].source, model.images, indexed("textures", t), "source", "images");
      }
    }
    for (std::size_t c = 0; c < model.cameras.size(); ++c) camera(c);
  }
};

}  // namespace

void validate_gltf_model(const tinygltf::Model& model, const std::string& where) {
  Validator{model, where}.run();
}

}  // namespace sg::scene
