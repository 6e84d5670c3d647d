// The time of whole shots to rest (issue 34): each scene run in frames of 1/60 s until the first frame at which every
// ball is at rest, as a game or the bench's S7 and S8 run it, timed from the simulation's construction to that frame.
// Rounds alternate the scenes; each scene's median and fastest wall time, its steps, rejected steps and right-hand
// sides (the same in every round; redone: accepted trials done again to end where a law changes), and a digest of the end state (to tell that two builds ran the same physics) are
// printed, one line a scene. Run it pinned to one core (scripts/speed_bench.py does). With --census, one more run
// of each scene counts its steps and right-hand sides by the kind of island that took them and by the phase a step
// resolves (phase_of), and ten more share out the wall time between them. With --rigid the scenes run on the rigid
// model (ContactModel::Rigid); first_ms is
// the first round's time, which works out the restitution table's knots the process has not met yet.
//   shot_speed [--rounds N] [--plain] [--rigid] [--census] SCENE...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "shotlab/contact.hpp"
#include "shotlab/diagnostics.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Run {
  double ms = 0;
  shotlab::Stats stats;
  double end_time = 0, digest = 0;
};

// One shot to rest; false (printed) if the engine stops or no rest comes within ten minutes of simulated time.
bool run_to_rest(const shotlab::Prepared& prepared, Run& out) {
  shotlab::Prepared p = prepared;
  const auto t0 = Clock::now();
  shotlab::Simulation sim(std::move(p.model), std::move(p.state));
  for (int frame = 0; frame < 60 * 600 && !sim.at_rest(); ++frame)
    if (sim.advance(1.0 / 60) != shotlab::Status::Ok) {
      std::fprintf(stderr, "shot_speed: %s\n", sim.diagnostic().c_str());
      return false;
    }
  out.ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (!sim.at_rest()) return std::fprintf(stderr, "shot_speed: no rest within 600 s\n"), false;
  out.stats = sim.stats();
  out.end_time = sim.time();
  out.digest = 0;
  for (double v : sim.state().x) out.digest += v;
  return true;
}

// Steps and right-hand sides of one run to rest by island: "N balls" for islands of several, and for lone balls
// "lone, closed form" (one right-hand side a step: rolling, sliding, flying) or "lone, integrated". For each kind also
// what shortens its steps: how many ended at a contact or friction change (redone), the trials the error control
// rejected, and how many steps ended with a friction term inside a band widened by the rate limit (there the term is a
// linear damper at the limit's rate, docs/model.md#rate-limit). The wall time a kind takes is what passed between the
// end of the observer's last call and the start of this one: the step, with the regroups and the frame ends before it
// (the observer's own work left out), averaged over kCensusTimed runs.
struct Census {
  long steps = 0, rhs = 0, redone = 0, rejected = 0, limited = 0;
  double wall_ms = 0;
};
constexpr int kCensusTimed = 10;

// What a step resolves, told by what touches at its end (a contact's steps are short): a ball-ball contact, a
// cushion (or its jaw), a pocket (its liner, or a ball in its hole), else the bed alone (a hop after a hit, its
// landings, the settling onto the cloth); steps at one right-hand side are closed form.
std::string phase_of(const shotlab::StepView& v, long rhs) {
  if (rhs <= 1) return "closed form";
  bool ball = false, cushion = false, pocket = false;
  for (const shotlab::Contact& c : shotlab::contacts(v.model, v.state)) {
    if (c.other_ball >= 0) {
      ball = true;
      continue;
    }
    const std::string& name = v.model.colliders[c.collider].name;
    if (name.rfind("cushion", 0) == 0) cushion = true;
    else if (name != "bed") pocket = true;
  }
  for (int k = 0; k < v.state.ball_count(); ++k)
    pocket = pocket || (v.state.in_play[k] && v.state.x[9 * k + 1] < 0.5 * v.model.balls[k].radius);
  return ball ? "ball-ball contact" : cushion ? "cushion" : pocket ? "pocket" : "bed alone (hops, landings, settling)";
}

void census(const std::string& file, const shotlab::Prepared& prepared) {
  std::map<std::string, Census> count, by_phase;
  std::vector<std::string> phases;  // each step's phase_of, in the order run 0 met them (every run takes the same steps)
  constexpr uint8_t kLimited = shotlab::kSlipLimited | shotlab::kRollLimited | shotlab::kSpinLimited;
  for (int run = 0; run <= kCensusTimed; ++run) {  // run 0 counts, the others time
    shotlab::Prepared p = prepared;
    shotlab::Simulation sim(std::move(p.model), std::move(p.state));
    std::map<const shotlab::Stats*, shotlab::Stats> seen;  // each island's counts at its last step
    auto since = Clock::now();
    size_t step = 0;
    sim.set_observer([&](const shotlab::StepView& v) {
      const auto now = Clock::now();
      shotlab::Stats& last = seen[&v.stats];
      if (last.rhs_evaluations > v.stats.rhs_evaluations) last = shotlab::Stats{};  // a new island in an old one's place
      const long rhs = v.stats.rhs_evaluations - last.rhs_evaluations;
      const std::string kind = v.balls.size() > 1 ? std::to_string(v.balls.size()) + " balls"
                               : rhs <= 1       ? "lone, closed form"
                                                : "lone, integrated";
      Census& c = count[kind];
      if (run == 0) phases.push_back(phase_of(v, rhs));
      Census& ph = by_phase[phases.at(step++)];
      if (run > 0) {
        c.wall_ms += std::chrono::duration<double, std::milli>(now - since).count() / kCensusTimed;
        ph.wall_ms += std::chrono::duration<double, std::milli>(now - since).count() / kCensusTimed;
      } else {
        ph.steps += 1;
        ph.rhs += rhs;
        c.steps += 1;
        c.rhs += rhs;
        c.redone += v.stats.redone_steps > last.redone_steps;
        c.rejected += v.stats.rejected_steps - last.rejected_steps;
        for (const shotlab::Contact& contact : shotlab::contacts(v.model, v.state))
          if (contact.force.bands & kLimited) {
            ++c.limited;
            break;
          }
      }
      last = v.stats;
      since = Clock::now();
    });
    for (int frame = 0; frame < 60 * 600 && !sim.at_rest(); ++frame)
      if (sim.advance(1.0 / 60) != shotlab::Status::Ok) return;
  }
  for (const auto& [kind, c] : count)
    std::printf("%s census %s steps %ld rhs %ld redone %ld rejected %ld limited %ld wall_us %.0f\n", file.c_str(),
                kind.c_str(), c.steps, c.rhs, c.redone, c.rejected, c.limited, 1e3 * c.wall_ms);
  for (const auto& [name, c] : by_phase)
    std::printf("%s phase %s steps %ld rhs %ld wall_us %.0f\n", file.c_str(), name.c_str(), c.steps, c.rhs,
                1e3 * c.wall_ms);
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 20;
  bool plain = false, rigid = false, with_census = false;
  std::vector<std::string> files;
  for (int a = 1; a < argc; ++a) {
    if (!std::strcmp(argv[a], "--rounds") && a + 1 < argc) rounds = std::max(1, std::atoi(argv[++a]));
    else if (!std::strcmp(argv[a], "--plain")) plain = true;
    else if (!std::strcmp(argv[a], "--rigid")) rigid = true;
    else if (!std::strcmp(argv[a], "--census")) with_census = true;
    else files.push_back(argv[a]);
  }
  if (files.empty()) return std::fprintf(stderr, "usage: shot_speed [--rounds N] [--plain] [--rigid] [--census] SCENE...\n"), 2;
  std::vector<shotlab::Prepared> scenes;
  try {
    for (const std::string& f : files) {
      scenes.push_back(shotlab::prepare(shotlab::load_scene(f)));
      if (plain) shotlab::use_path(scenes.back().model.options, shotlab::SolverPath::Plain);
      if (rigid) scenes.back().model.options.contact = shotlab::ContactModel::Rigid;
    }
  } catch (const std::exception& e) {
    return std::fprintf(stderr, "shot_speed: %s\n", e.what()), 1;
  }
  std::vector<std::vector<Run>> runs(scenes.size());
  for (int r = 0; r < rounds; ++r)
    for (size_t s = 0; s < scenes.size(); ++s)
      if (!run_to_rest(scenes[s], runs[s].emplace_back())) return 1;
  for (size_t s = 0; s < scenes.size(); ++s) {
    std::vector<double> ms;
    for (const Run& run : runs[s]) ms.push_back(run.ms);
    std::sort(ms.begin(), ms.end());
    const Run& last = runs[s].back();
    std::printf(
        "%s median_ms %.4f min_ms %.4f steps %ld rejected %ld redone %ld rhs %ld end_s %.4f digest %.12e first_ms %.4f\n",
        files[s].c_str(), ms[ms.size() / 2], ms.front(), last.stats.steps, last.stats.rejected_steps,
        last.stats.redone_steps, last.stats.rhs_evaluations, last.end_time, last.digest, runs[s].front().ms);
  }
  for (size_t s = 0; s < scenes.size() && with_census; ++s) census(files[s], scenes[s]);
  return 0;
}
