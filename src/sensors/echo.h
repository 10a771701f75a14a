// A ray's echo (Echo, sensor_model.h): the noise-free truth a sensor model
// reads, made from where the ray went and what it hit. The simulation's
// sensor reader and the bench's pipeline both make their echoes here, so the
// bench times the physics the simulation runs.
//
// Frames: W world.
#pragma once

#include "core/geometry.h"
#include "sensors/sensor_model.h"

namespace proxsim {

/// The echo of a ray of unit direction dir_W whose first hit lies distance_m
/// away, on a surface of unit normal normal_W (either side): d and the
/// incidence α. The surface's material stays at Echo's defaults (ρ = 1,
/// reflectivity 1, not specular: the robot's links); the caller sets a scene
/// object's own, and the flight shift when the sensor times its echo's flight.
Echo EchoOfHit(double distance_m, const Vec3& dir_W, const Vec3& normal_W);

}  // namespace proxsim
