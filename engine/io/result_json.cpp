#include "shotlab/io/result_json.hpp"

#include "csv.hpp"

namespace shotlab {
namespace {
nlohmann::json vec(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace

nlohmann::json result_to_json(const Simulation& sim, const std::vector<Event>& extra_events) {
  using nlohmann::json;
  const State& s = sim.state();
  json out;
  out["time"] = s.time;
  out["status"] = status_name(sim.status());
  out["diagnostic"] = sim.diagnostic();
  out["balls"] = json::array();
  for (int i = 0; i < s.ball_count(); ++i)
    out["balls"].push_back({{"id", sim.model().balls[i].id},
                            {"position", vec(position(s.x, i))},
                            {"velocity", vec(velocity(s.x, i))},
                            {"angular_velocity", vec(spin(s.x, i))},
                            {"motion", motion_name(sim.motion(i))}});
  out["events"] = json::array();
  std::vector<Event> events = extra_events;
  events.insert(events.end(), sim.events().begin(), sim.events().end());
  for (const Event& e : events) out["events"].push_back({{"time", e.time}, {"kind", e.kind}, {"bodies", e.bodies}});
  const Energy e = sim.energy();
  out["energy"] = {{"kinetic", e.kinetic}, {"potential", e.potential}, {"elastic", e.elastic}, {"total", e.total()}};
  out["momentum"] = vec(sim.momentum());
  const Stats& st = sim.stats();
  out["stats"] = {{"integrator", method_name(sim.model().integrator.method)},
                  {"steps", st.steps},
                  {"rejected_steps", st.rejected_steps},
                  {"redone_steps", st.redone_steps},
                  {"rhs_evaluations", st.rhs_evaluations},
                  {"wall_seconds", st.wall_seconds}};
  return out;
}

void write_trajectory_header(std::ostream& out) { out << "time,ball,x,y,z,vx,vy,vz,wx,wy,wz,motion\n"; }

void write_trajectory_rows(std::ostream& out, const Simulation& sim) {
  const State& s = sim.state();
  for (int i = 0; i < s.ball_count(); ++i) {
    out << s.time << ',' << csv_field(sim.model().balls[i].id);
    for (int k = 0; k < kBallDofs; ++k) out << ',' << s.x[9 * i + k];
    out << ',' << motion_name(sim.motion(i)) << '\n';
  }
}

}  // namespace shotlab
