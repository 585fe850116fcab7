// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_export.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/scene/gltf_shadow_extras.h"
#include "systems/scene/lights.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/motions.h"
#include "systems/scene/node_animation.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {
namespace {

// tinygltf keeps extras and extensions as its own Value; they are written here as JSON first.
tinygltf::Value to_value(const nlohmann::json& json) {
  if (json.is_boolean()) return tinygltf::Value(json.get<bool>());
  if (json.is_number_integer()) return tinygltf::Value(json.get<int>());
  if (json.is_number()) return tinygltf::Value(json.get<double>());
  if (json.is_string()) return tinygltf::Value(json.get<std::string>());
  if (json.is_array()) {
    tinygltf::Value::Array array;
    for (const nlohmann::json& item : json) array.push_back(to_value(item));
    return tinygltf::Value(std::move(array));
  }
  tinygltf::Value::Object object;
  for (const auto& [key, item] : json.items()) object[key] = to_value(item);
  return tinygltf::Value(std::move(object));
}

// A node's reference to its light. tinygltf 2.9 (Debian 13) writes it from Node::light and drops
// the extension a node carries without one; 2.7 (Debian 12) has no such field and writes the
// extension as given.
template <typename Node>  // tinygltf::Node: a template, so that the member test may fail
void set_node_light(Node& node, std::size_t light) {
  if constexpr (requires { node.light; }) node.light = static_cast<int>(light);
  node.extensions["KHR_lights_punctual"] = to_value({{"light", light}});
}

nlohmann::json vec3(const glm::vec3& v) { return {v.x, v.y, v.z}; }

tinygltf::Camera perspective(const Camera& lens) {
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.perspective.yfov = lens.yfov;
  camera.perspective.znear = lens.znear;
  camera.perspective.zfar = lens.zfar;
  camera.perspective.aspectRatio = lens.aspect;
  return camera;
}

const char* falloff_name(FalloffMode mode) {
  return mode == FalloffMode::gltf_punctual ? "gltf_punctual" : "linear_window";
}

class Exporter {
 public:
  explicit Exporter(const Scene& scene) : scene_(scene) {
    model_.asset.version = "2.0";
    model_.asset.generator = "Shadowgraph";
    model_.buffers.emplace_back();
  }

  ExportReport run(const std::optional<ExportView>& view) {
    if (view) add_view_camera(*view);
    const ecs::World& world = scene_.world;
    // Nodes in the world's order, then their children lists once every entity has its node.
    world.query<const ecs::LocalTransform>().for_each(
        [&](ecs::Entity entity, const ecs::LocalTransform& local) { add_node(entity, local); });
    for (const auto& [entity, node] : node_of_) {
      const ecs::Parent* parent = world.try_get<ecs::Parent>(entity);
      const auto found = parent ? node_of_.find(parent->entity) : node_of_.end();
      if (found == node_of_.end()) {
        roots_.push_back(node);
      } else {
        model_.nodes[static_cast<std::size_t>(found->second)].children.push_back(node);
      }
    }
    std::sort(roots_.begin(), roots_.end());
    for (auto& node : model_.nodes) std::sort(node.children.begin(), node.children.end());
    tinygltf::Scene gltf_scene;
    gltf_scene.nodes = roots_;
    model_.scenes.push_back(gltf_scene);
    model_.defaultScene = 0;
    if (!lights_.empty()) {
      model_.extensionsUsed.push_back("KHR_lights_punctual");
      model_.extensions["KHR_lights_punctual"] = to_value({{"lights", lights_}});
    }
    report_.nodes = model_.nodes.size();
    report_.meshes = model_.meshes.size();
    report_.lights = lights_.size() + cylinders_;
    return report_;
  }

  tinygltf::Model& model() { return model_; }

 private:
  void add_view_camera(const ExportView& view) {
    model_.cameras.push_back(perspective(view.lens));
    // A glTF camera looks down its -Z with +Y up: the inverse of the view matrix's rotation.
    const glm::vec3 forward = glm::normalize(view.pose.target - view.pose.eye);
    const glm::mat4 look = glm::lookAt(view.pose.eye, view.pose.target, camera_up(forward, view.pose.up));
    const glm::quat rotation = glm::quat_cast(glm::transpose(glm::mat3(look)));
    tinygltf::Node node;
    node.name = "view";
    node.camera = 0;
    node.translation = {view.pose.eye.x, view.pose.eye.y, view.pose.eye.z};
    node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
    model_.nodes.push_back(node);
    roots_.push_back(0);
  }

  void add_node(ecs::Entity entity, const ecs::LocalTransform& local) {
    const ecs::World& world = scene_.world;
    tinygltf::Node node;
    if (const Name* name = world.try_get<Name>(entity)) node.name = name->value;
    node.translation = {local.translation.x, local.translation.y, local.translation.z};
    node.rotation = {local.rotation.x, local.rotation.y, local.rotation.z, local.rotation.w};
    node.scale = {local.scale.x, local.scale.y, local.scale.z};
    nlohmann::json extras = nlohmann::json::object();
    if (const MeshInstance* instance = world.try_get<MeshInstance>(entity)) {
      const Material* material = world.try_get<Material>(entity);
      node.mesh = mesh_of(instance->mesh, material ? *material : Material{});
      if (!instance->casts_shadow) extras["casts_shadow"] = false;
      if (!instance->receives_shadow) extras["receives_shadow"] = false;
      if (instance->light_layers != first_layer) extras[to_key(MeshLayers::light)] = instance->light_layers;
      if (instance->shadow_layers != first_layer)
        extras[to_key(MeshLayers::shadow)] = instance->shadow_layers;
    }
    if (const Camera* camera = world.try_get<Camera>(entity)) {
      node.camera = static_cast<int>(model_.cameras.size());
      model_.cameras.push_back(perspective(*camera));
    }
    if (const ShadowSettings* shadow = world.try_get<ShadowSettings>(entity)) {
      if (const auto* beam = world.try_get<CylinderLight>(entity)) {
        nlohmann::json cylinder = shadow_extras(*shadow);
        cylinder.update({{"color", vec3(beam->color)},
                         {"intensity", beam->intensity},
                         {"inner_radius", beam->inner_radius},
                         {"outer_radius", beam->outer_radius}});
        extras["shadowgraph"] = {{"cylinder_light", cylinder}};
        ++cylinders_;
      } else if (const std::optional<nlohmann::json> light = punctual_light(entity, *shadow)) {
        set_node_light(node, lights_.size());
        lights_.push_back(*light);
      }
    }
    if (world.try_get<OrbitMotion>(entity) || world.try_get<BobMotion>(entity) ||
        world.try_get<NodeAnimation>(entity)) {
      ++report_.animated_entities;
    }
    if (!extras.empty()) node.extras = to_value(extras);
    node_of_.emplace(entity, static_cast<int>(model_.nodes.size()));
    model_.nodes.push_back(node);
  }

  std::optional<nlohmann::json> punctual_light(ecs::Entity entity, const ShadowSettings& shadow) const {
    const ecs::World& world = scene_.world;
    nlohmann::json extras = shadow_extras(shadow);
    nlohmann::json light;
    if (const auto* point = world.try_get<PointLight>(entity)) {
      light = {{"type", "point"},
               {"color", vec3(point->color)},
               {"intensity", point->intensity},
               {"range", point->range}};
      extras["falloff"] = falloff_name(point->falloff);
    } else if (const auto* spot = world.try_get<SpotLight>(entity)) {
      light = {{"type", "spot"},
               {"color", vec3(spot->color)},
               {"intensity", spot->intensity},
               {"range", spot->range},
               {"spot", {{"innerConeAngle", spot->inner_cone}, {"outerConeAngle", spot->outer_cone}}}};
      extras["falloff"] = falloff_name(spot->falloff);
    } else if (const auto* sun = world.try_get<DirectionalLight>(entity)) {
      light = {{"type", "directional"}, {"color", vec3(sun->color)}, {"intensity", sun->intensity}};
    } else {
      return std::nullopt;
    }
    light["extras"] = {{"shadowgraph", extras}};
    return light;
  }

  // Appends `bytes` to the buffer, 4-byte aligned, as a buffer view.
  int add_view(const void* data, std::size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    buffer.resize((buffer.size() + 3) & ~std::size_t{3});
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    buffer.resize(buffer.size() + bytes);
    std::memcpy(buffer.data() + view.byteOffset, data, bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  int add_accessor(int view, int component, int type, std::size_t count) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = component;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  // The glTF mesh of library mesh `mesh` drawn with `material`: one per pair, the vertex data
  // once per library mesh.
  int mesh_of(std::uint32_t mesh, const Material& material) {
    const int material_index = material_of(material);
    const auto key = std::make_pair(mesh, material_index);
    if (const auto found = meshes_.find(key); found != meshes_.end()) return found->second;
    tinygltf::Primitive primitive;
    primitive.attributes = attributes_of(mesh);
    primitive.indices = indices_of(mesh);
    primitive.material = material_index;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gltf_mesh;
    gltf_mesh.name = scene_.meshes.meshes[mesh].name;
    gltf_mesh.primitives.push_back(primitive);
    model_.meshes.push_back(gltf_mesh);
    const int index = static_cast<int>(model_.meshes.size() - 1);
    meshes_.emplace(key, index);
    return index;
  }

  std::map<std::string, int> attributes_of(std::uint32_t mesh) {
    if (const auto found = attributes_.find(mesh); found != attributes_.end()) return found->second;
    const MeshRange& range = scene_.meshes.meshes[mesh];
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    for (std::uint32_t v = 0; v < range.vertex_count; ++v) {
      const Vertex& vertex = scene_.meshes.vertices[range.vertex_offset + v];
      positions.push_back(vertex.position);
      normals.push_back(vertex.normal);
      uvs.push_back(vertex.uv);
    }
    const std::size_t count = range.vertex_count;
    const int position =
        add_accessor(add_view(positions.data(), count * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    model_.accessors[static_cast<std::size_t>(position)].minValues = {range.bounds.min.x, range.bounds.min.y,
                                                                      range.bounds.min.z};
    model_.accessors[static_cast<std::size_t>(position)].maxValues = {range.bounds.max.x, range.bounds.max.y,
                                                                      range.bounds.max.z};
    const int normal =
        add_accessor(add_view(normals.data(), count * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    const int uv = add_accessor(add_view(uvs.data(), count * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
    std::map<std::string, int> attributes{{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}};
    attributes_.emplace(mesh, attributes);
    return attributes;
  }

  int indices_of(std::uint32_t mesh) {
    if (const auto found = indices_.find(mesh); found != indices_.end()) return found->second;
    const MeshRange& range = scene_.meshes.meshes[mesh];
    const std::uint32_t* first = scene_.meshes.indices.data() + range.first_index;
    const int accessor = add_accessor(
        add_view(first, range.index_count * sizeof(std::uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, range.index_count);
    indices_.emplace(mesh, accessor);
    return accessor;
  }

  int material_of(const Material& m) {
    const auto key =
        std::make_tuple(m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a, m.base_color_texture,
                        m.specular, m.shininess, int(m.alpha_mode), m.alpha_cutoff, m.double_sided);
    if (const auto found = materials_.find(key); found != materials_.end()) return found->second;
    tinygltf::Material material;
    material.pbrMetallicRoughness.baseColorFactor = {m.base_color.r, m.base_color.g, m.base_color.b,
                                                     m.base_color.a};
    if (m.base_color_texture != no_texture)
      material.pbrMetallicRoughness.baseColorTexture.index = texture_of(m.base_color_texture);
    material.alphaMode = m.alpha_mode == AlphaMode::mask    ? "MASK"
                         : m.alpha_mode == AlphaMode::blend ? "BLEND"
                                                            : "OPAQUE";
    material.alphaCutoff = m.alpha_cutoff;
    material.doubleSided = m.double_sided;
    material.extras = to_value({{"shadowgraph", {{"specular", m.specular}, {"shininess", m.shininess}}}});
    model_.materials.push_back(material);
    const int index = static_cast<int>(model_.materials.size() - 1);
    materials_.emplace(key, index);
    return index;
  }

  int texture_of(std::uint32_t texture) {
    if (const auto found = textures_.find(texture); found != textures_.end()) return found->second;
    const Texture& source = scene_.textures.textures[texture];
    tinygltf::Image image;
    image.name = source.name;
    image.width = static_cast<int>(source.width);
    image.height = static_cast<int>(source.height);
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image = source.pixels;
    image.mimeType = "image/png";
    model_.images.push_back(image);
    tinygltf::Texture gltf_texture;
    gltf_texture.source = static_cast<int>(model_.images.size() - 1);
    model_.textures.push_back(gltf_texture);
    const int index = static_cast<int>(model_.textures.size() - 1);
    textures_.emplace(texture, index);
    return index;
  }

  const Scene& scene_;
  tinygltf::Model model_;
  ExportReport report_;
  std::vector<int> roots_;
  std::unordered_map<ecs::Entity, int> node_of_;
  std::vector<nlohmann::json> lights_;
  std::size_t cylinders_ = 0;
  std::map<std::pair<std::uint32_t, int>, int> meshes_;
  std::unordered_map<std::uint32_t, std::map<std::string, int>> attributes_;
  std::unordered_map<std::uint32_t, int> indices_;
  std::map<std::tuple<float, float, float, float, std::uint32_t, float, float, int, float, bool>, int>
      materials_;
  std::unordered_map<std::uint32_t, int> textures_;
};

}  // namespace

ExportReport export_gltf(const Scene& scene, const std::optional<ExportView>& view, const std::string& path) {
  Exporter exporter(scene);
  const ExportReport report = exporter.run(view);
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToFile(&exporter.model(), path, true, true, !binary, binary)) {
    throw SceneError(path, "(file)", "cannot be written");
  }
  return report;
}

}  // namespace sg::scene
