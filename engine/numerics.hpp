// The engine's numerical thresholds, each named once with its unit and why. Physics constants belong to the model
// (model.hpp, material.hpp); these decide how the equations are stepped, cut and switched (docs/model.md#steps).
#pragma once

namespace shotlab {

// --- Distances (m) ---

// A contact counts from this depth on; a pair (or a sleeper and a ball) closer than this counts as touching. Frozen
// balls touch at zero depth give or take round-off (1e-17 to 1e-11 m), which must not begin or end contacts; a real
// impact passes 1 nm within 1e-10 s at 10 m/s.
inline constexpr double kTouch = 1e-9;
// A ball this close to a collider counts as supported: it stays "on the table" through the micrometre bounces of a
// settling contact instead of flickering between airborne and landed.
inline constexpr double kSupportGap = 1e-5;
// A bounded plane's floor column is inset by this much: level_floor wants the corners strictly inside.
inline constexpr double kFloorInset = 1e-9;

// --- Times (s) ---

// Bisection stops when the bracket is this short for a reported event and for a contact change that cuts a step.
inline constexpr double kTimeResolution = 1e-10;
// How closely the onset of a contact left out of a step is located: the time the next step spends on the wrong law
// (a damped contact's force jumps to c v at zero depth). A step ending this close after an onset ends at it.
inline constexpr double kOnsetResolution = 1e-13;
// A kink this close to a step's start is crossed within round-off: not worth a step of its own.
inline constexpr double kKinkTooClose = 1e-12;
// Balls that could touch this soon are integrated together (partition.hpp). Shorter splits a scene finer but looks at
// islands again more often.
inline constexpr double kLinkTime = 1e-3;
// The longest islands run apart while one holds two or more awake balls; they are split only when they synchronise.
inline constexpr double kMaxHorizon = 0.02;
// The longest islands run apart when each is a single awake ball, and how far ahead a lone ball's free path and a
// swing's closed form are followed.
inline constexpr double kLoneHorizon = 0.25;

// --- Speeds (m/s) ---

// Speeds this small are round-off, not motion: below every tolerance an integrator is run at.
inline constexpr double kDeadTail = 1e-12;
// A rolling ball this slow stops (Regimes::settle_rolling).
inline constexpr double kStopSpeed = 1e-7;

// --- Shares and counts (dimensionless) ---

// How closely a friction switch is located, as a share of the step: a kink left this close to a step's end costs
// nothing.
inline constexpr double kSwitchResolution = 1e-4;
// A ball enters the rolling regime once its slip is under kEntrySlip rest_speed and under kEntrySlipPerTolerance
// abs_tol: the smoothed friction has done almost all its work, and the snap stays under the integration error.
inline constexpr double kEntrySlip = 0.01;
inline constexpr double kEntrySlipPerTolerance = 10.0;
// The share of abs_tol one snap onto a regime may move a ball where its corrections do not hold (Regimes::settles,
// swing_of): a break has a few dozen snaps, and at 3 % they stay under the plain path's own error.
inline constexpr double kSnapShare = 0.03;
// A friction switch whose terms move the velocities by less than this share of abs_tol over the step is no kink
// worth a cut (EventDetector::moves).
inline constexpr double kSwitchMoveShare = 0.01;
// A change this close to a step's start, as a share of the step, does not end it: a contact's onset or end is left to
// the next step (Island::cut_at_change), a friction term's band edge is crossed (band_edge_share).
inline constexpr double kEarlyShare = 0.01;
// Attempts of one step redone to end at a contact change before it is redone with the plain law.
inline constexpr int kMaxRedos = 8;
// Iterations of the root finder that locates a change of sign (a depth or height crossing, a release, a change of
// motion) before bisection finishes (events.cpp): it takes a handful on a smooth crossing.
inline constexpr int kMaxRootIterations = 30;
// Steps of a bounce's scalar ODE (bounce.cpp) after which it ends where it got to: a settling ball takes a few dozen.
inline constexpr int kMaxBounceSteps = 2000;

// --- Rates (1/s) ---

// Baumgarte rate that pulls a rod's numerical drift of length and radial speed back to zero: slow against contacts,
// fast against a swing.
inline constexpr double kRodDriftRate = 50.0;

}  // namespace shotlab
