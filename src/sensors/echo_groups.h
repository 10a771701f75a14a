// Several echoes from one ping: the rays whose echo counts, sorted by the
// distance their echo arrives from and split wherever two successive
// distances differ by the part's separation or more (its pulse cannot tell
// nearer surfaces apart: they merge into one echo). A multi-zone sensor's
// targets per zone (multizone.h) and a beam's echoes (beam_echoes.h) are both
// made here.
#pragma once

#include <cstddef>
#include <vector>

namespace proxsim {

/// One ray's echo: the distance it arrives from and the sensor's ray index.
struct RangedRay {
  double d_m;
  int ray;
};

/// One echo: rays [begin, end) of the sorted rays.
struct EchoGroup {
  std::size_t begin;
  std::size_t end;
};

/// Sorts `rays` nearest first (ties by ray index) and writes into `groups`
/// (cleared) at most `max_groups` echoes, nearest first: a gap of
/// `separation_m` or more between two successive rays starts a new echo.
void SplitEchoes(std::vector<RangedRay>& rays, double separation_m, int max_groups, std::vector<EchoGroup>& groups);

}  // namespace proxsim
