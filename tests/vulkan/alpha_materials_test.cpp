// glTF's alphaMode and doubleSided on lavapipe, under validation: a masked card shows, and
// casts, the shape of its texture's alpha; a double-sided card shows its back face, lit from
// its side; on every lighting path.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "sandbox/sandbox_frame.h"
#include "systems/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "vulkan_test_context.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 96;
constexpr uint32_t height = 96;

constexpr LightingPath every_path[] = {LightingPath::deferred, LightingPath::forward, LightingPath::fused};

scene::Material matte(glm::vec4 color) {
  scene::Material m;
  m.base_color = color;
  m.specular = 0.0f;
  return m;
}

// A texture of `columns` texels in a row, opaque red on the left half, fully transparent red on
// the right.
scene::Texture half_transparent(uint32_t columns) {
  scene::Texture texture{"half", columns, 1, std::vector<uint8_t>(size_t{columns} * 4, 0)};
  for (uint32_t x = 0; x < columns; ++x) {
    texture.pixels[x * 4] = 255;
    texture.pixels[x * 4 + 3] = x < columns / 2 ? 255 : 0;
  }
  return texture;
}

class AlphaMaterials : public GpuTest {
 protected:
  // One frame of `scene` on `lighting`.
  vk::Rgba8Image render(sandbox::SandboxScene& scene, LightingPath lighting) {
    sandbox::Options options;
    options.lighting = lighting;
    options.animate = false;
    vk::FrameRing frames(context);
    sandbox::SandboxFrame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({width, height});
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    return vk::read_rgba8(context, frame.image());
  }

  // The linear colour where `scene`'s camera sees world point `p`.
  static glm::vec3 seen(const vk::Rgba8Image& image, const sandbox::SandboxScene& scene, glm::vec3 p) {
    const glm::vec4 clip =
        projection_matrix(scene.lens, float(width) / height) * view_matrix(scene.pose) * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const uint8_t* pixel =
        image.at(uint32_t((ndc.x * 0.5f + 0.5f) * width), uint32_t((ndc.y * 0.5f + 0.5f) * height));
    return {vk::srgb_to_linear(pixel[0]), vk::srgb_to_linear(pixel[1]), vk::srgb_to_linear(pixel[2])};
  }
};

// A 4 x 4 m red card 1 m above a green floor, its left half opaque and its right half cut out
// (alphaMode MASK), under a sun slanting towards +X, seen from straight above: through the hole
// the floor shows, in the opaque half's shadow next to the hole's left edge and lit a metre on.
TEST_F(AlphaMaterials, AMaskedCardShowsAndCastsItsTexturesShape) {
  sandbox::SandboxScene scene;
  scene.scene.name = "masked card";
  const uint32_t box = scene::add_box_mesh(scene.scene.meshes);
  const uint32_t quad = scene::add_quad_mesh(scene.scene.meshes);
  scene.scene.textures.textures.push_back(half_transparent(8));
  scene::add_instance(scene.scene, box, {{0.0f, -0.5f, 0.0f}, glm::quat(1, 0, 0, 0), {20.0f, 1.0f, 20.0f}},
                      matte({0.1f, 0.8f, 0.1f, 1.0f}));
  scene::Material card = matte(glm::vec4(1.0f));
  card.base_color_texture = 0;
  card.alpha_mode = scene::AlphaMode::mask;
  scene::add_instance(scene.scene, quad, {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {4.0f, 1.0f, 4.0f}},
                      card);
  scene::ShadowSettings hard;
  hard.algorithm = scene::ShadowAlgorithm::hard;
  scene::add_light(scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
                   {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {1, 4, 0}), glm::vec3(1.0f)},
                   hard, "sun");
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{0.0f, 8.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};

  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(lighting_path_name(path)));
    const vk::Rgba8Image image = render(scene, path);
    const glm::vec3 opaque = seen(image, scene, {-1.0f, 1.0f, 0.0f});
    const glm::vec3 shadowed = seen(image, scene, {0.4f, 0.0f, 0.0f});
    const glm::vec3 lit = seen(image, scene, {1.6f, 0.0f, 0.0f});
    EXPECT_GT(opaque.r, 4.0f * opaque.g) << "the card's opaque half is red";
    EXPECT_GT(shadowed.g, 4.0f * shadowed.r) << "the green floor shows through the hole";
    EXPECT_GT(lit.g, 4.0f * lit.r) << "the green floor shows through the hole";
  }
}

// A card 1 m up, facing up, seen from below with a sun shining up at it: single-sided, its back
// face is culled and the background shows; double-sided, the back face shows, lit through its
// flipped normal.
TEST_F(AlphaMaterials, ADoubleSidedCardShowsItsBackFaceLitFromItsSide) {
  const auto card_seen = [&](bool double_sided, LightingPath path) {
    sandbox::SandboxScene scene;
    scene.scene.name = "card";
    const uint32_t quad = scene::add_quad_mesh(scene.scene.meshes);
    scene::Material card = matte({0.9f, 0.9f, 0.9f, 1.0f});
    card.double_sided = double_sided;
    scene::add_instance(scene.scene, quad, {{0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), {4.0f, 1.0f, 4.0f}},
                        card);
    scene::add_light(
        scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.8f},
        {glm::vec3(0.0f, -5.0f, 0.0f), scene::look_rotation({0, -5, 0}, {0.1f, -4, 0}), glm::vec3(1.0f)},
        scene::ShadowSettings{}, "sun below");
    ecs::update_world_transforms(scene.scene.world, 0);
    scene.pose = {{0.0f, -6.0f, 0.01f}, {0.0f, 1.0f, 0.0f}};
    const vk::Rgba8Image image = render(scene, path);
    return seen(image, scene, {0.5f, 1.0f, 0.5f}).g;
  };
  for (const LightingPath path : every_path) {
    SCOPED_TRACE(std::string(lighting_path_name(path)));
    EXPECT_NEAR(card_seen(false, path), background_colour.g, 0.01f) << "the background";
    EXPECT_GT(card_seen(true, path), 0.4f) << "the lit back face";
  }
}

}  // namespace
}  // namespace sg::test
