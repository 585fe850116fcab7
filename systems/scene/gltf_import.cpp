// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_import.h"

#include <cmath>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "ecs/hierarchy.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/camera.h"
#include "systems/scene/gltf_animations.h"
#include "systems/scene/gltf_json.h"
#include "systems/scene/gltf_lights.h"
#include "systems/scene/gltf_materials.h"
#include "systems/scene/gltf_meshes.h"
#include "systems/scene/gltf_model.h"
#include "systems/scene/gltf_preflight.h"
#include "systems/scene/gltf_shadow_extras.h"
#include "systems/scene/gltf_source.h"
#include "systems/scene/gltf_validate.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {
namespace {

// LocalTransform holds translation, rotation and scale only; a node matrix is split into those
// (negative determinant -> negative x scale). Shear or projection cannot be kept.
ecs::LocalTransform decompose(const glm::mat4& matrix, const std::string& object, Scene& scene) {
  ecs::LocalTransform local;
  local.translation = glm::vec3(matrix[3]);
  glm::mat3 basis(matrix);
  local.scale = {glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2])};
  if (glm::determinant(basis) < 0.0f) local.scale.x = -local.scale.x;
  if (local.scale.x != 0.0f && local.scale.y != 0.0f && local.scale.z != 0.0f) {
    for (int axis = 0; axis < 3; ++axis) basis[axis] /= local.scale[axis];
    local.rotation = glm::normalize(glm::quat_cast(basis));
  }
  const glm::mat4 rebuilt = ecs::to_matrix(local);
  float error = 0.0f;
  float magnitude = 1.0f;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      error = std::max(error, std::abs(rebuilt[c][r] - matrix[c][r]));
      magnitude = std::max(magnitude, std::abs(matrix[c][r]));
    }
  }
  if (error > 1e-4f * magnitude) {
    warn(scene, object +
                    ": matrix has shear or projection; approximated by translation, "
                    "rotation and scale");
  }
  return local;
}

ecs::LocalTransform node_transform(const tinygltf::Node& node, const std::string& object, Scene& scene) {
  if (node.matrix.size() == 16) {
    glm::mat4 matrix;
    for (int i = 0; i < 16; ++i)
      matrix[i / 4][i % 4] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
    return decompose(matrix, object, scene);
  }
  ecs::LocalTransform local;
  if (node.translation.size() == 3) {
    local.translation = {node.translation[0], node.translation[1], node.translation[2]};
  }
  if (node.rotation.size() == 4) {  // glTF stores x, y, z, w
    const glm::quat rotation(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                             static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    const float length = glm::length(rotation);
    if (length > 0.0f) {
      local.rotation = rotation / length;
    } else {
      warn(scene, object + ": zero rotation quaternion; using identity");
    }
  }
  if (node.scale.size() == 3) local.scale = {node.scale[0], node.scale[1], node.scale[2]};
  return local;
}

class Importer {
 public:
  Importer(const GltfSource& source, const tinygltf::Model& model, std::vector<ImportedLight> lights,
           Scene& scene)
      : source_(source), model_(model), scene_(scene), lights_(std::move(lights)) {}

  void run() {
    // Every node's light reference is checked, not only those of the scene imported.
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      node_lights_.push_back(node_light(source_, i, lights_.size()));
    }
    import_textures(model_, scene_);
    materials_ = import_materials(model_, scene_);
    meshes_ = import_meshes(model_, scene_);
    if (!model_.skins.empty()) {
      warn(scene_, "skins present: skinned meshes are drawn in their bind pose, not deformed");
    }
    node_entities_.assign(model_.nodes.size(), ecs::null_entity);
    std::vector<std::pair<int, ecs::Entity>> pending;  // node, parent entity
    const std::vector<int> roots = root_nodes();
    for (auto root = roots.rbegin(); root != roots.rend(); ++root)
      pending.emplace_back(*root, ecs::null_entity);
    while (!pending.empty()) {
      const auto [index, parent] = pending.back();
      pending.pop_back();
      const ecs::Entity entity = add_node(static_cast<std::size_t>(index), parent);
      const auto& children = model_.nodes[static_cast<std::size_t>(index)].children;
      for (auto child = children.rbegin(); child != children.rend(); ++child)
        pending.emplace_back(*child, entity);
    }
    import_animations(source_, model_, node_entities_, scene_);
    ecs::update_world_transforms(scene_.world, 0);
  }

 private:
  std::vector<int> root_nodes() const {
    if (!model_.scenes.empty()) {
      const int chosen =
          model_.defaultScene >= 0 && static_cast<std::size_t>(model_.defaultScene) < model_.scenes.size()
              ? model_.defaultScene
              : 0;
      return model_.scenes[static_cast<std::size_t>(chosen)].nodes;
    }
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes) {
      for (const int child : node.children) is_child[static_cast<std::size_t>(child)] = true;
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  ecs::Entity add_node(std::size_t index, ecs::Entity parent) {
    const tinygltf::Node& node = model_.nodes[index];
    const std::string object = indexed("nodes", index);
    ecs::World& world = scene_.world;
    const ecs::Entity entity = world.create();
    node_entities_[index] = entity;
    world.add<ecs::LocalTransform>(entity, node_transform(node, object, scene_));
    world.add<ecs::WorldTransform>(entity);
    if (!node.name.empty()) world.add<Name>(entity, node.name);
    if (parent != ecs::null_entity) ecs::set_parent(world, entity, parent);
    if (node.mesh >= 0) add_primitives(entity, node, index);
    if (node.camera >= 0) add_camera_to(entity, static_cast<std::size_t>(node.camera));
    if (const auto cylinder = read_cylinder_light(source_.document["nodes"][index], object, scene_)) {
      world.add<CylinderLight>(entity, cylinder->light);
      world.add<ShadowSettings>(entity, cylinder->shadow);
    } else if (const auto light = node_lights_[index]) {
      const ImportedLight& imported = lights_[*light];
      std::visit([&](const auto& value) { world.add<std::decay_t<decltype(value)>>(entity, value); },
                 imported.light);
      world.add<ShadowSettings>(entity, imported.shadow);
    }
    return entity;
  }

  // A node's primitives cast and receive shadows unless the node, or else its mesh, says they do
  // not (read_shadow_flag: extras, or KHR_lights_shadows), and lie on the layers the node, or else
  // its mesh, names (read_mesh_layers), layer 0 alone if neither does.
  void add_primitives(ecs::Entity node_entity, const tinygltf::Node& node, std::size_t index) {
    ecs::World& world = scene_.world;
    const auto mesh = static_cast<std::size_t>(node.mesh);
    const auto flag = [&](ShadowFlag which) {
      const std::optional<bool> own =
          read_shadow_flag(source_.document["nodes"][index], which, indexed("nodes", index), scene_);
      return own ? own
                 : read_shadow_flag(source_.document["meshes"][mesh], which, indexed("meshes", mesh), scene_);
    };
    const auto layers = [&](MeshLayers which) {
      const std::optional<LayerMask> own =
          read_mesh_layers(source_.document["nodes"][index], which, indexed("nodes", index), scene_);
      return own ? *own
                 : read_mesh_layers(source_.document["meshes"][mesh], which, indexed("meshes", mesh), scene_)
                       .value_or(first_layer);
    };
    const std::optional<bool> casts = flag(ShadowFlag::casts);
    const std::optional<bool> receives = flag(ShadowFlag::receives);
    const LayerMask light_layers = layers(MeshLayers::light);
    const LayerMask shadow_layers = layers(MeshLayers::shadow);
    for (const ImportedPrimitive& primitive : meshes_[mesh]) {
      const ecs::Entity entity = world.create();
      world.add<ecs::LocalTransform>(entity);
      world.add<ecs::WorldTransform>(entity);
      world.add<MeshInstance>(entity, MeshInstance{primitive.mesh, casts.value_or(true),
                                                   receives.value_or(true), light_layers, shadow_layers});
      world.add<Material>(entity, primitive.material >= 0
                                      ? materials_[static_cast<std::size_t>(primitive.material)]
                                      : Material{});
      if (node.skin < 0) ecs::set_parent(world, entity, node_entity);
    }
  }

  void add_camera_to(ecs::Entity entity, std::size_t index) {
    const tinygltf::Camera& camera = model_.cameras[index];
    if (camera.type != "perspective") {
      warn(scene_, indexed("cameras", index) + ": " + camera.type + " cameras are not supported; skipped");
      return;
    }
    const tinygltf::PerspectiveCamera& p = camera.perspective;
    const auto znear = static_cast<float>(p.znear);
    scene_.world.add<Camera>(entity, static_cast<float>(p.yfov), znear,
                             p.zfar > 0.0 ? static_cast<float>(p.zfar) : 10000.0f * znear,
                             static_cast<float>(p.aspectRatio));
  }

  const GltfSource& source_;
  const tinygltf::Model& model_;
  Scene& scene_;
  std::vector<ImportedLight> lights_;
  std::vector<std::optional<std::size_t>> node_lights_;  // by node
  std::vector<ecs::Entity> node_entities_;               // by node; null when not imported
  std::vector<Material> materials_;
  std::vector<std::vector<ImportedPrimitive>> meshes_;
};

}  // namespace

Scene load_gltf(const std::string& path) {
  Scene scene;
  scene.name = path;
  const GltfSource source = read_gltf_source(path);
  preflight_gltf(source);
  // Lights first: tinygltf would reject some light errors with messages that name no light.
  std::vector<ImportedLight> lights = read_gltf_lights(source, scene);
  const tinygltf::Model model = parse_gltf_model(source, scene);
  validate_gltf_model(model, path);
  Importer(source, model, std::move(lights), scene).run();
  return scene;
}

}  // namespace sg::scene
