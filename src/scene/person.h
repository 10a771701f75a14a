// A person made of primitives (docs/worlds.md, "Person"): two legs and two
// arms (cylinders), a torso (box) and a head (sphere), sized from the height.
// Carried by a motion, the person faces M's +x and swings its legs and arms
// with the distance walked (a full cycle, two steps, every 0.8·height: a
// walking adult's stride), the legs in opposition and each arm against the
// leg of its side. At shin height the legs are what a walking robot's
// sensors see, so they are full cylinders swinging from the hip, as wide as
// a trouser leg. Standing (no motion), the limbs hang straight.
//
// Proportions (of the height H): hip at 0.53·H, leg radius 0.04·H, torso
// 0.30·H tall over the hips, shoulders at 0.81·H, arm 0.33·H long, head a
// sphere of radius 0.07·H at the top. These follow anthropometric tables
// (Drillis and Contini's segment lengths) to the nearest few percent; they
// are not a body model.
//
// Frames: W world, M the motion's frame, P the person (feet between its
// soles, at its pose), O a part.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace proxsim {

/// Tallest and shortest person accepted, metres.
constexpr double kPersonMinHeight_m = 0.5;
constexpr double kPersonMaxHeight_m = 2.5;

/// The parts of a person named `name` (`NAME/left_leg`, `NAME/right_leg`,
/// `NAME/left_arm`, `NAME/right_arm`, `NAME/torso`, `NAME/head`) standing at
/// X_P (in W, or in M when `motion` is given: the motion carries it).
std::vector<SceneObject> PersonParts(const std::string& name, double height_m, const Pose& X_P,
                                     const Material& material, const std::optional<Motion>& motion);

}  // namespace proxsim
