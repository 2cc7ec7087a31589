// BVH writer. The output must be byte-for-byte reproducible (the committed assets are
// checked against a fresh generation), so numbers go through std::to_chars, which ignores
// the C locale, with a fixed number of decimals.
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "anim/bvh.h"
#include "anim/bvh_channels.h"
#include "core/error.h"

namespace throng::anim {
namespace {

constexpr int kDecimals = 6;

void appendFixed(std::string& out, float value) {
  char buffer[64];
  auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, kDecimals);
  if (ec != std::errc()) fail("formatBvh: cannot format the value ", value);
  std::string_view text(buffer, size_t(end - buffer));
  // A tiny negative value would print as "-0.000000"; one spelling of zero keeps diffs quiet.
  if (text.find_first_not_of("-0.") == std::string_view::npos) text = "0.000000";
  out += text;
}

void appendVector(std::string& out, glm::vec3 v) {
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    appendFixed(out, v[i]);
  }
}

bool isValidName(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name) {
    if (c <= ' ' || c == '{' || c == '}' || c == 0x7f) return false;
  }
  return true;
}

struct Writer {
  const RawClip& clip;
  std::vector<std::vector<int>> children;
  std::vector<int> order;  // joints in the order they are written (depth first)
  std::string out;

  void writeJoint(int j, int depth) {
    const Joint& joint = clip.skeleton.joints[size_t(j)];
    const std::string indent(size_t(depth), '\t');
    out += indent;
    out += depth == 0 ? "ROOT " : "JOINT ";
    out += joint.name;
    out += '\n' + indent + "{\n" + indent + "\tOFFSET";
    appendVector(out, joint.offset);
    out += '\n' + indent + "\tCHANNELS " + std::to_string(joint.channels.size());
    for (Channel c : joint.channels) {
      out += ' ';
      out += channelName(c);
    }
    out += '\n';
    order.push_back(j);
    for (int child : children[size_t(j)]) writeJoint(child, depth + 1);
    if (joint.endSite) {
      out += indent + "\tEnd Site\n" + indent + "\t{\n" + indent + "\t\tOFFSET";
      appendVector(out, *joint.endSite);
      out += '\n' + indent + "\t}\n";
    }
    out += indent + "}\n";
  }
};

}  // namespace

std::string formatBvh(const RawClip& clip) {
  const Skeleton& skeleton = clip.skeleton;
  const int jointCount = skeleton.jointCount();
  if (jointCount == 0) fail(clip.sourceName, ": formatBvh: expected at least one joint");
  Writer writer{clip, std::vector<std::vector<int>>(size_t(jointCount)), {}, {}};
  std::vector<int> firstChannel(size_t(jointCount), 0);
  int channelCount = 0;
  for (int j = 0; j < jointCount; ++j) {
    const Joint& joint = skeleton.joints[size_t(j)];
    if (!isValidName(joint.name)) {
      fail(clip.sourceName, ": formatBvh: joint ", j, " needs a name without spaces or braces");
    }
    if ((j == 0) != (joint.parent == -1) || joint.parent >= j || joint.parent < -1) {
      fail(clip.sourceName, ": formatBvh: joint '", joint.name, "' has parent ", joint.parent,
           ", expected one root first and parents before their children");
    }
    if (j > 0) writer.children[size_t(joint.parent)].push_back(j);
    firstChannel[size_t(j)] = channelCount;
    channelCount += int(joint.channels.size());
  }
  if (clip.frameCount < 0 || channelCount != clip.channelCount ||
      clip.values.size() != size_t(clip.frameCount) * size_t(channelCount)) {
    fail(clip.sourceName, ": formatBvh: expected ", clip.frameCount, " frames x ", channelCount,
         " channels of values, found ", clip.values.size(), " (channelCount ", clip.channelCount,
         ")");
  }
  if (!(clip.frameTime > 0.0f) || !std::isfinite(clip.frameTime)) {
    fail(clip.sourceName, ": formatBvh: expected a positive frame time, found ", clip.frameTime);
  }
  for (size_t i = 0; i < clip.values.size(); ++i) {
    if (!std::isfinite(clip.values[i])) {
      fail(clip.sourceName, ": formatBvh: value ", i % size_t(channelCount), " of frame ",
           i / size_t(channelCount), " is not finite");
    }
  }

  writer.out = "HIERARCHY\n";
  writer.writeJoint(0, 0);
  std::string& out = writer.out;
  out += "MOTION\nFrames: " + std::to_string(clip.frameCount) + "\nFrame Time: ";
  // Shortest text that reads back as the same float: 1/30 stays exactly 1/30 in float.
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, clip.frameTime);
  if (ec != std::errc()) fail(clip.sourceName, ": formatBvh: cannot format the frame time");
  out.append(buffer, end);
  out += '\n';
  for (int f = 0; f < clip.frameCount; ++f) {
    const float* frame = clip.values.data() + size_t(f) * size_t(channelCount);
    bool first = true;
    // Values follow the written (depth-first) joint order, which may differ from storage order.
    for (int j : writer.order) {
      for (size_t c = 0; c < skeleton.joints[size_t(j)].channels.size(); ++c) {
        if (!first) out += ' ';
        first = false;
        appendFixed(out, frame[firstChannel[size_t(j)] + int(c)]);
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace throng::anim
