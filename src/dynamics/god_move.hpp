// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// A move of a god object (App. H.3) from velocity v to velocity V over `displacement` D:
/// the boundary conditions of one target, relative to the object's state when it sets out.
struct GodMoveEnds {
  Vec3 displacement = Vec3::Zero();    // P - p, m
  Vec3 start_velocity = Vec3::Zero();  // v, m/s
  Vec3 end_velocity = Vec3::Zero();    // V, m/s
};

/// A move of two constant-acceleration pieces (one switch) that meets the ends in `duration`:
/// `first` for `switch_fraction` of it, then `second`. switch_fraction is 1 for a move of one
/// piece (second unused).
struct GodMove {
  double duration = 0.0;
  double switch_fraction = 1.0;
  Vec3 first = Vec3::Zero();
  Vec3 second = Vec3::Zero();
};

/// The least largest |acceleration| of any one-switch move that meets `ends` in `duration`
/// (> 0), in closed form (god_move.cpp):
///   m(tau) = sqrt(|dV|^2 + 2 E + 2 sqrt(E^2 + s^2)) / tau,
/// with e = 2 D / tau - v - V, E = |e|^2, s = e . dV and dV = V - v. For a rest-to-rest move of
/// distance d it is 4 d / tau^2.
double GodMoveAcceleration(const GodMoveEnds& ends, double duration);

/// The one-switch move that meets `ends` in `duration` (> 0) with the least largest
/// |acceleration| (both pieces then have |a| = GodMoveAcceleration; a single piece when
/// e = 0, or when rounding leaves one piece no time).
GodMove MakeGodMove(const GodMoveEnds& ends, double duration);

/// The earliest duration >= requested (any real; <= 0 asks for "as soon as possible") for which
/// a one-switch move with |acceleration| <= max_acceleration (> 0) meets `ends`: the requested
/// one when it is feasible, otherwise the first root of a polynomial of degree 6 in the
/// duration beyond it (god_move.cpp). The returned move's pieces have |a| <= max_acceleration
/// within a relative 1e-13.
double EarliestGodMoveDuration(const GodMoveEnds& ends, double max_acceleration, double requested);

}  // namespace sparsedyn
