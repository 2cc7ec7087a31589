// The gaits: the root follows a designed path; the upper body and arms follow periodic
// curves; each leg is solved by inverse kinematics while its foot is planted and follows swing
// keys in the air (an alternating run or walk, a two-footed hop, or planted throughout when
// standing). Everything is computed in double and rounded to float only
// when stored, so a last-bit difference in a libm call almost never changes the BVH text.
#include "anim/gait.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace throng::anim {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPiD;
// Height of the ball-of-foot joint above the ground when the foot is planted (rest pose).
constexpr double kBallHeight = 0.03;

// clang-format off
enum JointIndex : int {
  kHips, kSpine, kSpine1, kSpine2, kSpine3, kNeck, kHead,
  kLeftShoulder, kLeftArm, kLeftForeArm, kLeftHand, kLeftHandIndex,
  kRightShoulder, kRightArm, kRightForeArm, kRightHand, kRightHandIndex,
  kLeftUpLeg, kLeftLeg, kLeftFoot, kLeftToeBase,
  kRightUpLeg, kRightLeg, kRightFoot, kRightToeBase,
  kJointCount
};
// clang-format on
constexpr int kRootChannels = 6;
constexpr int kChannelCount = kRootChannels + 3 * (kJointCount - 1);

// Index of joint j's first rotation channel (Z X Y order); the root's positions are 0..2.
int rotationChannel(int joint) {
  return joint == 0 ? 3 : kRootChannels + 3 * (joint - 1);
}

void setRotation(std::vector<double>& pose, int joint, double x, double y, double z) {
  int c = rotationChannel(joint);
  pose[size_t(c)] = z;
  pose[size_t(c) + 1] = x;
  pose[size_t(c) + 2] = y;
}

double wrapPhase(double phase) {
  return phase - std::floor(phase);
}

// Periodic cubic (Catmull-Rom with non-uniform spacing) through the keys: C1 everywhere,
// so the cycle's seam is as smooth as its middle.
double periodicCurve(const std::vector<GaitKey>& keys, double phase) {
  const int n = int(keys.size());
  THRONG_CHECK(n >= 3, "a gait curve needs at least three keys");
  auto keyAt = [&](int i) {
    int k = ((i % n) + n) % n;
    double wraps = std::floor(double(i) / n);
    return GaitKey{keys[size_t(k)].phase + wraps, keys[size_t(k)].degrees};
  };
  double u = wrapPhase(phase);
  int i = n - 1;  // segment [key i, key i+1] holds u; before the first key it wraps back
  for (int k = 0; k < n; ++k) {
    if (keys[size_t(k)].phase <= u) i = k;
  }
  if (u < keys[0].phase) u += 1.0;
  GaitKey k0 = keyAt(i - 1), k1 = keyAt(i), k2 = keyAt(i + 1), k3 = keyAt(i + 2);
  double h = k2.phase - k1.phase;
  THRONG_CHECK(h > 0.0, "gait keys must have increasing phases in [0, 1)");
  double m1 = (k2.degrees - k0.degrees) / (k2.phase - k0.phase) * h;
  double m2 = (k3.degrees - k1.degrees) / (k3.phase - k1.phase) * h;
  double s = (u - k1.phase) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * k1.degrees + (s3 - 2 * s2 + s) * m1 +
         (-2 * s3 + 3 * s2) * k2.degrees + (s3 - s2) * m2;
}

double smoothstep(double a, double b, double x) {
  double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Steps per cycle: two alternating feet, one hop, none standing.
int stepsPerCycle(const GaitParams& p) {
  return p.kind == GaitKind::Alternate ? 2 : p.kind == GaitKind::Hop ? 1 : 0;
}

// 1 while the foot is planted, 0 in mid-swing; the changes happen in the air, where the foot
// is free to move.
double stanceWeight(const GaitParams& p, double u) {
  if (p.kind == GaitKind::Stand) return 1.0;
  u = wrapPhase(u);
  const double s = p.stanceFraction;
  if (u <= s) return 1.0;
  return std::max(1.0 - smoothstep(s, s + 0.12, u), smoothstep(0.9, 1.0, u));
}

struct LegAngles {
  double thigh = 0.0;      // flexion from vertical, + forward
  double adduction = 0.0;  // + towards the midline
  double knee = 0.0;       // + flexed
};

LegAngles operator+(LegAngles a, LegAngles b) {
  return {a.thigh + b.thigh, a.adduction + b.adduction, a.knee + b.knee};
}
LegAngles operator-(LegAngles a, LegAngles b) {
  return {a.thigh - b.thigh, a.adduction - b.adduction, a.knee - b.knee};
}
LegAngles operator*(double k, LegAngles a) {
  return {k * a.thigh, k * a.adduction, k * a.knee};
}

// A guess for the solver: the thigh sweeps back through the stance, the knee bent.
LegAngles stanceSeed(const GaitParams& p, double u) {
  if (p.kind == GaitKind::Stand) return {0.0, 3.0, 10.0};
  return {25.0 - 45.0 * u / p.stanceFraction, 3.0, 35.0};
}

// Cubic through the swing keys that leaves toe-off with the solved angle and rate and
// arrives at touchdown the same way (C1 through both contacts). Rates per unit phase.
double swingCurve(const std::vector<GaitKey>& keys, GaitKey start, double startRate, GaitKey end,
                  double endRate, double u) {
  std::vector<GaitKey> knots;
  knots.reserve(keys.size() + 2);
  knots.push_back(start);
  for (const GaitKey& k : keys) {
    THRONG_CHECK(k.phase > knots.back().phase && k.phase < end.phase,
                 "swing keys must increase strictly between toe-off and touchdown");
    knots.push_back(k);
  }
  knots.push_back(end);
  size_t i = 0;
  while (i + 2 < knots.size() && u > knots[i + 1].phase) ++i;
  auto rate = [&](size_t k) {
    if (k == 0) return startRate;
    if (k + 1 == knots.size()) return endRate;
    return (knots[k + 1].degrees - knots[k - 1].degrees) /
           (knots[k + 1].phase - knots[k - 1].phase);
  };
  const GaitKey a = knots[i], b = knots[i + 1];
  const double h = b.phase - a.phase, x = (u - a.phase) / h, x2 = x * x, x3 = x2 * x;
  return (2 * x3 - 3 * x2 + 1) * a.degrees + (x3 - 2 * x2 + x) * h * rate(i) +
         (-2 * x3 + 3 * x2) * b.degrees + (x3 - x2) * h * rate(i + 1);
}

// Writes one leg; `side` is +1 left, -1 right (the mirror negates Y and Z rotations).
void poseLeg(const GaitParams& p, std::vector<double>& pose, int upLeg, double side, double u,
             LegAngles leg) {
  const double pelvisPitch = pose[size_t(rotationChannel(kHips)) + 1];
  const double w = stanceWeight(p, u);
  const double pitch = periodicCurve(p.footPitch, u);
  // Planted: the ankle keeps the foot at the designed pitch against the ground whatever the
  // hip and knee do; in the air it follows its own curve.
  const double ankle =
      w * (pitch + leg.thigh - leg.knee) + (1.0 - w) * periodicCurve(p.swingAnkle, u);
  setRotation(pose, upLeg, -leg.thigh - pelvisPitch, side * 2.0, side * -leg.adduction);
  setRotation(pose, upLeg + 1, leg.knee, 0.0, 0.0);
  setRotation(pose, upLeg + 2, ankle, 0.0, 0.0);
  // The toes stay flat on the ground while the heel rises.
  setRotation(pose, upLeg + 3, -0.8 * w * std::max(pitch, 0.0), 0.0, 0.0);
}

// One arm; it swings against the leg of the same side, so `u` is that leg's phase.
void poseArm(const GaitParams& p, std::vector<double>& pose, int shoulder, double side, double u,
             double chestPitch) {
  // Forward-most when the same-side hip is furthest back, just after its toe-off.
  const double swing = std::cos(kTwoPi * (u - p.stanceFraction - 0.05));
  const double flexion = p.shoulderMean + p.shoulderSwing * swing;
  const double elbow = p.elbowMean + p.elbowSwing * swing;
  setRotation(pose, shoulder, 0.0, side * -3.0 * swing, 0.0);
  // Internal rotation turns the bent forearm towards the body's midline.
  setRotation(pose, shoulder + 1, -flexion - chestPitch, side * -15.0, side * p.armAbduction);
  setRotation(pose, shoulder + 2, -elbow, 0.0, 0.0);
  setRotation(pose, shoulder + 3, -10.0, 0.0, side * -5.0);
  setRotation(pose, shoulder + 4, 0.0, 0.0, side * -30.0);  // loosely curled fingers
}

// A standing character's arm: gestures that rise and fall `gestureBeats` times a cycle, the
// elbow bending as the arm rises; the two arms out of step.
void gestureArm(const GaitParams& p, std::vector<double>& pose, int shoulder, double side, double t,
                double chestPitch) {
  const double phase = kTwoPi * (p.gestureBeats * t + (side > 0.0 ? 0.0 : 0.37));
  const double rise = 0.5 + 0.5 * std::sin(phase);
  const double flexion = p.shoulderMean + p.gestureRaise * rise;
  const double elbow = p.elbowMean + p.gestureElbow * (0.5 + 0.5 * std::sin(phase + 0.9));
  setRotation(pose, shoulder, 0.0, 0.0, side * 2.0 * rise);
  setRotation(pose, shoulder + 1, -flexion - chestPitch, side * -(15.0 + 20.0 * rise),
              side * (p.armAbduction + 10.0 * rise));
  setRotation(pose, shoulder + 2, -elbow, side * -20.0 * rise, 0.0);
  setRotation(pose, shoulder + 3, -10.0 - 15.0 * rise, 0.0, side * -5.0);
  setRotation(pose, shoulder + 4, 0.0, 0.0, side * -30.0 * (1.0 - 0.6 * rise));  // fingers open as it rises
}

// The root's path at absolute phase t (any real; one cycle further is a cycle's travel further).
glm::dvec3 rootPosition(const GaitParams& p, double t) {
  if (p.kind == GaitKind::Stand) {  // a slow weight shift from foot to foot, dipping as it passes
    return {p.sway * std::sin(kTwoPi * t), p.rootHeight - p.bob * std::cos(2.0 * kTwoPi * t), 0.0};
  }
  const double s = p.stanceFraction;
  const double steps = stepsPerCycle(p);
  const double cycleTravel = p.speed * p.cycleFrames * p.frameTime;
  const double twice = steps * kTwoPi * (t - 0.5 * s);  // 0 at each mid-stance
  const double sway = p.kind == GaitKind::Alternate ? p.sway * std::cos(kTwoPi * (t - 0.5 * s)) : 0.0;
  return {sway, p.rootHeight - p.bob * std::cos(twice),
          cycleTravel * (t - p.speedDip / (steps * kTwoPi) * std::sin(twice))};
}

// Pelvis, spine, head and arms at phase t, with the root in place; legs not yet set.
std::vector<double> upperPose(const GaitParams& p, double t) {
  std::vector<double> pose(size_t(kChannelCount), 0.0);
  const double s = p.stanceFraction;
  const double twist = std::cos(kTwoPi * (t + 0.03));  // +1 just before left touchdown
  const double midStance = std::cos(stepsPerCycle(p) * kTwoPi * (t - 0.5 * s));  // +1 at each mid-stance
  const double pelvisPitch = p.pelvisTilt + 0.25 * p.bounceTilt * midStance;
  const double pelvisYaw = -p.pelvisYaw * twist;  // negative: the left hip forward
  const double pelvisRoll = p.pelvisRoll * std::cos(kTwoPi * (t - 0.5 * s));
  glm::dvec3 root = rootPosition(p, t);
  for (int i = 0; i < 3; ++i) pose[size_t(i)] = root[i];
  setRotation(pose, kHips, pelvisPitch, pelvisYaw, pelvisRoll);

  // The chest leans by trunkLean, flexes a little more as each foot takes the load, and
  // turns against the pelvis (right shoulder forward when the left leg is forward).
  const double chestPitch = p.trunkLean + p.bounceTilt * (0.5 + 0.5 * midStance);
  const double chestYaw = p.thoraxYaw * twist;
  const double spineX = chestPitch - pelvisPitch, spineY = chestYaw - pelvisYaw;
  const double spineZ = -0.7 * pelvisRoll;
  const double weights[4] = {0.2, 0.3, 0.3, 0.2};
  for (int i = 0; i < 4; ++i) {
    setRotation(pose, kSpine + i, weights[i] * spineX, weights[i] * spineY, weights[i] * spineZ);
  }
  // The head looks ahead and stays square to the direction of travel.
  const double residualRoll = pelvisRoll + spineZ;
  setRotation(pose, kNeck, -0.5 * chestPitch, -0.5 * chestYaw, -0.5 * residualRoll);
  setRotation(pose, kHead, -0.4 * chestPitch, -0.5 * chestYaw, -0.5 * residualRoll);
  if (p.headNod != 0.0) {  // two nods per gesture
    const double nod = p.headNod * std::sin(kTwoPi * (2.0 * p.gestureBeats * t + 0.2));
    setRotation(pose, kNeck, -0.5 * chestPitch + 0.4 * nod, -0.5 * chestYaw, -0.5 * residualRoll);
    setRotation(pose, kHead, -0.4 * chestPitch + 0.6 * nod, -0.5 * chestYaw, -0.5 * residualRoll);
  }
  if (p.kind == GaitKind::Stand) {
    gestureArm(p, pose, kLeftShoulder, 1.0, t, chestPitch);
    gestureArm(p, pose, kRightShoulder, -1.0, t, chestPitch);
  } else {
    // Alternating feet: each arm swings against its leg; a hop: both arms swing together.
    poseArm(p, pose, kLeftShoulder, 1.0, t, chestPitch);
    poseArm(p, pose, kRightShoulder, -1.0, p.kind == GaitKind::Hop ? t : t - 0.5, chestPitch);
  }
  return pose;
}

struct LegSide {
  int upLeg = 0;
  int ball = 0;
  double side = 1.0;    // +1 left, -1 right
  double offset = 0.0;  // phase of its first touchdown
};
const LegSide kLeft{kLeftUpLeg, kLeftToeBase, 1.0, 0.0};
const LegSide kRight{kRightUpLeg, kRightToeBase, -1.0, 0.5};
const LegSide kRightHop{kRightUpLeg, kRightToeBase, -1.0, 0.0};

LegSide rightLeg(const GaitParams& p) { return p.kind == GaitKind::Alternate ? kRight : kRightHop; }

// Stance number n of the alternating feet (even: left, odd: right; stance n starts at phase n/2).
int alternateStance(const LegSide& leg, int k) { return 2 * k + (leg.side > 0 ? 0 : 1); }

// Where the ball of foot of `leg` lands at its touchdown number k (the one at phase
// k + leg.offset): alternate feet land half a cycle's travel apart, hops a whole one.
glm::dvec3 contactPoint(const GaitParams& p, const LegSide& leg, int k) {
  if (p.kind == GaitKind::Stand) return {leg.side * p.stanceWidth, kBallHeight, p.footForward};
  const double s = p.stanceFraction;
  const double cycleTravel = p.speed * p.cycleFrames * p.frameTime;
  const double start = rootPosition(p, 0.0).z;
  const double landing = start + p.reach * (rootPosition(p, s).z - start);
  if (p.kind == GaitKind::Hop) return {leg.side * p.stanceWidth, kBallHeight, landing + k * cycleTravel};
  const double step = 0.5 * p.speed * p.cycleFrames * p.frameTime;
  return {leg.side * p.stanceWidth, kBallHeight, landing + alternateStance(leg, k) * step};
}

glm::dvec3 ballPosition(const GaitParams& p, const Skeleton& skeleton, const LegSide& leg, double t,
                        LegAngles angles) {
  std::vector<double> pose = upperPose(p, t);
  poseLeg(p, pose, leg.upLeg, leg.side, t - leg.offset, angles);
  return forwardKinematics(skeleton, std::span<const double>(pose))[size_t(leg.ball)];
}

// Damped Gauss-Newton on the leg's three angles so that its ball of foot reaches `target`;
// the damping and the knee limit keep an out-of-reach target from throwing the leg around
// (the tests then see the foot miss its contact). A fixed iteration count keeps the result,
// and so the generated file, reproducible.
LegAngles solveLeg(const GaitParams& p, const Skeleton& skeleton, const LegSide& leg, double t,
                   int touchdown) {
  const glm::dvec3 target = contactPoint(p, leg, touchdown);
  LegAngles a = stanceSeed(p, p.kind == GaitKind::Alternate ? t - 0.5 * alternateStance(leg, touchdown) : t - touchdown);
  constexpr double kStep = 1e-4;     // degrees, for the finite-difference Jacobian
  constexpr double kDamping = 1e-8;  // (m/deg)^2: negligible unless the leg is straight
  for (int iteration = 0; iteration < 16; ++iteration) {
    glm::dvec3 ball = ballPosition(p, skeleton, leg, t, a);
    glm::dmat3 jacobian;
    for (int k = 0; k < 3; ++k) {
      LegAngles d;
      (k == 0 ? d.thigh : k == 1 ? d.adduction : d.knee) = kStep;
      jacobian[k] = (ballPosition(p, skeleton, leg, t, a + d) - ball) / kStep;
    }
    glm::dmat3 jt = glm::transpose(jacobian);
    glm::dvec3 delta = glm::inverse(jt * jacobian + glm::dmat3(kDamping)) * (jt * (target - ball));
    double largest = std::max({std::abs(delta.x), std::abs(delta.y), std::abs(delta.z)});
    if (largest > 10.0) delta *= 10.0 / largest;  // degrees per iteration
    a = a + LegAngles{delta.x, delta.y, delta.z};
    a.knee = std::clamp(a.knee, 0.0, 150.0);
  }
  return a;
}

// The leg at absolute phase t: solved while planted, and in the air a curve through the
// swing keys that joins the solved toe-off and next touchdown without a jump in angle or rate.
LegAngles legAngles(const GaitParams& p, const Skeleton& skeleton, const LegSide& leg, double t) {
  if (p.kind == GaitKind::Stand) return solveLeg(p, skeleton, leg, t, 0);
  const double s = p.stanceFraction;
  const double local = t - leg.offset;
  const double touchdown = std::floor(local);
  const double u = local - touchdown;
  const int stance = int(touchdown);
  const double t0 = touchdown + leg.offset;  // absolute phase of this stance's touchdown
  if (u <= s) return solveLeg(p, skeleton, leg, t, stance);

  constexpr double h = 1e-5;
  auto solved = [&](double e, int n) { return solveLeg(p, skeleton, leg, t0 + e, n); };
  const LegAngles off = solved(s, stance);
  const LegAngles offRate = (0.5 / h) * (solved(s + h, stance) - solved(s - h, stance));
  const LegAngles on = solved(1.0, stance + 1);
  const LegAngles onRate = (0.5 / h) * (solved(1.0 + h, stance + 1) - solved(1.0 - h, stance + 1));
  auto curve = [&](const std::vector<GaitKey>& keys, double LegAngles::*angle) {
    return swingCurve(keys, {s, off.*angle}, offRate.*angle, {1.0, on.*angle}, onRate.*angle, u);
  };
  const std::vector<GaitKey> adduction = {{0.5 * (1.0 + s), p.swingAdduction}};
  return {curve(p.swingHip, &LegAngles::thigh), curve(adduction, &LegAngles::adduction),
          curve(p.swingKnee, &LegAngles::knee)};
}

std::vector<double> fullPose(const GaitParams& p, const Skeleton& skeleton, double t) {
  std::vector<double> pose = upperPose(p, t);
  for (const LegSide& leg : {kLeft, rightLeg(p)}) {
    poseLeg(p, pose, leg.upLeg, leg.side, t - leg.offset, legAngles(p, skeleton, leg, t));
  }
  return pose;
}

void checkParams(const GaitParams& p) {
  THRONG_CHECK(p.cycleFrames > 0, "gait '", p.name, "' needs frames");
  if (p.kind == GaitKind::Stand) {
    THRONG_CHECK(p.speed == 0.0 && p.gestureBeats >= 0, "standing gait '", p.name, "' must not travel");
  } else {
    THRONG_CHECK(p.stanceFraction > 0.0 && p.stanceFraction < 0.8, "gait '", p.name,
                 "' needs a stance between 0 and 0.8 of a cycle");
  }
}

}  // namespace

std::vector<double> gaitPose(const GaitParams& params, double phase) {
  checkParams(params);
  return fullPose(params, gaitSkeleton(), phase);
}

std::vector<double> gaitFrame(const GaitParams& params, int frame) {
  checkParams(params);
  const int n = params.cycleFrames;
  // Whole cycles are added separately so that frame n is exactly frame 0 moved on by one
  // cycle's travel: the pose is computed from the same phase, 0.
  int cycle = frame >= 0 ? frame / n : -((n - 1 - frame) / n);
  int within = frame - cycle * n;
  std::vector<double> pose = fullPose(params, gaitSkeleton(), double(within) / n);
  pose[2] += cycle * gaitCycleTravel(params);
  return pose;
}

double gaitCycleTravel(const GaitParams& params) {
  return params.speed * params.cycleFrames * params.frameTime;
}

RawClip generateGait(const GaitParams& params) {
  checkParams(params);
  RawClip clip;
  clip.sourceName = params.name + ".bvh";
  clip.skeleton = gaitSkeleton();
  clip.frameCount = params.cycleFrames;
  clip.frameTime = float(params.frameTime);
  clip.channelCount = kChannelCount;
  clip.values.reserve(size_t(kChannelCount) * size_t(params.cycleFrames));
  for (int f = 0; f < params.cycleFrames; ++f) {
    for (double v : fullPose(params, clip.skeleton, double(f) / params.cycleFrames)) {
      clip.values.push_back(float(v));
    }
  }
  return clip;
}

}  // namespace throng::anim
