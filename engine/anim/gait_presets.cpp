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
