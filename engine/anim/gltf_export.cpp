#include "anim/gltf_export.h"

// Debian builds tinygltf as a shared library (libtinygltf2d): the header only declares it.
#include <tiny_gltf.h>

#include <cstring>
#include <sstream>

#include <glm/gtx/quaternion.hpp>

#include "core/error.h"
#include "core/file_io.h"

namespace throng::anim {
namespace {

using tinygltf::Accessor;
using tinygltf::BufferView;
using tinygltf::Model;

// Appends raw floats/shorts to the one buffer and returns the accessor's index.
struct Packer {
  Model& model;

  int view(const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& blob = model.buffers[0].data;
    while (blob.size() % 4) blob.push_back(0);
    BufferView v;
    v.buffer = 0;
    v.byteOffset = blob.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    blob.insert(blob.end(), p, p + bytes);
    model.bufferViews.push_back(v);
    return int(model.bufferViews.size()) - 1;
  }

  int floats(const std::vector<float>& values, int type, int components, bool bounds,
             int target = 0) {
    Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(float), target);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = type;
    a.count = values.size() / size_t(components);
    if (bounds) {
      a.minValues.assign(size_t(components), 1e30);
      a.maxValues.assign(size_t(components), -1e30);
      for (size_t i = 0; i < values.size(); ++i) {
        a.minValues[i % size_t(components)] =
            std::min(a.minValues[i % size_t(components)], double(values[i]));
        a.maxValues[i % size_t(components)] =
            std::max(a.maxValues[i % size_t(components)], double(values[i]));
      }
    }
    model.accessors.push_back(a);
    return int(model.accessors.size()) - 1;
  }
};

// A bone of length 1 along +y: a narrow double pyramid, widest a fifth of the way up.
int addBoneMesh(Model& model, Packer& pack) {
  const std::vector<float> positions = {0,      0,    0, 0.08f, 0.2f, 0,      0, 0.2f, 0.08f,
                                        -0.08f, 0.2f, 0, 0,     0.2f, -0.08f, 0, 1,    0};
  const std::vector<uint16_t> indices = {0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4,
                                         5, 1, 2, 5, 2, 3, 5, 3, 4, 5, 4, 1};
  Accessor index;
  index.bufferView = pack.view(indices.data(), indices.size() * sizeof(uint16_t),
                               TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  index.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  index.type = TINYGLTF_TYPE_SCALAR;
  index.count = indices.size();
  model.accessors.push_back(index);
  tinygltf::Primitive primitive;
  primitive.indices = int(model.accessors.size()) - 1;
  primitive.attributes["POSITION"] =
      pack.floats(positions, TINYGLTF_TYPE_VEC3, 3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "bone";
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  return int(model.meshes.size()) - 1;
}

std::vector<double> asVector(const glm::vec3& v) {
  return {v.x, v.y, v.z};
}
std::vector<double> asVector(const glm::quat& q) {
  return {q.x, q.y, q.z, q.w};
}

// A child of the parent's node showing the bone from the parent to `offset`.
int addBoneNode(Model& model, int mesh, const glm::vec3& offset) {
  tinygltf::Node node;
  const float length = glm::length(offset);
  node.mesh = mesh;
  node.rotation = asVector(glm::rotation(glm::vec3(0, 1, 0), offset / length));
  node.scale = {length, length, length};
  model.nodes.push_back(node);
  return int(model.nodes.size()) - 1;
}

bool translationVaries(const JointAnimation& a, int joint) {
  for (int f = 1; f < a.frameCount; ++f)
    if (glm::length(a.translation(f, joint) - a.translation(0, joint)) > 1e-6f) return true;
  return false;
}

void addChannel(Model& model, tinygltf::Animation& animation, int node, const char* path, int input,
                int output) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(animation.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(channel);
  (void)model;
}

// The character's joint nodes and its animation channels; returns its root node.
int addCharacter(Model& model, Packer& pack, int boneMesh, int times, const JointAnimation& a,
                 tinygltf::Animation& animation) {
  const int first = int(model.nodes.size());
  const std::vector<bool> placement = a.skeleton.placementJoints();
  for (int j = 0; j < a.jointCount(); ++j) {
    tinygltf::Node node;
    node.name = a.name + "/" + a.skeleton.joints[size_t(j)].name;
    node.translation = asVector(a.translation(0, j));
    node.rotation = asVector(a.rotation(0, j));
    model.nodes.push_back(node);
  }
  for (int j = 0; j < a.jointCount(); ++j) {
    const int p = a.skeleton.joints[size_t(j)].parent;
    if (p < 0) continue;
    model.nodes[size_t(first + p)].children.push_back(first + j);
    if (!placement[size_t(j)] && glm::length(a.translation(0, j)) > 1e-4f) {
      const int bone = addBoneNode(model, boneMesh, a.translation(0, j));  // may grow model.nodes
      model.nodes[size_t(first + p)].children.push_back(bone);
    }
  }
  for (int j = 0; j < a.jointCount(); ++j) {
    std::vector<float> rotations, translations;
    for (int f = 0; f < a.frameCount; ++f) {
      glm::quat q = a.rotation(f, j);
      rotations.insert(rotations.end(), {q.x, q.y, q.z, q.w});
      glm::vec3 t = a.translation(f, j);
      translations.insert(translations.end(), {t.x, t.y, t.z});
    }
    addChannel(model, animation, first + j, "rotation", times,
               pack.floats(rotations, TINYGLTF_TYPE_VEC4, 4, false));
    if (a.skeleton.joints[size_t(j)].parent < 0 || translationVaries(a, j))
      addChannel(model, animation, first + j, "translation", times,
                 pack.floats(translations, TINYGLTF_TYPE_VEC3, 3, false));
  }
  return first;
}

}  // namespace

std::vector<uint8_t> formatGlb(const std::vector<JointAnimation>& characters) {
  if (characters.empty()) fail("glTF export: no characters to write");
  for (const JointAnimation& a : characters)
    if (a.frameCount != characters[0].frameCount || a.frameTime != characters[0].frameTime ||
        a.frameCount < 1)
      fail("glTF export: every character needs the same frame count and frame time");
  Model model;
  model.asset.version = "2.0";
  model.asset.generator = "throng export";
  model.buffers.resize(1);
  Packer pack{model};
  const int boneMesh = addBoneMesh(model, pack);
  std::vector<float> seconds;
  for (int f = 0; f < characters[0].frameCount; ++f)
    seconds.push_back(float(f) * characters[0].frameTime);
  const int times = pack.floats(seconds, TINYGLTF_TYPE_SCALAR, 1, true);
  tinygltf::Animation animation;
  animation.name = "crowd";
  tinygltf::Scene scene;
  for (const JointAnimation& a : characters)
    scene.nodes.push_back(addCharacter(model, pack, boneMesh, times, a, animation));
  model.animations.push_back(animation);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    fail("glTF export: tinygltf could not write the model");
  const std::string bytes = out.str();
  return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

void writeGlb(const std::filesystem::path& path, const std::vector<JointAnimation>& characters) {
  writeFileAtomic(path, formatGlb(characters));
}

}  // namespace throng::anim
