#pragma once
/// The three kinds of motion about the centre of mass: oscillation, free flight, runaway.

namespace swarm {

enum class Regime { attractive, free, repulsive };

/// Classifies k = J M: oscillation (k > 0), free flight (k = 0), exponential runaway (k < 0).
Regime regime_of(double k);

/// sqrt(|k|) (1/time): the angular frequency omega = sqrt(J M) for J > 0, the runaway rate
/// Omega = sqrt(-J M) for J < 0, 0 for J = 0.
double omega_of(double k);

/// Period 2 pi / omega of the attractive case; infinity otherwise.
double period_of(double k);

/// 2 pi / sqrt|k| (time): the period when k > 0, and when k < 0 the time in which the runaway
/// grows e^(2 pi)-fold, the same scale of time for pacing and drawing; infinity when k = 0.
double natural_time_of(double k);

}  // namespace swarm
