// Measures what a contact material does in one collision, by running the engine on a two-body scene (not by a
// formula): contact time, peak penetration, peak force and restitution at a given impact speed. Used by the tuning
// panel's readouts and by tests; gravity, table and friction are off so that only the normal law acts.
#pragma once
#include <string>
#include <vector>

#include "shotlab/material.hpp"
#include "shotlab/model.hpp"

namespace shotlab {

struct CollisionProbe {
  double contact_time = 0;       // s; where the bodies do not part (`parted` false), the time probed in contact
  bool parted = true;            // false: still touching at the probe's end, 0.2 s in (an overdamped contact)
  std::string failure;           // the engine's diagnostic where the probe's run stopped (then nothing above holds)
  double peak_penetration = 0;   // m
  double peak_force = 0;         // N
  double restitution = 0;        // separation speed / approach speed
  long steps = 0;                // integrator steps while in contact
  std::vector<double> time;      // s since the contact began, at every step's end while in contact, and its end
  std::vector<double> force;     // N, the normal force then
};

// Ball (mass, radius) hitting an equal free ball head-on (`ball_ball` = true) or a fixed plane, at `speed` m/s.
CollisionProbe probe_collision(const ContactMaterial& material, double mass, double radius, double speed,
                               bool ball_ball, const IntegratorOptions& integrator = {});

}  // namespace shotlab
