#include "scenario/gait_section.h"

#include <optional>

namespace proxsim {

namespace {

// The gaits proxsim walks (bipeds from toys to adults, slow to running pace):
// a period of 1e-9 s walked the robot kilometres per sample and the terrain
// corridor never ended.
constexpr double kMinStride_m = 0.01, kMaxStride_m = 3.0;
constexpr double kMinGaitPeriod_s = 0.1, kMaxGaitPeriod_s = 30.0;
// The largest touchdown tolerance: a foot that settles moves to the true
// ground within one sample (gait/touchdown.h), a jump that stays a kinematic
// stand-in for a foot feeling its way down only over a few centimetres.
constexpr double kMaxTouchdownTolerance_m = 0.05;
// a knee bent further than this is a squat, not a walk
constexpr double kMaxCrouchKnee_deg = 90.0;

const char* const kStrideNote = "a stride a walking robot can take";

}  // namespace

const ConfigSchema<RobotConfig>& GaitSectionSchema() {
  using C = RobotConfig;
  static const ConfigSchema<C> schema = [] {
    // keyframe: a member of the walk's gait, not of the robot
    ConfigParam<C> keyframe;
    keyframe.description = Describe("keyframe", ParamType::kText, "none",
                                    "the name of one of the model's keyframes (MJCF `<key name>`): the gait walks "
                                    "with its knee bend and holds every joint it does not drive at the key's angle "
                                    "(`joints_deg` overrides)");
    keyframe.get = [](const C& c) { return ParamValue(c.gait.keyframe); };
    keyframe.set = [](C& c, const ParamValue& v) { c.gait.keyframe = std::get<std::string>(v); };
    keyframe.is_unset = [](const C& c) { return c.gait.keyframe.empty(); };
    return ConfigSchema<C>{
        WithNote(ConvertedNumberParam<C>(
            "stride_m", Between(kMinStride_m, kMaxStride_m), "m", "the built-in biped's 0.6 m scaled to the legs",
            "the distance between two heel strikes of one foot",
            [](const C& c) { return c.gait.stride_m; },
            [](C& c, double v) {
              c.gait.stride_m = v;
              c.gait.derive_stride_from_legs = false;
            },
            [](const C& c) { return c.gait.derive_stride_from_legs; }), kStrideNote),
        WithNote(ConvertedNumberParam<C>(
            "period_s", Between(kMinGaitPeriod_s, kMaxGaitPeriod_s), "s",
            "the built-in biped's 1.2 s scaled by the square root of the leg length", "the time of one gait cycle",
            [](const C& c) { return c.gait.period_s; },
            [](C& c, double v) {
              c.gait.period_s = v;
              c.gait.derive_period_from_legs = false;
            },
            [](const C& c) { return c.gait.derive_period_from_legs; }), "a gait cycle a walking robot can take"),
        WithNote(ConvertedNumberParam<C>(
            "max_step_m", Between(kMinStride_m, kMaxStride_m), "m",
            "what the legs reach with the knee flexed at most 100° (about 0.32 m for the built-in biped)",
            "the highest step up or down the legs take; a higher one is unsafe ([terrain.md](terrain.md))",
            [](const C& c) { return c.gait.max_step_m; }, [](C& c, double v) { c.gait.max_step_m = v; },
            [](const C& c) { return c.gait.max_step_m == 0.0; }), kStrideNote),
        WithGlosses(ChoiceParam<C, UnsafeSteps>("unsafe_steps", &C::unsafe_steps,
                                                {{UnsafeSteps::kFall, "fall"}, {UnsafeSteps::kRefuse, "refuse"}},
                                                "`fall`: a step the legs cannot take is taken, and the robot falls "
                                                "there, ending the episode; `refuse`: the legs stand before it "
                                                "([outcomes.md](outcomes.md))"),
                    {"a step the legs cannot take is taken, and the robot falls", "the legs stand before it"}),
        WithGlosses(ChoiceParam<C, Footholds>("footholds", &C::footholds,
                                              {{Footholds::kTruth, "truth"}, {Footholds::kMap, "map"}},
                                              "`truth`: every foothold and swing arc planned on the scene's true "
                                              "surface; `map`: on the robot's own terrain map, which must be on "
                                              "(where it knows nothing, a level step at the stance foot's height; "
                                              "the true surface then decides each landing)"),
                    {"footsteps planned on the scene's true surface", "on the robot's own terrain map"}),
        ConvertedNumberParam<C>(
            "touchdown_tolerance_m", Between(0.0, kMaxTouchdownTolerance_m), "m", "0.02",
            "under `footholds: map`, a foot landing lower than planned by more than this falls; within it the foot "
            "settles on the true surface ([terrain.md](terrain.md#footholds-on-the-robots-own-map))",
            [](const C& c) { return c.gait.touchdown_tolerance_m; },
            [](C& c, double v) { c.gait.touchdown_tolerance_m = v; }),
        keyframe,
        ConvertedNumberParam<C>(
            "crouch_knee_deg", Between(0.0, kMaxCrouchKnee_deg), "deg", "the keyframe's, else 0",
            "the stance knee bend added to the curves, half taken by the hip and half by the ankle "
            "([robots.md](robots.md#the-gaits-shape-crouch-from-a-keyframe))",
            [](const C& c) { return RadToDeg(c.gait.crouch_knee_rad.value_or(0.0)); },
            [](C& c, double v) { c.gait.crouch_knee_rad = DegToRad(v); },
            [](const C& c) { return !c.gait.crouch_knee_rad.has_value(); }),
    };
  }();
  return schema;
}

}  // namespace proxsim
