// The two run cycles. Curve shapes follow published running kinematics (e.g. Novacheck
// 1998, "The biomechanics of running"): the hip sweeps back through stance and peaks in
// flexion late in swing, the knee flexes ~40° while loaded and folds far more in swing at
// higher speed, and the arms swing against the legs with the elbows bent near 90°.
// The stance leg is solved from the root path and the planted foot, so the hip and knee
// keys below shape the swing and only seed the stance.
#include "anim/gait.h"

namespace throng::anim {

GaitParams slowRunGait() {
  GaitParams p;
  p.name = "run_slow";
  p.cycleFrames = 23;  // 2 steps in 23/30 s: 2.61 steps/s
  p.stanceFraction = 0.28;
  p.speed = 2.5;
  p.speedDip = 0.05;
  p.rootHeight = 0.92;
  p.bob = 0.03;
  p.sway = 0.012;
  p.reach = 0.45;
  p.stanceWidth = 0.06;
  p.swingHip = {{0.40, -18}, {0.55, 0}, {0.78, 34}, {0.90, 28}};
  p.swingKnee = {{0.45, 50}, {0.62, 100}, {0.78, 70}, {0.90, 25}};
  p.footPitch = {{0.0, 0}, {0.08, 0}, {0.18, 12}, {0.25, 30}, {0.30, 52}, {0.50, 60}, {0.85, 10}};
  p.swingAnkle = {{0.05, 2}, {0.40, 22}, {0.55, 12}, {0.75, -3}, {0.92, 2}};
  p.swingAdduction = 0;
  p.trunkLean = 6;
  p.pelvisTilt = 8;
  p.bounceTilt = 2;
  p.pelvisYaw = 6;
  p.pelvisRoll = 4;
  p.thoraxYaw = 8;
  p.shoulderMean = -8;
  p.shoulderSwing = 24;
  p.elbowMean = 82;
  p.elbowSwing = 10;
  p.armAbduction = 10;
  return p;
}

GaitParams fastRunGait() {
  GaitParams p;
  p.name = "run_fast";
  p.cycleFrames = 20;  // 2 steps in 20/30 s: 3.0 steps/s
  p.stanceFraction = 0.24;
  p.speed = 4.5;
  p.speedDip = 0.05;
  p.rootHeight = 0.895;
  p.bob = 0.025;
  p.sway = 0.012;
  p.reach = 0.5;
  p.stanceWidth = 0.05;
  p.swingHip = {{0.34, -24}, {0.50, 0}, {0.76, 50}, {0.90, 38}};
  p.swingKnee = {{0.40, 60}, {0.58, 118}, {0.76, 80}, {0.90, 28}};
  p.footPitch = {{0.0, 0}, {0.06, 0}, {0.14, 12}, {0.20, 30}, {0.24, 55}, {0.45, 65}, {0.82, 10}};
  p.swingAnkle = {{0.05, 2}, {0.34, 24}, {0.50, 14}, {0.72, -3}, {0.92, 2}};
  p.swingAdduction = 0;
  p.trunkLean = 12;
  p.pelvisTilt = 12;
  p.bounceTilt = 3;
  p.pelvisYaw = 8;
  p.pelvisRoll = 5;
  p.thoraxYaw = 10;
  p.shoulderMean = -8;
  p.shoulderSwing = 36;
  p.elbowMean = 88;
  p.elbowSwing = 14;
  p.armAbduction = 12;
  return p;
}

}  // namespace throng::anim

// Walking (Perry & Burnfield, "Gait Analysis"): a stance of ~60% of the cycle with double
// support, the body highest at mid-stance (inverted pendulum, so the bob is negative here),
// the knee ~15° in loading and ~60° in swing, small arm swing with the elbows nearly straight.
namespace throng::anim {

GaitParams slowWalkGait() {
  GaitParams p;
  p.name = "walk_slow";
  p.cycleFrames = 33;  // 2 steps in 33/30 s: 1.82 steps/s
  p.stanceFraction = 0.62;
  p.speed = 1.0;
  p.speedDip = 0.03;
  p.rootHeight = 0.905;
  p.bob = -0.014;
  p.sway = 0.02;
  p.reach = 0.5;
  p.stanceWidth = 0.07;
  p.swingHip = {{0.70, -4}, {0.80, 16}, {0.93, 22}};
  p.swingKnee = {{0.68, 42}, {0.76, 62}, {0.86, 50}, {0.95, 15}};
  p.footPitch = {{0.0, 0}, {0.30, 0}, {0.45, 8}, {0.55, 25}, {0.62, 40}, {0.80, 10}};
  p.swingAnkle = {{0.05, 0}, {0.66, 12}, {0.78, -6}, {0.90, -18}};
  p.trunkLean = 3;
  p.pelvisTilt = 6;
  p.bounceTilt = 1;
  p.pelvisYaw = 4;
  p.pelvisRoll = 3;
  p.thoraxYaw = 5;
  p.shoulderMean = -2;
  p.shoulderSwing = 12;
  p.elbowMean = 15;
  p.elbowSwing = 8;
  p.armAbduction = 8;
  return p;
}

GaitParams fastWalkGait() {
  GaitParams p = slowWalkGait();
  p.name = "walk_fast";
  p.cycleFrames = 26;  // 2 steps in 26/30 s: 2.31 steps/s
  p.stanceFraction = 0.58;
  p.speed = 1.6;
  p.rootHeight = 0.90;
  p.bob = -0.02;
  p.swingHip = {{0.66, -4}, {0.77, 16}, {0.92, 22}};
  p.swingKnee = {{0.64, 42}, {0.73, 64}, {0.84, 50}, {0.95, 15}};
  p.footPitch = {{0.0, 0}, {0.28, 0}, {0.42, 10}, {0.52, 28}, {0.58, 42}, {0.78, 12}};
  p.swingAnkle = {{0.05, 0}, {0.62, 12}, {0.75, -6}, {0.90, -18}};
  p.trunkLean = 5;
  p.pelvisYaw = 6;
  p.thoraxYaw = 7;
  p.shoulderSwing = 20;
  p.elbowMean = 25;
  p.elbowSwing = 12;
  return p;
}

// Standing: feet planted under the hips, a slow weight shift, the arms at rest (idle, w = 0)
// or gesturing with nods (talk, w = 1). No travel, so the pair blends gesture intensity.
GaitParams idleGait() {
  GaitParams p;
  p.name = "idle";
  p.kind = GaitKind::Stand;
  p.cycleFrames = 60;  // 2 s
  p.rootHeight = 0.925;
  p.bob = 0.004;
  p.sway = 0.02;
  p.stanceWidth = 0.10;
  p.footForward = 0.13;  // the ball of the foot ahead of the ankle, the ankle under the hip
  p.footPitch = {{0.0, 0}, {0.3, 0}, {0.6, 0}};
  p.swingAnkle = {{0.0, 0}, {0.3, 0}, {0.6, 0}};
  p.trunkLean = 1;
  p.pelvisTilt = 4;
  p.pelvisYaw = 1;
  p.pelvisRoll = 2;
  p.thoraxYaw = 2;
  p.shoulderMean = 2;
  p.elbowMean = 10;
  p.armAbduction = 6;
  p.gestureBeats = 1;
  p.gestureRaise = 4;
  p.gestureElbow = 6;
  p.headNod = 2;
  return p;
}

GaitParams talkGait() {
  GaitParams p = idleGait();
  p.name = "talk";
  p.sway = 0.015;
  p.thoraxYaw = 4;
  p.shoulderMean = 5;
  p.elbowMean = 25;
  p.armAbduction = 10;
  p.gestureBeats = 2;
  p.gestureRaise = 45;
  p.gestureElbow = 50;
  p.headNod = 5;
  return p;
}

// Forward hops with both feet (a standing long jump repeated): crouch on landing, heels rise
// before take-off, arms swing forward together, knees tuck in the air.
GaitParams slowHopGait() {
  GaitParams p;
  p.name = "hop_slow";
  p.kind = GaitKind::Hop;
  p.cycleFrames = 20;  // one hop in 0.667 s
  p.stanceFraction = 0.45;
  p.speed = 0.8;
  p.speedDip = 0.1;
  p.rootHeight = 0.86;
  p.bob = 0.08;
  p.reach = 0.45;
  p.stanceWidth = 0.10;
  p.swingHip = {{0.52, 20}, {0.62, 35}, {0.80, 38}, {0.93, 32}};
  p.swingKnee = {{0.52, 65}, {0.62, 85}, {0.78, 88}, {0.93, 68}};
  p.footPitch = {{0.0, 0}, {0.25, 0}, {0.38, 20}, {0.45, 40}, {0.52, 20}, {0.70, 5}, {0.90, 0}};
  p.swingAnkle = {{0.05, 0}, {0.50, 5}, {0.75, 0}, {0.93, -18}};
  p.trunkLean = 10;
  p.pelvisTilt = 10;
  p.bounceTilt = 8;
  p.shoulderMean = 0;
  p.shoulderSwing = 40;
  p.elbowMean = 40;
  p.elbowSwing = 20;
  p.armAbduction = 12;
  return p;
}

GaitParams fastHopGait() {
  GaitParams p = slowHopGait();
  p.name = "hop_fast";
  p.cycleFrames = 22;  // one hop in 0.733 s
  p.stanceFraction = 0.40;
  p.speed = 1.6;
  p.rootHeight = 0.85;
  p.bob = 0.11;
  p.swingHip = {{0.47, 20}, {0.57, 40}, {0.76, 42}, {0.92, 34}};
  p.swingKnee = {{0.47, 70}, {0.57, 95}, {0.75, 98}, {0.92, 72}};
  p.footPitch = {{0.0, 0}, {0.22, 0}, {0.33, 22}, {0.40, 45}, {0.47, 22}, {0.65, 5}, {0.88, 0}};
  p.trunkLean = 14;
  p.shoulderSwing = 55;
  return p;
}

std::vector<GaitParams> allGaits() {
  return {slowRunGait(), fastRunGait(), slowWalkGait(), fastWalkGait(),
          idleGait(),    talkGait(),    slowHopGait(),  fastHopGait()};
}

}  // namespace throng::anim
