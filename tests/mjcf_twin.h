// A small MuJoCo robot that tests write as a file (tests/mjcf_model_test.cc
// against its URDF twin, tests/model_scene_test.cc inside a scene file).
#pragma once

#include <string>
#include <utility>

namespace proxsim::testing {

// The robot: a pelvis (free), two legs of hip, knee and ankle pitch joints as
// the built-in biped's (the default leg map), a sensor site on the left shin,
// and on the pelvis a tilted mast turned by two hinges about anchors off its
// origin, carrying a head on a limited slide joint.
inline constexpr const char* kMjcfTwinBody = R"(<mujoco model="twin">
  <compiler angle="degree"/>
  <worldbody>
    <body name="pelvis" pos="0 0 0.98">
      <freejoint name="root"/>
      <geom type="box" size="0.1 0.15 0.08" pos="0 0 0.04"/>
      <body name="mast" pos="-0.05 0 0.12" quat="0.9689124217106447 0.04786268954660339 -0.1005403300 0.2190535140">
        <joint name="mast_yaw" type="hinge" axis="0 0 1" pos="0.01 0 0.02" range="-45 45" limited="true"/>
        <joint name="mast_pitch" type="hinge" axis="0 1 0" pos="0 0.01 0.05"/>
        <geom type="cylinder" size="0.02 0.1" pos="0 0 0.1"/>
        <body name="head" pos="0 0 0.25">
          <joint name="head_lift" type="slide" axis="0 0 1" range="-0.05 0.1" limited="true"/>
          <geom type="sphere" size="0.08"/>
        </body>
      </body>
%LEGS%    </body>
  </worldbody>
  <actuator><motor joint="left_knee_pitch"/></actuator>
</mujoco>
)";

// one leg of the twin: S its side, Y its hip's y, SITE what its shin carries
inline constexpr const char* kMjcfTwinLeg = R"(      <body name="S_thigh" pos="0 Y 0">
        <joint name="S_hip_pitch" type="hinge" axis="0 -1 0" range="-60 100" limited="true"/>
        <geom type="cylinder" size="0.05 0.225" pos="0 0 -0.225"/>
        <body name="S_tibia" pos="0 0 -0.45">
          <joint name="S_knee_pitch" type="hinge" axis="0 1 0" range="0 130" limited="true"/>
          <geom type="cylinder" size="0.04 0.225" pos="0 0 -0.225"/>SITE
          <body name="S_foot" pos="0 0 -0.45">
            <joint name="S_ankle_pitch" type="hinge" axis="0 -1 0" range="-40 40" limited="true"/>
            <geom type="box" size="0.13 0.05 0.03" pos="0.07 0 -0.05"/>
          </body>
        </body>
      </body>
)";

// The twin's MJCF text: its body with both legs in place.
inline std::string MjcfTwin() {
  const auto leg = [](const std::string& side, const std::string& y, const std::string& site) {
    std::string text = kMjcfTwinLeg;
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"S_", side + "_"}, {" Y ", " " + y + " "}, {"SITE", site}}) {
      for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    }
    return text;
  };
  std::string text = kMjcfTwinBody;
  text.replace(text.find("%LEGS%"), 6,
               leg("left", "0.1", "\n          <site name=\"left_shin_sensor\" pos=\"0.06 0 -0.35\" euler=\"0 15 0\"/>") +
                   leg("right", "-0.1", ""));
  return text;
}

}  // namespace proxsim::testing
