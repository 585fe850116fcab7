// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_preflight.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>
#include <vector>

#include "systems/scene/gltf_json.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

constexpr std::array<std::string_view, 1> supported_required_extensions = {"KHR_lights_punctual"};

bool is_data_uri(std::string_view uri) { return uri.starts_with("data:"); }

// Decodes %XX escapes, as URIs in glTF are percent-encoded ("my%20file.bin").
std::string decode_uri(std::string_view uri) {
  std::string decoded;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      decoded.push_back(static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16)));
      i += 2;
    } else {
      decoded.push_back(uri[i]);
    }
  }
  return decoded;
}

// The most bytes a base64 data URI can decode to; tinygltf decodes only base64.
std::uint64_t data_uri_capacity(const GltfSource& source, std::string_view uri, const std::string& object) {
  const std::size_t marker = uri.find(";base64,");
  if (marker == std::string_view::npos) {
    throw SceneError(source.path, object, "data URI is not base64");
  }
  const std::uint64_t payload = uri.size() - (marker + 8);
  return payload / 4 * 3 + (payload % 4 == 0 ? 0 : 3);
}

std::vector<std::uint64_t> check_buffers(const GltfSource& source) {
  const nlohmann::json& buffers = json_array(source.document, "buffers", source.path);
  std::vector<std::uint64_t> lengths;
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const std::string object = indexed("buffers", i);
    if (!buffers[i].is_object()) throw SceneError(source.path, object, "is not an object");
    const auto declared = json_uint(buffers[i], "byteLength", source.path, object);
    if (!declared) throw SceneError(source.path, object, "byteLength is missing");
    const auto uri = json_string(buffers[i], "uri", source.path, object);
    std::uint64_t available = 0;
    std::string origin;
    if (!uri) {
      if (!source.binary || i != 0) {
        throw SceneError(source.path, object, "has no uri (only a .glb's first buffer may omit it)");
      }
      available = source.bin_chunk.size();
      origin = "the .glb BIN chunk holds";
    } else if (is_data_uri(*uri)) {
      available = data_uri_capacity(source, *uri, object);
      origin = "its data URI holds at most";
    } else {
      const std::filesystem::path file = source.base_dir / decode_uri(*uri);
      available = checked_file_size(file, source.path, object + " (missing buffer file?)");
      origin = file.string() + " holds";
    }
    if (*declared > available) {
      throw SceneError(source.path, object,
                       "byteLength " + std::to_string(*declared) + " exceeds the data: " + origin + " " +
                           std::to_string(available) + " bytes");
    }
    lengths.push_back(*declared);
  }
  return lengths;
}

void check_buffer_views(const GltfSource& source, const std::vector<std::uint64_t>& buffers) {
  const nlohmann::json& views = json_array(source.document, "bufferViews", source.path);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const std::string object = indexed("bufferViews", i);
    if (!views[i].is_object()) throw SceneError(source.path, object, "is not an object");
    const auto buffer = json_uint(views[i], "buffer", source.path, object);
    const auto length = json_uint(views[i], "byteLength", source.path, object);
    const std::uint64_t offset = json_uint(views[i], "byteOffset", source.path, object).value_or(0);
    if (!buffer || *buffer >= buffers.size()) {
      throw SceneError(source.path, object, "buffer is missing or does not exist");
    }
    if (!length || *length == 0) throw SceneError(source.path, object, "byteLength is missing or 0");
    // Both terms are at most a file size (<= 2^30) or the check below fails on the first.
    if (offset > buffers[*buffer] || *length > buffers[*buffer] - offset) {
      throw SceneError(source.path, object,
                       "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(*length) +
                           " exceeds buffers[" + std::to_string(*buffer) + "].byteLength " +
                           std::to_string(buffers[*buffer]));
    }
  }
}

void check_images(const GltfSource& source) {
  const nlohmann::json& images = json_array(source.document, "images", source.path);
  const std::size_t view_count = json_array(source.document, "bufferViews", source.path).size();
  for (std::size_t i = 0; i < images.size(); ++i) {
    const std::string object = indexed("images", i);
    if (!images[i].is_object()) throw SceneError(source.path, object, "is not an object");
    const auto uri = json_string(images[i], "uri", source.path, object);
    const auto view = json_uint(images[i], "bufferView", source.path, object);
    if (uri && !is_data_uri(*uri)) {
      checked_file_size(source.base_dir / decode_uri(*uri), source.path, object + " (missing image file?)");
    } else if (!uri && (!view || *view >= view_count)) {
      throw SceneError(source.path, object, "has neither a uri nor an existing bufferView");
    }
  }
}

void check_required_extensions(const GltfSource& source) {
  const nlohmann::json& required = json_array(source.document, "extensionsRequired", source.path);
  for (std::size_t i = 0; i < required.size(); ++i) {
    const std::string name = required[i].is_string() ? required[i].get<std::string>() : "?";
    if (std::find(supported_required_extensions.begin(), supported_required_extensions.end(), name) ==
        supported_required_extensions.end()) {
      throw SceneError(source.path, indexed("extensionsRequired", i),
                       "unsupported required extension \"" + name + "\" (supported: KHR_lights_punctual)");
    }
  }
}

}  // namespace

void preflight_gltf(const GltfSource& source) {
  check_required_extensions(source);
  check_buffer_views(source, check_buffers(source));
  check_images(source);
}

}  // namespace sg::scene
