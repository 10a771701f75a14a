#include "scene/person.h"

#include <cmath>

namespace proxsim {

namespace {

Pose At(double x, double y, double z) {
  Pose X = Pose::Identity();
  X.translation() = Vec3(x, y, z);
  return X;
}

}  // namespace

std::vector<SceneObject> PersonParts(const std::string& name, double height_m, const Pose& X_P,
                                     const Material& material, const std::optional<Motion>& motion) {
  const double H = height_m;
  const double hip_z = 0.53 * H, hip_y = 0.05 * H, leg_r = 0.04 * H;
  const double shoulder_z = 0.81 * H, shoulder_y = 0.13 * H, arm_r = 0.022 * H, arm_length = 0.33 * H;
  const double head_r = 0.07 * H;
  // a full cycle (two steps) per 0.8·H walked; the leg's angle at full swing
  // puts the feet a step (0.4·H) apart: 2·hip_z·sin(a) = 0.4·H
  const double cycle_m = 0.8 * H;
  const double leg_amplitude_rad = std::asin(0.2 * H / hip_z);
  const double arm_amplitude_rad = 0.5 * leg_amplitude_rad;

  struct Part {
    const char* part;
    Shape shape;
    Pose X_PO;
    Vec3 pivot_P;
    double amplitude_rad;
    double phase_rad;
  };
  const Part parts[] = {
      {"left_leg", Cylinder{leg_r, hip_z}, At(0, hip_y, 0.5 * hip_z), Vec3(0, hip_y, hip_z), leg_amplitude_rad, 0},
      {"right_leg", Cylinder{leg_r, hip_z}, At(0, -hip_y, 0.5 * hip_z), Vec3(0, -hip_y, hip_z), leg_amplitude_rad, kPi},
      {"left_arm", Cylinder{arm_r, arm_length}, At(0, shoulder_y, shoulder_z - 0.5 * arm_length),
       Vec3(0, shoulder_y, shoulder_z), arm_amplitude_rad, kPi},
      {"right_arm", Cylinder{arm_r, arm_length}, At(0, -shoulder_y, shoulder_z - 0.5 * arm_length),
       Vec3(0, -shoulder_y, shoulder_z), arm_amplitude_rad, 0},
      {"torso", Box{Vec3(0.13 * H, 2 * (shoulder_y - arm_r), 0.30 * H)}, At(0, 0, hip_z + 0.15 * H), Vec3::Zero(), 0, 0},
      {"head", Sphere{head_r}, At(0, 0, H - head_r), Vec3::Zero(), 0, 0},
  };

  std::vector<SceneObject> objects;
  for (const Part& part : parts) {
    SceneObject object;
    object.name = name + "/" + part.part;
    object.shape = part.shape;
    object.material = material;
    if (motion) {
      // the motion carries the person: X_P is in M, the swing about the pivot in M
      Motion carried = *motion;
      carried.X_MO = X_P * part.X_PO;
      carried.swing = Swing{.pivot_M = X_P * part.pivot_P,
                            .axis_M = X_P.linear() * Vec3::UnitY(),
                            .amplitude_rad = part.amplitude_rad,
                            .cycle_m = cycle_m,
                            .phase_rad = part.phase_rad};
      object.X_WO = MotionPoseAt(carried, 0.0);
      object.motion = std::move(carried);
    } else {
      object.X_WO = X_P * part.X_PO;
    }
    objects.push_back(std::move(object));
  }
  return objects;
}

}  // namespace proxsim
