// Several echoes from one ping: the rays whose echo counts, sorted by the
// distance their echo arrives from and split wherever two successive
// distances differ by the part's separation or more (its pulse cannot tell
// nearer surfaces apart: they merge into one echo). A multi-zone sensor's
// targets per zone (multizone.h), a beam's echoes (beam_echoes.h) and the
// target a single-zone time-of-flight part reads through its beam
// (sensor_model.h MeasureBeam, BeamReadout::kSignalWeighted) are all made
// here; a target's distance is the centre of its rays' distances weighed by
// the signal each carries (the part's histogram peak, or the mean time of
// every photon it counted).
#pragma once

#include <cstddef>
#include <vector>

namespace proxsim {

/// One ray's echo: the distance it arrives from, the sensor's ray index, and
/// the signal its return carries (what it weighs in its target's distance).
struct RangedRay {
  double d_m;
  int ray;
  double signal = 0.0;
};

/// One echo: rays [begin, end) of the sorted rays.
struct EchoGroup {
  std::size_t begin;
  std::size_t end;
};

/// One target: its echo of the sorted rays and its distance, the centre of
/// its rays' distances weighed by their signal (the plain mean when no ray
/// carries any, as a mirror's off-lobe rays). Its nearest ray is the sorted
/// rays' [rays.begin].
struct ResolvedTarget {
  EchoGroup rays;
  double d_m = 0.0;
};

/// Sorts `rays` nearest first (ties by ray index) and writes into `groups`
/// (cleared) at most `max_groups` echoes, nearest first: a gap of
/// `separation_m` or more between two successive rays starts a new echo.
void SplitEchoes(std::vector<RangedRay>& rays, double separation_m, int max_groups, std::vector<EchoGroup>& groups);

/// The targets a part resolves its returns into: SplitEchoes' echoes
/// (`separation_m` +inf: every ray one target), each at its signal-weighted
/// centre, nearest first, at most `max_targets`. Writes `targets` (cleared).
void ResolveTargets(std::vector<RangedRay>& rays, double separation_m, int max_targets,
                    std::vector<ResolvedTarget>& targets);

}  // namespace proxsim
