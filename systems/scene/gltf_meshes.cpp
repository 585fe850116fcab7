// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_meshes.h"

#include <cmath>
#include <optional>
#include <string>

#include "systems/scene/gltf_accessor.h"
#include "systems/scene/gltf_json.h"
#include "systems/scene/mesh_library.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

// The attribute's values, or empty when the primitive lacks it; non-finite values are refused.
std::vector<double> read_attribute(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                   const char* name, Scene& scene) {
  const auto found = primitive.attributes.find(name);
  if (found == primitive.attributes.end()) return {};
  const auto accessor = static_cast<std::size_t>(found->second);
  std::vector<double> values = read_accessor(model, accessor, scene.name);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw SceneError(scene.name, indexed("accessors", accessor),
                       std::string(name) + " has a non-finite value at component " + std::to_string(i));
    }
  }
  return values;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                        std::size_t vertex_count, const std::string& object,
                                        const std::string& where) {
  std::vector<std::uint32_t> indices;
  std::string counted = object + " vertex count";
  if (primitive.indices < 0) {
    indices.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<std::uint32_t>(i);
  } else {
    const auto accessor = static_cast<std::size_t>(primitive.indices);
    counted = indexed("accessors", accessor) + " (indices of " + object + ") count";
    const std::vector<double> values = read_accessor(model, accessor, where);
    indices.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] >= static_cast<double>(vertex_count)) {
        throw SceneError(where, indexed("accessors", accessor),
                         "index " + std::to_string(static_cast<std::uint64_t>(values[i])) + " at position " +
                             std::to_string(i) + " is out of range: " + object + " has " +
                             std::to_string(vertex_count) + " vertices");
      }
      indices.push_back(static_cast<std::uint32_t>(values[i]));
    }
  }
  if (indices.size() % 3 != 0) {
    throw SceneError(where, object,
                     counted + " " + std::to_string(indices.size()) + " is not a multiple of 3 (triangles)");
  }
  return indices;
}

std::optional<ImportedPrimitive> import_primitive(const tinygltf::Model& model,
                                                  const tinygltf::Primitive& primitive,
                                                  const std::string& object, Scene& scene) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) {
    warn(scene, object + ": mode " + std::to_string(primitive.mode) + " is not triangles; skipped");
    return std::nullopt;
  }
  const std::vector<double> positions = read_attribute(model, primitive, "POSITION", scene);
  if (positions.empty()) {
    warn(scene, object + ": no POSITION attribute; skipped");
    return std::nullopt;
  }
  if (!primitive.targets.empty()) warn(scene, object + ": morph targets ignored");
  const std::vector<double> normals = read_attribute(model, primitive, "NORMAL", scene);
  const std::vector<double> uvs = read_attribute(model, primitive, "TEXCOORD_0", scene);
  const std::size_t vertex_count = positions.size() / 3;
  std::vector<Vertex> vertices(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    vertices[v].position = {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
    if (!normals.empty()) {
      const glm::vec3 normal{normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]};
      const float length = glm::length(normal);
      vertices[v].normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    if (!uvs.empty()) vertices[v].uv = {uvs[2 * v], uvs[2 * v + 1]};
  }
  std::vector<std::uint32_t> indices = read_indices(model, primitive, vertex_count, object, scene.name);
  if (normals.empty()) make_flat_normals(vertices, indices);
  return ImportedPrimitive{add_mesh(scene.meshes, object, vertices, indices), primitive.material};
}

}  // namespace

std::vector<std::vector<ImportedPrimitive>> import_meshes(const tinygltf::Model& model, Scene& scene) {
  std::vector<std::vector<ImportedPrimitive>> meshes(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      const std::string object = indexed("meshes", m) + "." + indexed("primitives", p);
      if (auto primitive = import_primitive(model, model.meshes[m].primitives[p], object, scene)) {
        meshes[m].push_back(*primitive);
      }
    }
  }
  return meshes;
}

}  // namespace sg::scene
