// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "systems/scene/gltf_json.h"

namespace sg::scene {

void import_textures(const tinygltf::Model& model, Scene& scene) {
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    const tinygltf::Image& image = model.images[i];
    Texture texture;
    texture.name = image.name.empty() ? image.uri : image.name;
    // decode_rgba8 (gltf_model.cpp) produced every decoded image; an empty one was not decoded.
    if (!image.image.empty()) {
      texture.width = static_cast<std::uint32_t>(image.width);
      texture.height = static_cast<std::uint32_t>(image.height);
      texture.pixels = image.image;
    }
    scene.textures.textures.push_back(std::move(texture));
  }
}

namespace {

// KHR_materials_specular's strength as the Blinn-Phong kS: its specularFactor times the largest
// channel of its specularColorFactor scale the default kS, as they scale a dielectric's default
// reflectance (both 1 by default: the default kS), held within [0, 1]. Its textures are not read.
void read_specular_extension(const tinygltf::Material& source, const std::string& object, Material& material,
                             Scene& scene) {
  const auto found = source.extensions.find("KHR_materials_specular");
  if (found == source.extensions.end()) return;
  const tinygltf::Value& specular = found->second;
  const auto number = [&](const tinygltf::Value& value, const std::string& key) -> std::optional<double> {
    if (value.IsNumber() && std::isfinite(value.GetNumberAsDouble()) && value.GetNumberAsDouble() >= 0.0) {
      return value.GetNumberAsDouble();
    }
    warn(scene, object + ": KHR_materials_specular." + key + " is not a number >= 0; using 1");
    return std::nullopt;
  };
  double factor = 1.0;
  if (specular.Has("specularFactor"))
    factor = number(specular.Get("specularFactor"), "specularFactor").value_or(1.0);
  double color = 1.0;
  if (specular.Has("specularColorFactor")) {
    const tinygltf::Value& rgb = specular.Get("specularColorFactor");
    if (rgb.IsArray() && rgb.ArrayLen() == 3) {
      color = 0.0;
      for (int c = 0; c < 3; ++c) {
        color = std::max(color, number(rgb.Get(c), "specularColorFactor").value_or(1.0));
      }
    } else {
      warn(scene, object + ": KHR_materials_specular.specularColorFactor is not 3 numbers; using [1, 1, 1]");
    }
  }
  for (const char* texture : {"specularTexture", "specularColorTexture"}) {
    if (specular.Has(texture)) warn(scene, object + ": KHR_materials_specular." + texture + " is not read");
  }
  const double strength = Material{}.specular * factor * color;
  material.specular = static_cast<float>(std::min(strength, 1.0));
  if (strength > 1.0) warn(scene, object + ": KHR_materials_specular's strength is above 1; held at 1");
}

}  // namespace

std::vector<Material> import_materials(const tinygltf::Model& model, Scene& scene) {
  std::vector<Material> materials;
  materials.reserve(model.materials.size());
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    const auto& pbr = model.materials[m].pbrMetallicRoughness;
    const std::string object = indexed("materials", m);
    Material material;
    if (pbr.baseColorFactor.size() == 4) {
      const glm::vec4 factor{pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                             pbr.baseColorFactor[3]};
      material.base_color = glm::clamp(factor, 0.0f, 1.0f);
      if (material.base_color != factor) warn(scene, object + ": baseColorFactor outside [0, 1]; clamped");
    }
    if (pbr.baseColorTexture.index >= 0) {
      const int image = model.textures[static_cast<std::size_t>(pbr.baseColorTexture.index)].source;
      if (image >= 0 && !scene.textures.textures[static_cast<std::size_t>(image)].pixels.empty()) {
        material.base_color_texture = static_cast<std::uint32_t>(image);
      } else {
        warn(scene, object + ": base color texture has no decoded image; ignored");
      }
      if (pbr.baseColorTexture.texCoord != 0) {
        warn(scene, object + ": base color texture uses TEXCOORD_" +
                        std::to_string(pbr.baseColorTexture.texCoord) + "; TEXCOORD_0 used instead");
      }
    }
    const tinygltf::Material& source = model.materials[m];
    if (source.alphaMode == "MASK") {
      material.alpha_mode = AlphaMode::mask;
      material.alpha_cutoff = static_cast<float>(source.alphaCutoff);
    } else if (source.alphaMode == "BLEND") {
      material.alpha_mode = AlphaMode::blend;
    }
    material.double_sided = source.doubleSided;
    read_specular_extension(source, object, material, scene);
    // Blinn-Phong terms glTF has no place for, as export_gltf keeps them (over the extension's).
    if (source.extras.Has("shadowgraph")) {
      const tinygltf::Value& ours = source.extras.Get("shadowgraph");
      const auto number = [&](const char* key, float& target, float low, float high) {
        if (!ours.Has(key)) return;
        const tinygltf::Value& value = ours.Get(key);
        if (!value.IsNumber()) {
          warn(scene, object + ": extras.shadowgraph." + key + " is not a number; using the default");
          return;
        }
        target = std::clamp(static_cast<float>(value.GetNumberAsDouble()), low, high);
      };
      number("specular", material.specular, 0.0f, 1.0f);
      number("shininess", material.shininess, 1.0f, 4096.0f);
    }
    materials.push_back(material);
  }
  return materials;
}

}  // namespace sg::scene
