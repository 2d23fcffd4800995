// The elementary functions the engine uses, computed with + − × ÷ alone, so that every platform
// gives the same bits: C libraries differ in the last bit of sin, cos, atan and exp (glibc on
// the desktop and the musl-derived one of WebAssembly differ in ~1 of 10 random shots), and one
// bit at the strike grows along a shot. Accurate to about 1 ulp over the engine's arguments
// (angles within ±1e5 rad); tests/physics/portable_math_test.cpp compares them with the C
// library.
#pragma once

namespace physics::portable {

double sin(double x);
double cos(double x);
double tan(double x);
double atan(double x);
/// The angle of (x, y) in (−π, π], as std::atan2 for finite arguments.
double atan2(double y, double x);
double exp(double x);

}  // namespace physics::portable
