#pragma once
// A parametric gait: the project's own clip pairs (assets/*.bvh), generated instead of
// captured so that they carry no third-party licence: slow and fast run, slow and fast walk,
// standing idle and talking (zero travel), a slow and a fast forward hop (both feet together).
//
// Skeleton (25 joints, metres, Y up, facing and travelling along +z, rest pose standing with
// the arms hanging down, about 1.75 m tall):
//   Hips (root) ─ Spine ─ Spine1 ─ Spine2 ─ Spine3 ─ Neck ─ Head [End Site: top of head]
//                                            ├─ LeftShoulder ─ LeftArm ─ LeftForeArm ─ LeftHand
//                                            │                  ─ LeftHandIndex [End Site]
//                                            └─ RightShoulder ─ … ─ RightHandIndex [End Site]
//   Hips ─ LeftUpLeg ─ LeftLeg ─ LeftFoot ─ LeftToeBase [End Site: toe tip]
//   Hips ─ RightUpLeg ─ RightLeg ─ RightFoot ─ RightToeBase [End Site]
// Elbows are LeftForeArm/RightForeArm, knees LeftLeg/RightLeg, mid-spine Spine1, ankles
// LeftFoot/RightFoot, the balls of the feet LeftToeBase/RightToeBase.
// Channels: Hips "Xposition Yposition Zposition Zrotation Xrotation Yrotation", every other
// joint "Zrotation Xrotation Yrotation" (BVH: R = Rz * Rx * Ry), angles in degrees.
//
// Phase 0 is the left foot's touchdown; the right foot lands at phase 0.5. The root moves at
// the target speed (with a small dip at each mid-stance) and bobs twice per cycle. While a
// foot is planted its leg is solved by inverse kinematics so that the ball of the foot stays
// exactly where it landed (no skate); in the air it follows a curve through the swing keys
// that starts and ends on the solved toe-off and touchdown angles and rates (C1, no pop).
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"

namespace throng::anim {

// Alternate: the feet take turns (a run with a flight phase when the stance is under half a
// cycle, a walk with double support when over). Hop: both feet land and take off together,
// one hop per cycle. Stand: both feet stay planted; the arms gesture.
enum class GaitKind { Alternate, Hop, Stand };

// One key of a periodic curve: phase in [0, 1), value in degrees.
struct GaitKey {
  double phase = 0.0;
  double degrees = 0.0;
};

struct GaitParams {
  std::string name;     // "run_slow": the clip's sourceName is name + ".bvh"
  GaitKind kind = GaitKind::Alternate;
  int cycleFrames = 0;  // one cycle = two steps, an exact number of frames
  double frameTime = 1.0 / 30.0;
  double stanceFraction = 0.0;  // of a cycle, per foot; the rest of each step is flight
  double speed = 0.0;           // m/s, mean forward speed of the root
  double speedDip = 0.0;        // relative slow-down of the root at each mid-stance
  double rootHeight = 0.0;      // mean height of the root (Hips), metres
  double bob = 0.0;             // vertical amplitude: lowest at mid-stance (negative: highest, a walk)
  double sway = 0.0;            // lateral amplitude, towards the planted foot
  double reach = 0.0;           // share of the stance travel the ball lands ahead of the root
  double stanceWidth = 0.0;     // |x| of a planted ball of foot
  // The left leg in the air, keyed by phase in (stanceFraction, 1); the right leg is the
  // mirror, half a cycle later. While planted the leg is solved; these keys shape the swing
  // between the solved toe-off and touchdown poses.
  std::vector<GaitKey> swingHip;   // thigh angle from vertical, + forward
  std::vector<GaitKey> swingKnee;  // + flexed
  double swingAdduction = 0.0;     // at mid-swing, + towards the midline
  // Periodic over the whole cycle:
  std::vector<GaitKey> swingAnkle;  // plantarflexion while the foot is off the ground
  std::vector<GaitKey> footPitch;   // heel-up angle of the planted foot, world frame
  double trunkLean = 0.0;           // forward lean of the chest from vertical
  double pelvisTilt = 0.0;          // mean anterior tilt of the pelvis
  double bounceTilt = 0.0;          // trunk flexion at mid-stance (twice per cycle)
  double pelvisYaw = 0.0;           // amplitude; a hip is furthest forward at its touchdown
  double pelvisRoll = 0.0;          // amplitude; the swing side drops during stance
  double thoraxYaw = 0.0;           // amplitude of the chest's counter-rotation
  double shoulderMean = 0.0;        // mean arm flexion (negative: behind the body)
  double shoulderSwing = 0.0;       // amplitude of arm flexion, opposite to the same leg
  double elbowMean = 0.0;           // mean elbow flexion
  double elbowSwing = 0.0;          // extra flexion when the arm is forward
  double armAbduction = 0.0;
  // Stand: the balls of the feet this far ahead of the root; gestures of the arms (beats per
  // cycle, how far each arm rises and how much the elbow bends and opens), head nods.
  double footForward = 0.0;
  int gestureBeats = 0;
  double gestureRaise = 0.0;
  double gestureElbow = 0.0;
  double headNod = 0.0;
};

GaitParams slowRunGait();   // ≈ 2.5 m/s, 2.6 steps/s
GaitParams fastRunGait();   // ≈ 4.5 m/s, 3.0 steps/s, longer stride, more lean
GaitParams slowWalkGait();  // ≈ 1.0 m/s, 1.8 steps/s
GaitParams fastWalkGait();  // ≈ 1.6 m/s, 2.3 steps/s
GaitParams idleGait();      // standing, weight shift, arms at rest, no travel
GaitParams talkGait();      // standing, arm gestures and nods, no travel
GaitParams slowHopGait();   // forward hops with both feet, ≈ 0.8 m/s
GaitParams fastHopGait();   // ≈ 1.6 m/s, higher and longer
// Every generated clip, in pairs (slow, fast): run, walk, talk (idle, talk), jump (hops).
std::vector<GaitParams> allGaits();

Skeleton gaitSkeleton();

// Channel values (BVH order, degrees and metres) at a continuous phase; phase 1 is phase 0
// moved forward by gaitCycleTravel().
std::vector<double> gaitPose(const GaitParams& params, double phase);
// Frame `frame` of the cycle; any integer: frame + cycleFrames is the next cycle's frame.
std::vector<double> gaitFrame(const GaitParams& params, int frame);
// Root displacement over one cycle (two steps), along +z.
double gaitCycleTravel(const GaitParams& params);
// One cycle as a clip: cycleFrames frames, sourceName = name + ".bvh".
RawClip generateGait(const GaitParams& params);

// World positions of every joint for one frame of channel values, with BVH semantics (root
// position channels add to the root offset; rotation channels compose in listed order).
std::vector<glm::dvec3> forwardKinematics(const Skeleton& skeleton,
                                          std::span<const double> channelValues);
std::vector<glm::dvec3> forwardKinematics(const Skeleton& skeleton,
                                          std::span<const float> channelValues);

}  // namespace throng::anim
