// What a headless run writes: RESULT.json (final state, events, stats) and the trajectory CSV.
#pragma once
#include <nlohmann/json.hpp>
#include <ostream>

#include "shotlab/simulation.hpp"

namespace shotlab {

// time, status, diagnostic, balls (id, position, velocity, angular_velocity, motion), events, energy, momentum,
// stats (integrator, steps, rejected_steps, rhs_evaluations, wall_seconds).
nlohmann::json result_to_json(const Simulation& sim, const std::vector<Event>& extra_events = {});

// CSV with one row per ball per sample: time,ball,x,y,z,vx,vy,vz,wx,wy,wz,motion (RFC 4180: an id with a comma, a
// quote or a line break is quoted).
void write_trajectory_header(std::ostream& out);
void write_trajectory_rows(std::ostream& out, const Simulation& sim);

}  // namespace shotlab
