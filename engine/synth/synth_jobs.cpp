#include "synth/synth_jobs.h"

#include "core/error.h"
#include "synth/gpu_types.h"

namespace throng::synth {

void throwIfInvalid(const std::string& job, const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  std::string message = job + " is invalid:";
  for (const std::string& p : problems) message += "\n  - " + p;
  throw Error(message);
}

SynthPrograms::SynthPrograms(const gpu::Context& context)
    : rootMotion(context, "root_motion.comp"), pose(context, "synth_pose.comp") {}

std::vector<std::string> RootMotionJob::validate() const {
  std::vector<std::string> problems;
  if (!motion) problems.push_back("input 'motion' (GPU motion textures) is missing");
  if (!clips) problems.push_back("input 'clips' (motion pair) is missing");
  if (!crowd) problems.push_back("input/output 'crowd' buffers are missing");
  if (crowd && (!crowd->placement || !crowd->motion)) problems.push_back("crowd buffers are not allocated");
  if (!(dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", dt));
  if (clips && (clips->slow.duration() <= 0.0f || clips->fast.duration() <= 0.0f))
    problems.push_back("clip durations must be positive");
  return problems;
}

void RootMotionJob::record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const {
  throwIfInvalid("RootMotionJob", validate());
  RootMotionPush push{};
  push.characterCount = crowd->count;
  push.slowFrames = static_cast<uint32_t>(clips->slow.frameCount);
  push.fastFrames = static_cast<uint32_t>(clips->fast.frameCount);
  push.steering = static_cast<uint32_t>(steering);
  push.dt = dt;
  push.slowDuration = clips->slow.duration();
  push.fastDuration = clips->fast.duration();
  push.slowCycleTravel = glm::vec4(clips->slow.cycleTravel, 0.0f);
  push.fastCycleTravel = glm::vec4(clips->fast.cycleTravel, 0.0f);
  gpu::Binding bindings[] = {
      gpu::sampledImageBinding(0, motion->slow.view(), motion->sampler),
      gpu::sampledImageBinding(1, motion->fast.view(), motion->sampler),
      gpu::storageBinding(2, crowd->placement),
      gpu::storageBinding(3, crowd->motion),
  };
  gpu::dispatch(cmd, program, bindings, push, crowd->count);
}

std::vector<std::string> PoseJob::validate() const {
  std::vector<std::string> problems;
  if (!motion) problems.push_back("input 'motion' (GPU motion textures) is missing");
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!joints || !*joints) problems.push_back("output 'joints' buffer is missing");
  if (motion && crowd && joints && *joints) {
    if (firstCharacter > crowd->count) problems.push_back("firstCharacter is past the end of the crowd");
    uint32_t count = characterCount ? characterCount : crowd->count - std::min(firstCharacter, crowd->count);
    if (firstCharacter + count > crowd->count) problems.push_back("chunk runs past the end of the crowd");
    VkDeviceSize need = VkDeviceSize(count) * motion->jointCount * sizeof(JointMatrix);
    if (jointsOffset + need > joints->size())
      problems.push_back(concat("output 'joints' holds ", joints->size(), " bytes, the chunk needs ", need,
                                " at offset ", jointsOffset));
  }
  return problems;
}

void PoseJob::record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const {
  throwIfInvalid("PoseJob", validate());
  uint32_t count = characterCount ? characterCount : crowd->count - firstCharacter;
  PosePush push{};
  push.characterCount = count;
  push.jointCount = motion->jointCount;
  push.slowFrames = motion->slowFrames;
  push.fastFrames = motion->fastFrames;
  push.firstCharacter = firstCharacter;
  VkDeviceSize bytes = VkDeviceSize(count) * motion->jointCount * sizeof(JointMatrix);
  gpu::Binding bindings[] = {
      gpu::sampledImageBinding(0, motion->slow.view(), motion->sampler),
      gpu::sampledImageBinding(1, motion->fast.view(), motion->sampler),
      gpu::storageBinding(2, motion->parents),
      gpu::storageBinding(3, motion->jointRadius),
      gpu::storageBinding(4, crowd->placement),
      gpu::storageBinding(5, crowd->motion),
      gpu::storageBinding(6, *joints, jointsOffset, bytes),
  };
  gpu::dispatch(cmd, program, bindings, push, count);
}

}  // namespace throng::synth
