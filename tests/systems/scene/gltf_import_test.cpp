// SPDX-License-Identifier: MIT
// Import of glTF files the tests write themselves: one feature per test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/gtc/constants.hpp>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/camera.h"
#include "systems/scene/gltf_import.h"
#include "systems/scene/lights.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/node_animation.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/scene_queries.h"
#include "systems/scene/shadow_settings.h"
#include "tests/support/gltf_writer.h"

namespace sg::scene {
namespace {

using test::f32;
using test::GltfWriter;
using test::TempDir;

// The mesh of the only (or first) MeshInstance, with its world matrix.
struct FoundInstance {
  ecs::Entity entity;
  const MeshRange* mesh = nullptr;
  glm::mat4 world{1.0f};
};

std::vector<FoundInstance> instances(Scene& scene) {
  std::vector<FoundInstance> found;
  scene.world.query<const MeshInstance, const ecs::WorldTransform>().for_each(
      [&](ecs::Entity entity, const MeshInstance& instance, const ecs::WorldTransform& world) {
        found.push_back({entity, &scene.meshes.meshes[instance.mesh], world.matrix});
      });
  return found;
}

std::vector<std::uint32_t> mesh_indices(const Scene& scene, const MeshRange& mesh) {
  return {scene.meshes.indices.begin() + mesh.first_index,
          scene.meshes.indices.begin() + mesh.first_index + mesh.index_count};
}

template <typename T>
std::vector<T> components(Scene& scene) {
  std::vector<T> found;
  scene.world.query<const T>().for_each([&](const T& value) { found.push_back(value); });
  return found;
}

bool has_warning(const Scene& scene, const std::string& text) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// A triangle indexed with the given component type (u8, u16 or u32).
template <typename Index>
void expect_indexed_triangle_loads(int component_type) {
  TempDir dir;
  GltfWriter file;
  const std::vector<Index> indices = {2, 1, 0};
  const int index_accessor = file.add_accessor(file.add_view(indices), component_type, 3, "SCALAR");
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, index_accessor)}});
  Scene scene = load_gltf(file.write_gltf(dir, "indexed").string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  // No normals in the file: flat normals unweld the triangle, keeping the winding.
  ASSERT_EQ(found[0].mesh->index_count, 3u);
  const Vertex* v = &scene.meshes.vertices[found[0].mesh->vertex_offset];
  EXPECT_EQ(v[0].position, glm::vec3(0, 1, 0));
  EXPECT_EQ(v[2].position, glm::vec3(0, 0, 0));
  EXPECT_NEAR(v[0].normal.z, -1.0f, 1e-6f);  // (0,1,0),(1,0,0),(0,0,0) is clockwise from +Z
}

TEST(GltfImport, EveryIndexComponentType) {
  expect_indexed_triangle_loads<std::uint8_t>(test::u8);
  expect_indexed_triangle_loads<std::uint16_t>(test::u16);
  expect_indexed_triangle_loads<std::uint32_t>(test::u32);
}

TEST(GltfImport, NonIndexedPrimitiveGetsGeneratedIndices) {
  TempDir dir;
  GltfWriter file;
  const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  const int normal = file.add_accessor(file.add_view(normals), f32, 3, "VEC3");
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}, {"NORMAL", normal}})}});
  Scene scene = load_gltf(file.write_glb(dir, "plain").string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(mesh_indices(scene, *found[0].mesh), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(scene.meshes.vertices[found[0].mesh->vertex_offset + 1].normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(found[0].mesh->bounds.max, glm::vec3(1, 1, 0));
}

TEST(GltfImport, InterleavedAttributesWithByteStride) {
  TempDir dir;
  GltfWriter file;
  // position xyz, normal xyz, uv: 8 floats per vertex.
  const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 0.0f, 0.0f,  //
                                          2, 0, 0, 0, 0, 1, 1.0f, 0.0f,  //
                                          0, 3, 0, 0, 0, 1, 0.0f, 0.5f};
  const int view = file.add_view(interleaved, 32);
  const int position = file.add_accessor(view, f32, 3, "VEC3", 0);
  const int normal = file.add_accessor(view, f32, 3, "VEC3", 12);
  const int uv = file.add_accessor(view, f32, 3, "VEC2", 24);
  file.add_node({{"mesh", file.add_mesh({{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}})}});
  Scene scene = load_gltf(file.write_gltf(dir, "interleaved", GltfWriter::Buffer::bin_file).string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  const Vertex* v = &scene.meshes.vertices[found[0].mesh->vertex_offset];
  EXPECT_EQ(v[1].position, glm::vec3(2, 0, 0));
  EXPECT_EQ(v[2].position, glm::vec3(0, 3, 0));
  EXPECT_EQ(v[2].uv, glm::vec2(0.0f, 0.5f));
  EXPECT_EQ(v[1].normal, glm::vec3(0, 0, 1));
}

TEST(GltfImport, NormalizedTexcoordsMapToUnitRange) {
  TempDir dir;
  GltfWriter file;
  const std::vector<std::uint16_t> uvs = {0, 65535, 65535, 0, 32768, 32768};
  const int uv = file.add_accessor(file.add_view(uvs), test::u16, 3, "VEC2", 0, true);
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}, {"TEXCOORD_0", uv}})}});
  Scene scene = load_gltf(file.write_gltf(dir, "normalized").string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  // Flat normals unweld but keep the order here (non-indexed).
  const Vertex* v = &scene.meshes.vertices[found[0].mesh->vertex_offset];
  EXPECT_EQ(v[0].uv, glm::vec2(0.0f, 1.0f));
  EXPECT_EQ(v[1].uv, glm::vec2(1.0f, 0.0f));
  EXPECT_NEAR(v[2].uv.x, 0.5f, 1e-4f);
}

TEST(GltfImport, SparseAccessorReplacesListedElements) {
  TempDir dir;
  GltfWriter file;
  const int base = file.add_triangle_positions();
  const std::vector<std::uint16_t> targets = {1};
  const std::vector<float> values = {5, 0, 0};
  const int index_view = file.add_view(targets);
  const int value_view = file.add_view(values);
  file.document["accessors"][base]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", index_view}, {"componentType", test::u16}}},
      {"values", {{"bufferView", value_view}}}};
  // A second, view-less sparse accessor: zeros except element 2.
  const int implicit = file.add_accessor(-1, f32, 3, "VEC3");
  file.document["accessors"][implicit]["sparse"] = {
      {"count", 1},
      {"indices",
       {{"bufferView", file.add_view(std::vector<std::uint16_t>{2, 0})}, {"componentType", test::u16}}},
      {"values", {{"bufferView", file.add_view(std::vector<float>{0, 0, 1})}}}};
  file.add_node({{"mesh", file.add_mesh({{"POSITION", base}, {"NORMAL", implicit}})}});
  Scene scene = load_gltf(file.write_gltf(dir, "sparse").string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  const Vertex* v = &scene.meshes.vertices[found[0].mesh->vertex_offset];
  EXPECT_EQ(v[1].position, glm::vec3(5, 0, 0));
  EXPECT_EQ(v[2].normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(v[0].normal, glm::vec3(0, 1, 0));  // a zero normal becomes +Y, never NaN
}

TEST(GltfImport, HierarchyComposesTrsAndMatrixTransforms) {
  TempDir dir;
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  // Parent: translate (10, 0, 0) and turn 90 degrees about +Y, as a column-major matrix.
  const nlohmann::json matrix = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 10, 0, 0, 1};
  file.document["nodes"].push_back(
      {{"name", "child"}, {"translation", {0, 0, 1}}, {"scale", {2, 2, 2}}, {"mesh", mesh}});
  const int parent = file.add_node({{"name", "parent"}, {"matrix", matrix}, {"children", {0}}});
  (void)parent;
  Scene scene = load_gltf(file.write_gltf(dir, "hierarchy").string());
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  // The primitive entity is a child of the node entity, itself a child of "parent".
  const ecs::Entity node = ecs::parent_of(scene.world, found[0].entity);
  ASSERT_NE(node, ecs::null_entity);
  EXPECT_EQ(scene.world.get<Name>(node).value, "child");
  EXPECT_EQ(scene.world.get<Name>(ecs::parent_of(scene.world, node)).value, "parent");
  // Vertex (1,0,0): scaled to (2,0,0), moved to (2,0,1), turned to (1,0,-2), moved to (11,0,-2).
  const glm::vec3 moved = glm::vec3(found[0].world * glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(moved.x, 11.0f, 1e-5f);
  EXPECT_NEAR(moved.y, 0.0f, 1e-5f);
  EXPECT_NEAR(moved.z, -2.0f, 1e-5f);
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfImport, MatrixWithShearIsApproximatedWithAWarning) {
  TempDir dir;
  GltfWriter file;
  file.add_node({{"matrix", {1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  Scene scene = load_gltf(file.write_gltf(dir, "shear").string());
  EXPECT_TRUE(has_warning(scene, "nodes[0]: matrix has shear"));
}

TEST(GltfImport, BaseColorFactorAndTexture) {
  TempDir dir;
  GltfWriter file;
  // A 1x1 red PNG, as stb_image_write would produce it.
  const std::vector<std::uint8_t> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
      0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
      0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x08,
      0xd7, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18, 0xdd, 0x8d,
      0xb0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  file.document["images"] = {{{"uri", "data:image/png;base64," + test::base64(png)}, {"name", "red"}}};
  file.document["textures"] = {{{"source", 0}}};
  file.document["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}},
      {{"pbrMetallicRoughness", {{"baseColorFactor", {2.0, 0.5, 0.5, 1.0}}}}}};
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, -1, 0)}});
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, -1, 1)}});
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}})}});
  Scene scene = load_gltf(file.write_gltf(dir, "material").string());
  ASSERT_EQ(scene.textures.textures.size(), 1u);
  const Texture& texture = scene.textures.textures[0];
  EXPECT_EQ(texture.width, 1u);
  EXPECT_EQ(texture.name, "red");
  EXPECT_EQ(texture.pixels, (std::vector<std::uint8_t>{255, 0, 0, 255}));
  const auto materials = components<Material>(scene);
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[0].base_color, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
  EXPECT_EQ(materials[0].base_color_texture, 0u);
  EXPECT_EQ(materials[1].base_color.r, 1.0f);  // clamped
  EXPECT_TRUE(has_warning(scene, "materials[1]: baseColorFactor outside [0, 1]"));
  EXPECT_EQ(materials[2].base_color, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));  // the default grey
  EXPECT_EQ(materials[2].base_color_texture, no_texture);
}

TEST(GltfImport, AlphaModesCutoffsAndDoubleSidedness) {
  TempDir dir;
  GltfWriter file;
  file.document["materials"] = {
      {{"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true}},
      {{"alphaMode", "MASK"}},
      {{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 1.0, 1.0, 0.4}}}}},
      {{"alphaMode", "OPAQUE"}}};
  for (int m = 0; m < 4; ++m) {
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, -1, m)}});
  }
  Scene scene = load_gltf(file.write_gltf(dir, "alpha").string());
  const auto materials = components<Material>(scene);
  ASSERT_EQ(materials.size(), 4u);
  EXPECT_EQ(materials[0].alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(materials[0].alpha_cutoff, 0.3f);
  EXPECT_TRUE(materials[0].double_sided);
  EXPECT_EQ(materials[1].alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(materials[1].alpha_cutoff, 0.5f) << "glTF's default cutoff";
  EXPECT_FALSE(materials[1].double_sided);
  EXPECT_EQ(materials[2].alpha_mode, AlphaMode::blend);
  EXPECT_FLOAT_EQ(materials[2].base_color.a, 0.4f);
  EXPECT_EQ(materials[3].alpha_mode, AlphaMode::opaque);
}

// KHR_materials_specular scales the default specular strength; extras.shadowgraph.specular, as
// export_gltf writes it, wins over it.
TEST(GltfImport, SpecularStrengthFromKhrMaterialsSpecular) {
  TempDir dir;
  GltfWriter file;
  const auto specular = [](nlohmann::json extension) {
    return nlohmann::json{{"extensions", {{"KHR_materials_specular", std::move(extension)}}}};
  };
  file.document["materials"] = {
      specular({{"specularFactor", 0.5}}), specular({{"specularColorFactor", {0.2, 2.0, 1.0}}}),
      specular({{"specularFactor", 8.0}}),
      nlohmann::json{{"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.5}}}}},
                     {"extras", {{"shadowgraph", {{"specular", 0.9}}}}}},
      specular({{"specularFactor", "high"}, {"specularTexture", {{"index", 0}}}})};
  file.document["extensionsUsed"] = {"KHR_materials_specular"};
  for (int m = 0; m < 5; ++m) {
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, -1, m)}});
  }
  Scene scene = load_gltf(file.write_gltf(dir, "specular").string());
  const auto materials = components<Material>(scene);
  ASSERT_EQ(materials.size(), 5u);
  const float default_specular = Material{}.specular;
  EXPECT_FLOAT_EQ(materials[0].specular, 0.5f * default_specular);
  EXPECT_FLOAT_EQ(materials[1].specular, 2.0f * default_specular) << "the color's largest channel";
  EXPECT_FLOAT_EQ(materials[2].specular, 1.0f);
  EXPECT_TRUE(has_warning(scene, "materials[2]: KHR_materials_specular's strength is above 1; held at 1"));
  EXPECT_FLOAT_EQ(materials[3].specular, 0.9f) << "the engine's own extras win";
  EXPECT_FLOAT_EQ(materials[4].specular, default_specular);
  EXPECT_TRUE(has_warning(scene, "materials[4]: KHR_materials_specular.specularFactor is not a number"));
  EXPECT_TRUE(has_warning(scene, "materials[4]: KHR_materials_specular.specularTexture is not read"));
}

TEST(GltfImport, PerspectiveCameraAndSkippedOrthographic) {
  TempDir dir;
  GltfWriter file;
  file.document["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"aspectRatio", 1.5}}}},
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
  file.add_node({{"camera", 0}, {"translation", {0, 1, 5}}});
  file.add_node({{"camera", 1}});
  Scene scene = load_gltf(file.write_gltf(dir, "camera").string());
  const auto cameras = components<Camera>(scene);
  ASSERT_EQ(cameras.size(), 1u);
  EXPECT_FLOAT_EQ(cameras[0].yfov, 0.8f);
  EXPECT_FLOAT_EQ(cameras[0].znear, 0.1f);
  EXPECT_FLOAT_EQ(cameras[0].zfar, 1000.0f);  // infinite far plane -> 10,000 * znear
  EXPECT_FLOAT_EQ(cameras[0].aspect, 1.5f);
  const auto camera = first_camera(scene);
  ASSERT_TRUE(camera.has_value());
  EXPECT_EQ(light_position(scene.world.get<ecs::WorldTransform>(*camera)), glm::vec3(0, 1, 5));
  EXPECT_TRUE(has_warning(scene, "cameras[1]: orthographic cameras are not supported"));
}

TEST(GltfImport, EachLightTypeWithShadowExtras) {
  TempDir dir;
  GltfWriter file;
  file.add_light({{"type", "point"},
                  {"color", {1, 0.5, 0.25}},
                  {"intensity", 20},
                  {"range", 8},
                  {"extras",
                   {{"algorithm", "pcss"},
                    {"bias", 0.002},
                    {"slope_bias", 0.01},
                    {"pcf_radius", 2.5},
                    {"light_size", 0.7},
                    {"density", 0.5},
                    {"shadow_color", {0.1, 0.2, 0.3}},
                    {"resolution", 512},
                    {"casts_shadow", false}}}});
  file.add_light({{"type", "spot"},
                  {"intensity", 4},
                  {"range", 12},
                  {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}},
                  {"extras",
                   {{"algorithm", "noise"},
                    {"update", "on_demand"},
                    {"priority", -1.5},
                    {"contact_length", 0.3},
                    {"pcf_half_width", 2},
                    {"blocker_taps", 8},
                    {"filter_taps", 12},
                    {"noise_taps", 8},
                    {"caster_mask", 5},
                    {"light_mask", 2}}}});
  file.add_light(
      {{"type", "directional"}, {"intensity", 3}, {"extras", {{"algorithm", "hard"}, {"cascades", 2}}}});
  // Rotated -90 degrees about X: -Z turns to -Y, the light points down.
  const nlohmann::json down = {-0.7071068, 0, 0, 0.7071068};
  file.add_node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.add_node({{"rotation", down}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  file.add_node({{"rotation", down}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  file.document["extensionsRequired"] = {"KHR_lights_punctual"};
  Scene scene = load_gltf(file.write_gltf(dir, "lights").string());
  EXPECT_TRUE(scene.warnings.empty());

  ecs::Entity point_entity;
  scene.world.query<const PointLight>().for_each([&](ecs::Entity e, const PointLight&) { point_entity = e; });
  const PointLight& point = scene.world.get<PointLight>(point_entity);
  EXPECT_EQ(point.color, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(point.intensity, 20.0f);
  EXPECT_FLOAT_EQ(point.range, 8.0f);
  EXPECT_EQ(point.falloff, FalloffMode::gltf_punctual);
  EXPECT_EQ(light_position(scene.world.get<ecs::WorldTransform>(point_entity)), glm::vec3(1, 2, 3));
  const ShadowSettings& shadow = scene.world.get<ShadowSettings>(point_entity);
  EXPECT_EQ(shadow.algorithm, ShadowAlgorithm::pcss);
  EXPECT_FLOAT_EQ(shadow.constant_bias, 0.002f);
  EXPECT_FLOAT_EQ(shadow.slope_bias, 0.01f);
  EXPECT_FLOAT_EQ(shadow.pcf_radius, 2.5f);
  EXPECT_FLOAT_EQ(shadow.light_size, 0.7f);
  EXPECT_FLOAT_EQ(shadow.density, 0.5f);
  EXPECT_EQ(shadow.shadow_color, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(shadow.resolution, 512u);
  EXPECT_FALSE(shadow.casts_shadow);

  scene.world.query<const SpotLight, const ShadowSettings, const ecs::WorldTransform>().for_each(
      [](const SpotLight& spot, const ShadowSettings& settings, const ecs::WorldTransform& world) {
        EXPECT_FLOAT_EQ(spot.inner_cone, 0.2f);
        EXPECT_FLOAT_EQ(spot.outer_cone, 0.5f);
        EXPECT_FLOAT_EQ(spot.range, 12.0f);
        EXPECT_EQ(settings.algorithm, ShadowAlgorithm::noise);
        EXPECT_EQ(settings.update, ShadowUpdate::on_demand);
        EXPECT_FLOAT_EQ(settings.priority, -1.5f);
        EXPECT_FLOAT_EQ(settings.contact_length, 0.3f);
        EXPECT_EQ(settings.kernel, (ShadowKernel{2, 8, 12, 8}));
        EXPECT_EQ(settings.caster_mask, 5);
        EXPECT_EQ(settings.light_mask, 2);
        EXPECT_NEAR(light_direction(world).y, -1.0f, 1e-5f);
      });
  scene.world.query<const DirectionalLight, const ShadowSettings>().for_each(
      [](const DirectionalLight& sun, const ShadowSettings& settings) {
        EXPECT_FLOAT_EQ(sun.intensity, 3.0f);
        EXPECT_EQ(settings.algorithm, ShadowAlgorithm::hard);
        EXPECT_EQ(settings.cascades, 2u);
      });
  const SceneStats stats = scene_stats(scene);
  EXPECT_EQ(stats.point_lights, 1u);
  EXPECT_EQ(stats.spot_lights, 1u);
  EXPECT_EQ(stats.directional_lights, 1u);
  EXPECT_EQ(stats.shadow_casting_lights, 2u);
}

TEST(GltfImport, LightDefaultsWithoutExtrasOrRange) {
  TempDir dir;
  GltfWriter file;
  file.add_light({{"type", "point"}, {"intensity", 4}});
  file.add_light({{"type", "spot"}, {"spot", nlohmann::json::object()}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  Scene scene = load_gltf(file.write_gltf(dir, "defaults").string());
  const auto points = components<PointLight>(scene);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_FLOAT_EQ(points[0].range, 32.0f);  // infinite -> 16 * sqrt(intensity)
  EXPECT_EQ(points[0].color, glm::vec3(1.0f));
  const auto spots = components<SpotLight>(scene);
  ASSERT_EQ(spots.size(), 1u);
  EXPECT_FLOAT_EQ(spots[0].inner_cone, 0.0f);
  EXPECT_FLOAT_EQ(spots[0].outer_cone, glm::quarter_pi<float>());
  const ShadowSettings defaults;
  for (const ShadowSettings& shadow : components<ShadowSettings>(scene)) {
    EXPECT_EQ(shadow.algorithm, defaults.algorithm);
    EXPECT_EQ(shadow.constant_bias, defaults.constant_bias);
    EXPECT_EQ(shadow.resolution, defaults.resolution);
    EXPECT_EQ(shadow.caster_mask, all_layers);
    EXPECT_EQ(shadow.light_mask, all_layers);
    EXPECT_TRUE(shadow.casts_shadow);
  }
}

TEST(GltfImport, OddLightValuesAreClampedWithWarnings) {
  TempDir dir;
  GltfWriter file;
  file.add_light({{"type", "spot"},
                  {"color", {2, 0.5, -1}},
                  {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}},
                  {"extras",
                   {{"algorithm", "soft"},
                    {"density", 3},
                    {"resolution", 1e9},
                    {"cascades", 9},
                    {"update", "often"},
                    {"priority", 7},
                    {"noise_taps", 5},
                    {"filter_taps", 40},
                    {"caster_mask", 256},
                    {"light_mask", "all"}}}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  Scene scene = load_gltf(file.write_gltf(dir, "odd").string());
  const auto spots = components<SpotLight>(scene);
  ASSERT_EQ(spots.size(), 1u);
  EXPECT_EQ(spots[0].color, glm::vec3(1, 0.5f, 0));
  EXPECT_FLOAT_EQ(spots[0].inner_cone, 0.45f);
  const auto shadows = components<ShadowSettings>(scene);
  EXPECT_EQ(shadows[0].algorithm, ShadowAlgorithm::pcf);
  EXPECT_FLOAT_EQ(shadows[0].density, 1.0f);
  EXPECT_EQ(shadows[0].resolution, 16384u);
  EXPECT_EQ(shadows[0].cascades, max_shadow_cascades);
  EXPECT_EQ(shadows[0].update, ShadowUpdate::automatic);
  EXPECT_FLOAT_EQ(shadows[0].priority, max_shadow_priority);
  EXPECT_TRUE(has_warning(scene, "extras.update \"often\" is not one of"));
  EXPECT_EQ(shadows[0].kernel.noise_taps, 16u);
  EXPECT_EQ(shadows[0].kernel.filter_taps, max_filter_taps);
  EXPECT_TRUE(has_warning(scene, "extras.noise_taps 5 is not 4, 8 or 16; using 16"));
  EXPECT_EQ(shadows[0].caster_mask, all_layers);
  EXPECT_EQ(shadows[0].light_mask, all_layers);
  EXPECT_TRUE(has_warning(scene, "extras.caster_mask 256 is not a layer mask (an integer from 0 to 255)"));
  EXPECT_TRUE(has_warning(scene, "extras.light_mask \"all\" is not a layer mask"));
  EXPECT_TRUE(has_warning(scene, "color component outside [0, 1]"));
  EXPECT_TRUE(has_warning(scene, "extras.algorithm \"soft\" is not one of"));
  EXPECT_TRUE(has_warning(scene, "extras.density"));
  EXPECT_TRUE(has_warning(scene, "innerConeAngle equals outerConeAngle"));
}

// Settings may also sit in a namespaced extras.shadowgraph object (Blender writes a custom
// property group as one): its keys win over flat ones, which still count where it has none.
TEST(GltfImport, ShadowExtrasUnderAShadowgraphObjectOverrideTheFlatKeys) {
  TempDir dir;
  GltfWriter file;
  file.add_light({{"type", "point"},
                  {"extras",
                   {{"algorithm", "noise"},
                    {"density", 0.25},
                    {"shadowgraph", {{"algorithm", "pcss"}, {"light_size", 0.4}, {"resolution", "big"}}}}}});
  file.add_light({{"type", "point"}, {"extras", {{"shadowgraph", 3}}}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  Scene scene = load_gltf(file.write_gltf(dir, "namespaced").string());
  const auto shadows = components<ShadowSettings>(scene);
  ASSERT_EQ(shadows.size(), 2u);
  EXPECT_EQ(shadows[0].algorithm, ShadowAlgorithm::pcss) << "the namespaced key wins";
  EXPECT_FLOAT_EQ(shadows[0].light_size, 0.4f);
  EXPECT_FLOAT_EQ(shadows[0].density, 0.25f) << "a flat key it lacks still counts";
  EXPECT_EQ(shadows[0].resolution, ShadowSettings{}.resolution);
  EXPECT_TRUE(has_warning(scene, "extras.shadowgraph.resolution is not a finite number"));
  EXPECT_TRUE(has_warning(scene, "extras.shadowgraph is not an object"));
}

// Which meshes cast and receive shadows, as Blender's custom properties (extras.casts_shadow and
// receives_shadow, on the object or its mesh) or the draft KHR_lights_shadows (castShadows on a
// mesh or a light, receiveShadows on a mesh) say: the node's word over its mesh's, the extras'
// over the extension's.
TEST(GltfImport, ShadowFlagsFromExtrasAndKhrLightsShadows) {
  TempDir dir;
  GltfWriter file;
  const int glass = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  const int stone = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.document["meshes"][glass]["extras"] = {{"casts_shadow", false}};
  file.document["meshes"][stone]["extensions"] = {{"KHR_lights_shadows", {{"castShadows", false}}}};
  file.add_node({{"name", "pane"}, {"mesh", glass}});
  file.add_node({{"name", "pane that casts"},
                 {"mesh", glass},
                 {"extras", {{"shadowgraph", {{"casts_shadow", true}}}}}});
  file.add_node({{"name", "wall"}, {"mesh", stone}});
  file.add_node({{"name", "odd"}, {"mesh", stone}, {"extras", {{"casts_shadow", "no"}}}});
  file.add_node({{"name", "screen"}, {"mesh", glass}, {"extras", {{"receives_shadow", false}}}});
  file.document["meshes"][stone]["extensions"]["KHR_lights_shadows"]["receiveShadows"] = false;
  file.add_light({{"type", "point"}, {"extensions", {{"KHR_lights_shadows", {{"castShadows", false}}}}}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  Scene scene = load_gltf(file.write_gltf(dir, "casters").string());
  std::map<std::string, bool> casts, receives;
  scene.world.query<const MeshInstance>().for_each([&](ecs::Entity entity, const MeshInstance& instance) {
    const ecs::Entity node = scene.world.get<ecs::Parent>(entity).entity;
    casts[scene.world.get<Name>(node).value] = instance.casts_shadow;
    receives[scene.world.get<Name>(node).value] = instance.receives_shadow;
  });
  EXPECT_TRUE(receives.at("pane"));
  EXPECT_FALSE(receives.at("screen")) << "its own extras";
  EXPECT_FALSE(receives.at("wall")) << "its mesh's KHR_lights_shadows receiveShadows";
  EXPECT_FALSE(casts.at("pane")) << "its mesh's extras";
  EXPECT_TRUE(casts.at("pane that casts")) << "the node's word over its mesh's";
  EXPECT_FALSE(casts.at("wall")) << "its mesh's KHR_lights_shadows";
  EXPECT_FALSE(casts.at("odd"))
      << "a value that is not true or false is ignored: the mesh's extension counts";
  EXPECT_TRUE(has_warning(scene, "nodes[3]: extras.casts_shadow is not true or false"));
  const auto shadows = components<ShadowSettings>(scene);
  ASSERT_EQ(shadows.size(), 1u);
  EXPECT_FALSE(shadows[0].casts_shadow) << "the light's KHR_lights_shadows";
}

// A mesh's layers (systems/scene/layers.h) from its node's extras, else its mesh's; layer 0 alone
// without either; a value that is not a mask reported and skipped.
TEST(GltfImport, MeshLayersFromExtras) {
  TempDir dir;
  GltfWriter file;
  const int stage = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  const int plain = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.document["meshes"][stage]["extras"] = {{"light_layers", 2}, {"shadow_layers", 6}};
  file.add_node({{"name", "stage"}, {"mesh", stage}});
  file.add_node(
      {{"name", "stage, own"}, {"mesh", stage}, {"extras", {{"shadowgraph", {{"light_layers", 9}}}}}});
  file.add_node({{"name", "plain"}, {"mesh", plain}});
  file.add_node({{"name", "odd"}, {"mesh", plain}, {"extras", {{"shadow_layers", -3}}}});
  Scene scene = load_gltf(file.write_gltf(dir, "layers").string());
  std::map<std::string, std::pair<int, int>> layers;
  scene.world.query<const MeshInstance>().for_each([&](ecs::Entity entity, const MeshInstance& instance) {
    const ecs::Entity node = scene.world.get<ecs::Parent>(entity).entity;
    layers[scene.world.get<Name>(node).value] = {instance.light_layers, instance.shadow_layers};
  });
  EXPECT_EQ(layers.at("stage"), std::make_pair(2, 6)) << "its mesh's";
  EXPECT_EQ(layers.at("stage, own"), std::make_pair(9, 6)) << "the node's word over its mesh's";
  EXPECT_EQ(layers.at("plain"), std::make_pair(1, 1)) << "layer 0 alone";
  EXPECT_EQ(layers.at("odd"), std::make_pair(1, 1));
  EXPECT_TRUE(has_warning(scene, "nodes[3]: extras.shadow_layers -3 is not a layer mask"));
}

TEST(GltfImport, SkinnedMeshLoadsInBindPoseWithAWarning) {
  TempDir dir;
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.add_node({{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}});
  const int joint = file.add_node({{"name", "joint"}});
  const std::vector<float> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const int inverse_bind = file.add_accessor(file.add_view(identity), f32, 1, "MAT4");
  file.document["skins"] = {{{"joints", {joint}}, {"inverseBindMatrices", inverse_bind}}};
  Scene scene = load_gltf(file.write_glb(dir, "skinned").string());
  EXPECT_TRUE(has_warning(scene, "bind pose"));
  const auto found = instances(scene);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].world, glm::mat4(1.0f));  // the skinned node's own transform is ignored
}

TEST(GltfImport, NonTrianglePrimitivesAreSkippedWithAWarning) {
  TempDir dir;
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.document["meshes"][mesh]["primitives"][0]["mode"] = 1;  // lines
  file.add_node({{"mesh", mesh}});
  Scene scene = load_gltf(file.write_gltf(dir, "lines").string());
  EXPECT_TRUE(instances(scene).empty());
  EXPECT_TRUE(has_warning(scene, "meshes[0].primitives[0]: mode 1 is not triangles"));
}

TEST(GltfImport, SceneBoundsCoverTransformedInstances) {
  TempDir dir;
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.add_node({{"mesh", mesh}, {"translation", {-4, 0, 0}}});
  file.add_node({{"mesh", mesh}, {"translation", {4, 0, 2}}});
  Scene scene = load_gltf(file.write_gltf(dir, "bounds").string());
  const Aabb bounds = scene_bounds(scene);
  EXPECT_EQ(bounds.min, glm::vec3(-4, 0, 0));
  EXPECT_EQ(bounds.max, glm::vec3(5, 1, 2));
  EXPECT_EQ(scene_stats(scene).triangles, 2u);
  EXPECT_EQ(scene.meshes.meshes.size(), 1u);  // both nodes instance one library mesh
}

// A point light's node moved along +X from 0 to 4 over 2 s (LINEAR), and a STEP rotation on
// another node; `output_keys` values in the translation's output (2 for a well-formed file).
std::string write_animated(const TempDir& dir, std::size_t output_keys) {
  GltfWriter file;
  file.add_light({{"type", "point"}, {"range", 5}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  file.add_node({{"name", "turner"}});
  file.document["extensionsRequired"] = {"KHR_lights_punctual"};
  const std::vector<float> times{0.0f, 2.0f};
  std::vector<float> positions{0, 1, 0, 4, 1, 0};
  positions.resize(output_keys * 3, 0.0f);
  const std::vector<float> rotations{0, 0, 0, 1, 0, 0.7071068f, 0, 0.7071068f};
  const int input = file.add_accessor(file.add_view(times), f32, 2, "SCALAR");
  file.document["accessors"][input]["min"] = {0.0};
  file.document["accessors"][input]["max"] = {2.0};
  const int translation = file.add_accessor(file.add_view(positions), f32, output_keys, "VEC3");
  const int rotation = file.add_accessor(file.add_view(rotations), f32, 2, "VEC4");
  file.document["animations"] = {{{"samplers",
                                   {{{"input", input}, {"output", translation}},
                                    {{"input", input}, {"output", rotation}, {"interpolation", "STEP"}}}},
                                  {"channels",
                                   {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
                                    {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}}}}}};
  return file.write_gltf(dir, "animated").string();
}

TEST(GltfImport, AnimationsPlayOnTheirNodesLightsIncluded) {
  TempDir dir;
  Scene scene = load_gltf(write_animated(dir, 2));
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  ecs::Entity light;
  scene.world.query<const PointLight>().for_each([&](ecs::Entity e, const PointLight&) { light = e; });
  ASSERT_TRUE(scene.world.has<NodeAnimation>(light));
  EXPECT_FLOAT_EQ(scene.world.get<NodeAnimation>(light).channels[0].duration, 2.0f);

  animate_nodes(scene.world, 0.5f);
  ecs::update_world_transforms(scene.world, 0);
  EXPECT_EQ(light_position(scene.world.get<ecs::WorldTransform>(light)), glm::vec3(1, 1, 0));
  animate_nodes(scene.world, 2.5f);  // looped: half a second into the next round
  ecs::update_world_transforms(scene.world, 0);
  EXPECT_EQ(light_position(scene.world.get<ecs::WorldTransform>(light)), glm::vec3(1, 1, 0));
}

TEST(GltfImport, AnAnimationOutputOfTheWrongCountIsRefused) {
  TempDir dir;
  try {
    load_gltf(write_animated(dir, 3));
    FAIL() << "a sampler with 3 values for 2 keys was accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("animations[0].samplers[0]: output has 3 values for 2 keys"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace sg::scene
