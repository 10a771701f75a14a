// Sine and cosine for the world generators from + − × alone, so that a seed
// gives the same world on every CPU (docs/worlds.md, "The same world on every
// machine"). glibc picks among variants of sin, cos, tan, atan2, asin, exp and
// log by the CPU it runs on (FMA and AVX2 ones where the CPU has them), and
// they differ in the last bits; + − × ÷ and sqrt are correctly rounded by
// IEEE 754 on every CPU, so a fixed sequence of them gives the same bits.
// The generators' files are compiled with -ffp-contract=off (CMakeLists.txt):
// a build for a CPU with FMA must not fuse these products and sums either.
#pragma once

namespace proxsim::gen {

/// sin(x) for |x| <= π/2 (Taylor series to x^25, evaluated by Horner's rule:
/// its truncation error is below 1e-22, a few units in the last place in all).
double PortableSin(double x_rad);

/// cos(x) for |x| <= π/2, the same way (to x^24).
double PortableCos(double x_rad);

}  // namespace proxsim::gen
