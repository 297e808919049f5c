#pragma once
// Elementary functions that give the same bits natively and in WebAssembly.
//
// glibc's libm (native) and musl's (Emscripten) differ in the last bit of cos, sin, exp, log
// and the rest, and over a run those bits grow into visible differences between the desktop
// app, the CLI and the browser. These are fdlibm's algorithms (FreeBSD msun, as musl carries
// them) built from +, -, *, / and exact bit operations only, which IEEE 754 defines to the bit
// on both targets; portable_math.cpp is compiled with -ffp-contract=off so that no compiler
// fuses a multiply and an add where the other does not. Each is within 1 ulp of the C
// library's result (measured in tests/core/math/portable_math_test.cpp).

namespace swarm::portable {

/// sin(x) and cos(x), x in radians; any finite x (Payne-Hanek reduction beyond 2^20 pi/2).
double sin(double x);
double cos(double x);
/// Both at the cost of one argument reduction.
void sincos(double x, double* sin_x, double* cos_x);

double exp(double x);
/// exp(x) - 1, accurate for small x.
double expm1(double x);
double cosh(double x);
double sinh(double x);
/// Natural logarithm.
double log(double x);
double atan(double x);
/// The angle of (x, y) in (-pi, pi].
double atan2(double y, double x);

}  // namespace swarm::portable
