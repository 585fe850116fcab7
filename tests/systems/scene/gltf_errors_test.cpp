// SPDX-License-Identifier: MIT
// One test per class of malformed input: the import must throw SceneError naming the file,
// the object and the problem, and never crash (the suite also runs under ASan/UBSan).
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "systems/scene/gltf_import.h"
#include "systems/scene/scene_error.h"
#include "tests/support/gltf_writer.h"

namespace sg::scene {
namespace {

using test::f32;
using test::GltfWriter;
using test::TempDir;

// Loads `path` expecting a SceneError whose message holds the file name and every fragment.
void expect_refused(const std::filesystem::path& path, const std::vector<std::string>& fragments) {
  try {
    load_gltf(path.string());
    ADD_FAILURE() << path << " loaded, but should have been refused";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "missing \"" << fragment << "\" in: " << message;
    }
  }
}

// A valid one-triangle file to damage.
GltfWriter triangle_file() {
  GltfWriter file;
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}})}});
  return file;
}

TEST(GltfErrors, TruncatedGlb) {
  TempDir dir;
  std::vector<std::uint8_t> bytes = triangle_file().glb_bytes();
  const std::filesystem::path path = dir.path("truncated.glb");
  test::write_file(path, bytes.data(), bytes.size() / 2);
  expect_refused(path, {"glb header", "truncated"});
  test::write_file(path, bytes.data(), 10);
  expect_refused(path, {"glb header", "truncated"});
}

TEST(GltfErrors, GlbChunkLongerThanTheFile) {
  TempDir dir;
  std::vector<std::uint8_t> bytes = triangle_file().glb_bytes();
  bytes[12] = 0xff;  // JSON chunk length low byte: now longer than what follows
  bytes[13] = 0xff;
  bytes[14] = 0xff;
  const std::filesystem::path path = dir.path("chunk.glb");
  test::write_file(path, bytes.data(), bytes.size());
  expect_refused(path, {"glb chunk 0", "truncated"});
}

TEST(GltfErrors, IndexOutOfRange) {
  TempDir dir;
  GltfWriter file;
  const std::vector<std::uint16_t> indices = {0, 1, 5};
  const int index_accessor = file.add_accessor(file.add_view(indices), test::u16, 3, "SCALAR");
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, index_accessor)}});
  expect_refused(file.write_gltf(dir, "indices"), {"accessors[0]", "index 5", "out of range", "3 vertices"});
}

TEST(GltfErrors, UnknownAlphaModeAndNegativeCutoff) {
  TempDir dir;
  for (const auto& [material, fragment] :
       {std::pair{nlohmann::json{{"alphaMode", "CLIP"}}, std::string("alphaMode 'CLIP'")},
        std::pair{nlohmann::json{{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}},
                  std::string("alphaCutoff")}}) {
    GltfWriter file;
    file.document["materials"] = nlohmann::json::array({material});  // {material} alone copies it under clang
    file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, -1, 0)}});
    expect_refused(file.write_gltf(dir, "alpha"), {"materials[0]", fragment});
  }
}

TEST(GltfErrors, IndexCountNotAMultipleOfThree) {
  TempDir dir;
  GltfWriter file;
  const std::vector<std::uint16_t> indices = {0, 1, 2, 0};
  const int index_accessor = file.add_accessor(file.add_view(indices), test::u16, 4, "SCALAR");
  file.add_node({{"mesh", file.add_mesh({{"POSITION", file.add_triangle_positions()}}, index_accessor)}});
  expect_refused(file.write_gltf(dir, "count"), {"meshes[0].primitives[0]", "4 is not a multiple of 3"});
}

TEST(GltfErrors, MissingBufferFile) {
  TempDir dir;
  GltfWriter file = triangle_file();
  const std::filesystem::path path = file.write_gltf(dir, "missing", GltfWriter::Buffer::bin_file);
  std::filesystem::remove(dir.path("missing.bin"));
  expect_refused(path, {"buffers[0]", "missing buffer file", "file not found", "missing.bin"});
}

TEST(GltfErrors, BufferFileShorterThanDeclared) {
  TempDir dir;
  GltfWriter file = triangle_file();
  const std::filesystem::path path = file.write_gltf(dir, "short", GltfWriter::Buffer::bin_file);
  std::filesystem::resize_file(dir.path("short.bin"), 20);
  expect_refused(path, {"buffers[0]", "byteLength 36 exceeds the data", "holds 20 bytes"});
}

TEST(GltfErrors, DeclaredOneTebibyteBufferIsRefusedBeforeAllocating) {
  TempDir dir;
  const std::uint64_t tebibyte = std::uint64_t{1} << 40;
  GltfWriter file = triangle_file();
  file.document["buffers"] = {
      {{"byteLength", tebibyte}, {"uri", "data:application/octet-stream;base64," + test::base64(file.blob)}}};
  expect_refused(file.write_gltf(dir, "huge"), {"buffers[0]", "byteLength 1099511627776 exceeds the data"});
  GltfWriter binary = triangle_file();
  binary.document["buffers"] = {{{"byteLength", tebibyte}}};
  expect_refused(binary.write_glb(dir, "huge"), {"buffers[0]", "BIN chunk holds 36 bytes"});
}

TEST(GltfErrors, NonFinitePosition) {
  TempDir dir;
  GltfWriter file;
  const std::vector<float> positions = {0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0};
  const int position = file.add_accessor(file.add_view(positions), f32, 3, "VEC3");
  file.add_node({{"mesh", file.add_mesh({{"POSITION", position}})}});
  expect_refused(file.write_gltf(dir, "nan"), {"accessors[0]", "POSITION has a non-finite value"});
}

// JSON cannot carry NaN or infinity; an overflowing literal is refused by the parser, so no
// transform, camera or light value can be non-finite.
TEST(GltfErrors, OverflowingJsonNumber) {
  TempDir dir;
  const std::string text = R"({"asset":{"version":"2.0"},"nodes":[{"translation":[0,1e999,0]}]})";
  test::write_file(dir.path("inf.gltf"), text);
  expect_refused(dir.path("inf.gltf"), {"JSON: does not parse", "overflow"});
}

TEST(GltfErrors, NodeCycle) {
  TempDir dir;
  GltfWriter file;
  file.add_node({{"children", {1}}});
  file.document["nodes"].push_back({{"children", {0}}});
  expect_refused(file.write_gltf(dir, "cycle"), {"nodes[", "cycle"});
}

TEST(GltfErrors, NotAGltfFile) {
  TempDir dir;
  test::write_file(dir.path("text.gltf"), "this is not json");
  expect_refused(dir.path("text.gltf"), {"JSON", "does not parse"});
  test::write_file(dir.path("empty.gltf"), "");
  expect_refused(dir.path("empty.gltf"), {"JSON"});
  expect_refused(dir.path("absent.gltf"), {"file not found"});
}

struct BadLight {
  const char* name;
  nlohmann::json light;
  std::vector<std::string> fragments;
};

TEST(GltfErrors, EachBadLightValue) {
  const std::vector<BadLight> cases = {
      {"negative_range", {{"type", "point"}, {"range", -1}}, {"lights[0]", "range -1", "greater than 0"}},
      {"zero_range", {{"type", "point"}, {"range", 0}}, {"lights[0]", "must be greater than 0"}},
      {"negative_intensity",
       {{"type", "point"}, {"intensity", -2}},
       {"lights[0]", "intensity -2", "negative"}},
      {"inner_above_outer",
       {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.4}}}},
       {"lights[0].spot", "innerConeAngle 0.6", "greater than outerConeAngle 0.4"}},
      {"outer_above_half_pi",
       {{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}},
       {"lights[0].spot", "outerConeAngle 2", "outside (0, pi/2]"}},
      {"negative_inner",
       {{"type", "spot"}, {"spot", {{"innerConeAngle", -0.1}}}},
       {"lights[0].spot", "innerConeAngle -0.1", "negative"}},
      {"spot_without_cone", {{"type", "spot"}}, {"lights[0]", "required \"spot\" object"}},
      {"unknown_type", {{"type", "area"}}, {"lights[0]", "unknown light type \"area\""}},
      {"bad_color", {{"type", "point"}, {"color", {1, 1}}}, {"lights[0]", "color is not an array of 3"}},
  };
  for (const BadLight& bad : cases) {
    SCOPED_TRACE(bad.name);
    TempDir dir;
    GltfWriter file;
    file.add_light(bad.light);
    file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    expect_refused(file.write_gltf(dir, bad.name), bad.fragments);
  }
}

TEST(GltfErrors, NodeReferencingAMissingLight) {
  TempDir dir;
  GltfWriter file;
  file.add_light({{"type", "point"}});
  file.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}});
  expect_refused(file.write_gltf(dir, "dangling"),
                 {"nodes[0]", "references light 3", "does not exist (1 lights)"});
}

// Structural damage to a valid one-triangle file, one class per case.
struct Damage {
  const char* name;
  std::function<void(GltfWriter&)> apply;
  std::vector<std::string> fragments;
};

TEST(GltfErrors, EachStructuralDamage) {
  const std::vector<Damage> cases = {
      {"accessor_longer_than_view",
       [](GltfWriter& f) { f.document["accessors"][0]["count"] = 4; },
       {"accessors[0]", "exceed bufferViews[0].byteLength 36"}},
      {"accessor_offset_past_view",
       [](GltfWriter& f) { f.document["accessors"][0]["byteOffset"] = 4; },
       {"accessors[0]", "byteOffset 4"}},
      {"stride_below_element",
       [](GltfWriter& f) { f.document["bufferViews"][0]["byteStride"] = 8; },
       {"accessors[0]", "byteStride 8 is smaller than the element size 12"}},
      {"view_outside_buffer",
       [](GltfWriter& f) { f.document["bufferViews"][0]["byteLength"] = 40; },
       {"bufferViews[0]", "exceeds buffers[0].byteLength 36"}},
      {"huge_implicit_accessor",
       [](GltfWriter& f) { f.add_accessor(-1, f32, std::size_t{1} << 40, "VEC3"); },
       {"accessors[1]", "without a bufferView is over the limit"}},
      {"dangling_mesh",
       [](GltfWriter& f) { f.document["nodes"][0]["mesh"] = 7; },
       {"nodes[0]", "mesh 7 is not an index into meshes"}},
      {"unsupported_required_extension",
       [](GltfWriter& f) {
         f.document["extensionsRequired"] = {"KHR_lights_punctual", "KHR_draco_mesh_compression"};
       },
       {"extensionsRequired[1]", "unsupported required extension \"KHR_draco_mesh_compression\""}},
      {"missing_image_file",
       [](GltfWriter& f) {
         f.document["images"] = {{{"uri", "nowhere.png"}}};
       },
       {"images[0]", "missing image file", "nowhere.png"}},
      {"undecodable_image",
       [](GltfWriter& f) {
         f.document["images"] = {{{"uri", "data:image/png;base64," + test::base64({1, 2, 3, 4, 5, 6})}}};
       },
       {"images[0]", "cannot decode"}},
  };
  for (const Damage& damage : cases) {
    SCOPED_TRACE(damage.name);
    TempDir dir;
    GltfWriter file = triangle_file();
    damage.apply(file);
    expect_refused(file.write_gltf(dir, damage.name), damage.fragments);
  }
}

}  // namespace
}  // namespace sg::scene
