#pragma once
// Which skeleton and clip pair a cloth database was made for. A cape is simulated on the poses of
// one run graph, and playback places those character-space capes on whatever the crowd plays: on
// another skeleton, or other clips, the cape floats. The .tsg and .tsc record the pair's identity;
// playback checks it against the crowd's clips and names both when they differ.
#include <cstdint>
#include <string>

#include "anim/default_clips.h"
#include "core/binary_io.h"

namespace throng::secondary {

struct ClipPairIdentity {
  std::string name;           // where the clips came from (ClipPair::description), for messages
  uint32_t jointCount = 0;    // 0: not recorded (files older than the identity: the built-in run)
  uint64_t skeletonHash = 0;  // joint names, parents and rest offsets
  uint64_t clipsHash = 0;     // the prepared clips: frames, rotations, root path, cycle travel
  bool recorded() const { return jointCount != 0; }
  // "NAME (J joints, skeleton HASH, clips HASH)".
  std::string describe() const;
};

// Hashes of the prepared pair: the same files give the same identity in `cloth explore` and in
// the renderer (both prepare them with anim::loadClipPair). Values are rounded to 1e-5 first.
ClipPairIdentity clipPairIdentity(const anim::ClipPair& clips);
// anim::defaultRunPair()'s identity (what files without one were made for).
const ClipPairIdentity& builtInRunIdentity();
// An identity from a skeleton alone (a graph not built from a clip pair: the toy garment).
ClipPairIdentity skeletonIdentity(std::string name, const std::vector<std::string>& jointNames,
                                  const std::vector<int32_t>& parents);

// Chunks 'CLPN' (the name) and 'CLPI' (joint count and hashes).
void addClipIdentityChunks(ChunkWriter& writer, const ClipPairIdentity& identity);
ClipPairIdentity readClipIdentityChunks(const ChunkReader& reader);

// Throws Error naming `file`, what it was made for and what the crowd plays when the database was
// made for another skeleton or other clips (an identity not recorded counts as the built-in run).
void checkClipsMatch(const ClipPairIdentity& made, const std::string& file,
                     const anim::ClipPair& crowdClips);

}  // namespace throng::secondary
