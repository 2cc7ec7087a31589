#include "secondary/clip_identity.h"

#include <cmath>
#include <iomanip>

#include "core/error.h"

namespace throng::secondary {
namespace {
// FNV-1a, 64 bits.
class Hash {
 public:
  void bytes(const void* data, size_t n) {
    const uint8_t* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < n; ++i) value_ = (value_ ^ p[i]) * 0x100000001b3ull;
  }
  void integer(int64_t v) { bytes(&v, sizeof v); }
  void text(const std::string& s) {
    integer(int64_t(s.size()));
    bytes(s.data(), s.size());
  }
  // Rounded to 1e-5, so a last-bit difference of the preparation does not change the identity.
  void real(float v) { integer(std::llround(double(v) * 1e5)); }
  void vec(glm::vec3 v) {
    for (int a = 0; a < 3; ++a) real(v[a]);
  }
  uint64_t value() const { return value_; }

 private:
  uint64_t value_ = 0xcbf29ce484222325ull;
};

void hashClip(Hash& h, const anim::Clip& clip) {
  h.integer(clip.frameCount);
  h.real(clip.frameTime);
  for (const glm::vec4& q : clip.rotations)
    for (int a = 0; a < 4; ++a) h.real(q[a]);
  for (const glm::vec3& p : clip.rootPositions) h.vec(p);
  for (const glm::vec3& p : clip.animatedOffsets) h.vec(p);
  h.vec(clip.cycleTravel);
}

struct IdentityRecord {
  uint32_t jointCount, reserved;
  uint64_t skeletonHash, clipsHash;
};
static_assert(sizeof(IdentityRecord) == 24);

std::string hex(uint64_t v) {
  return concat(std::hex, std::setw(16), std::setfill('0'), v);
}
}  // namespace

std::string ClipPairIdentity::describe() const {
  return concat("'", name, "' (", jointCount, " joints, skeleton ", hex(skeletonHash), ", clips ",
                hex(clipsHash), ")");
}

ClipPairIdentity clipPairIdentity(const anim::ClipPair& clips) {
  const anim::Skeleton& skeleton = clips.slow.skeleton;
  Hash s;
  s.integer(skeleton.jointCount());
  for (const anim::Joint& joint : skeleton.joints) {
    s.text(joint.name);
    s.integer(joint.parent);
    s.vec(joint.offset);
  }
  Hash c;
  hashClip(c, clips.slow);
  hashClip(c, clips.fast);
  return {clips.description, uint32_t(skeleton.jointCount()), s.value(), c.value()};
}

const ClipPairIdentity& builtInRunIdentity() {
  static const ClipPairIdentity identity = clipPairIdentity(anim::defaultRunPair());
  return identity;
}

ClipPairIdentity skeletonIdentity(std::string name, const std::vector<std::string>& jointNames,
                                  const std::vector<int32_t>& parents) {
  Hash s;
  s.integer(int64_t(jointNames.size()));
  for (size_t j = 0; j < jointNames.size(); ++j) {
    s.text(jointNames[j]);
    s.integer(j < parents.size() ? parents[j] : -2);
  }
  return {std::move(name), uint32_t(jointNames.size()), s.value(), 0};
}

void addClipIdentityChunks(ChunkWriter& w, const ClipPairIdentity& id) {
  if (!id.recorded()) fail("clip identity of '", id.name, "': no joints");
  w.addString("CLPN", id.name);
  w.addScalar("CLPI", IdentityRecord{id.jointCount, 0u, id.skeletonHash, id.clipsHash});
}

ClipPairIdentity readClipIdentityChunks(const ChunkReader& r) {
  const IdentityRecord record = r.scalar<IdentityRecord>("CLPI");
  if (record.jointCount == 0) fail(r.name(), ": the clip identity has no joints");
  return {r.string("CLPN"), record.jointCount, record.skeletonHash, record.clipsHash};
}

void checkClipsMatch(const ClipPairIdentity& made, const std::string& file,
                     const anim::ClipPair& crowdClips) {
  const ClipPairIdentity& m = made.recorded() ? made : builtInRunIdentity();
  const ClipPairIdentity crowd = clipPairIdentity(crowdClips);
  if (m.jointCount != crowd.jointCount || m.skeletonHash != crowd.skeletonHash)
    fail(file, ": the capes were made for another skeleton: ", m.describe(),
         ", but the crowd plays ", crowd.describe(),
         " (explore the cape on these clips: throng cloth explore --slow … --fast …)");
  if (m.clipsHash != crowd.clipsHash)
    fail(file, ": the capes were made for other clips on this skeleton: ", m.describe(),
         ", but the crowd plays ", crowd.describe(),
         " (explore the cape on these clips: throng cloth explore --slow … --fast …)");
}

}  // namespace throng::secondary
