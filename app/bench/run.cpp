#include "run.hpp"

#include <algorithm>
#include <map>

#include "shotlab/io/scene_json.hpp"

namespace shotlab {
namespace {

// Steps per contact, from the step end times of each ball's islands and the contact events: a contact [begin, end]
// of ball A is overlapped by step k of A's island, which spans (t_{k-1}, t_k], when t_k > begin and t_{k-1} < end,
// i.e. by the steps from the first t_k > begin through the first t_k >= end. Contacts with the bed are left out: a
// ball on the table is always in one.
void count_contact_steps(const Model& model, const std::vector<Event>& events,
                         const std::vector<std::vector<double>>& step_ends, double end_time, RunResult& r) {
  std::map<std::vector<std::string>, double> open;
  std::vector<std::pair<std::vector<std::string>, std::pair<double, double>>> spans;
  for (const Event& e : events) {
    if (e.kind != "contact_begin" && e.kind != "contact_end") continue;
    if (std::find(e.bodies.begin(), e.bodies.end(), "bed") != e.bodies.end()) continue;
    if (e.kind == "contact_begin") {
      open[e.bodies] = e.time;
    } else if (auto it = open.find(e.bodies); it != open.end()) {
      spans.push_back({e.bodies, {it->second, e.time}});
      open.erase(it);
    }
  }
  for (const auto& [bodies, begin] : open) spans.push_back({bodies, {begin, end_time}});
  long total = 0;
  for (const auto& [bodies, span] : spans) {
    const auto [begin, end] = span;
    const std::vector<double>& ends = step_ends[model.ball_index(bodies[0])];
    const auto first = std::upper_bound(ends.begin(), ends.end(), begin);
    auto last = std::lower_bound(ends.begin(), ends.end(), end);
    if (last != ends.end()) ++last;
    total += std::max<long>(0, last - first);
  }
  r.contacts = static_cast<int>(spans.size());
  r.steps_per_contact = spans.empty() ? 0.0 : static_cast<double>(total) / spans.size();
}

}  // namespace

RunResult run_case(const std::string& data_root, const BenchCase& c, const MethodSetting& setting, bool reference) {
  Scene scene = load_scene(data_root + "/" + c.file, c.overrides);
  scene.model.integrator = integrator_options(setting);
  if (setting.plain) use_path(scene.model.options, SolverPath::Plain);
  if (setting.rigid) scene.model.options.contact = ContactModel::Rigid;
  Prepared p = prepare(scene);
  RunResult r;
  for (const BallSpec& b : p.model.balls) r.radius.push_back(b.radius);
  Simulation sim(std::move(p.model), std::move(p.state));
  r.x0 = sim.state().x;
  for (int i = 0; i < sim.state().ball_count(); ++i)
    r.speed_scale = std::max(r.speed_scale, glm::length(velocity(r.x0, i)));
  r.energy0 = sim.energy().total();
  r.momentum0 = sim.momentum();

  // The step end times of each ball's islands, and for a reference each component's largest size. The observer does
  // little per step: it must not distort the wall time.
  std::vector<std::vector<double>> step_ends(sim.state().ball_count());
  if (reference) {
    r.scale.resize(r.x0.size());
    std::transform(r.x0.begin(), r.x0.end(), r.scale.begin(), [](double v) { return std::abs(v); });
  }
  sim.set_observer([&](const StepView& step) {
    for (size_t k = 0; k < step.balls.size(); ++k) {
      const int i = step.balls[k];
      step_ends[i].push_back(step.t1);
      for (int c = 0; c < kBallDofs && reference; ++c) {
        double& scale = r.scale[kBallDofs * i + c];
        scale = std::max(scale, std::abs(step.state.x[kBallDofs * k + static_cast<size_t>(c)]));
      }
    }
  });
  if (c.until_rest) {
    // Frames of 1/60 s, as the GUI runs; stop at the first frame where everything is at rest.
    while (sim.time() < scene.duration && sim.status() == Status::Ok && !sim.at_rest()) sim.advance(1.0 / 60);
  } else {
    sim.advance(scene.duration);
  }
  r.status = sim.status();
  r.end_time = sim.time();
  r.x = sim.state().x;
  r.stats = sim.stats();
  r.energy1 = sim.energy().total();
  r.momentum1 = sim.momentum();
  count_contact_steps(sim.model(), sim.events(), step_ends, r.end_time, r);
  return r;
}

Errors errors(const BenchCase& c, const RunResult& run, const RunResult& ref, double tolerance) {
  Errors e;
  // Velocity errors relative to the fastest ball at the start; the cradle starts at rest, so it falls back on the
  // fastest ball of the reference's end state.
  double scale = ref.speed_scale;
  if (scale == 0)
    for (size_t i = 0; i < ref.radius.size(); ++i)
      scale = std::max(scale, glm::length(velocity(ref.x, static_cast<int>(i))));
  if (scale == 0) scale = 1.0;  // m/s: nothing ever moved; the velocities are compared as they are
  for (size_t k = 0; k < run.radius.size(); ++k) {
    const int i = static_cast<int>(k);
    e.position = std::max(e.position, glm::length(position(run.x, i) - position(ref.x, i)) / run.radius[k]);
    // Exact answer of an undamped head-on hit of equal balls: ball i leaves with the other ball's velocity.
    const Vec3 expected = c.swap_exact ? velocity(run.x0, 1 - i) : velocity(ref.x, i);
    e.velocity = std::max(e.velocity, glm::length(velocity(run.x, i) - expected) / scale);
    if (tolerance <= 0) continue;
    // Component by component, as the stepper weighs a step's error estimate (BallErrorChecker): a spin as the surface
    // speed R w.
    const Vec3 want[] = {position(ref.x, i), expected, spin(ref.x, i)};
    const Vec3 got[] = {position(run.x, i), velocity(run.x, i), spin(run.x, i)};
    for (int part = 0; part < 3; ++part)
      for (int k = 0; k < 3; ++k) {
        const double unit = part < 2 ? 1.0 : run.radius[static_cast<size_t>(i)];
        const double error = unit * std::abs(got[part][k] - want[part][k]), end = unit * std::abs(want[part][k]);
        const size_t at = kBallDofs * static_cast<size_t>(i) + 3 * part + k;
        const double over_run = at < ref.scale.size() ? std::max(end, unit * ref.scale[at]) : end;
        double& over = part < 2 ? e.tolerance_pv : e.tolerance_spin;
        double& at_end = part < 2 ? e.tolerance_pv_end : e.tolerance_spin_end;
        over = std::max(over, error / (tolerance + tolerance * over_run));
        at_end = std::max(at_end, error / (tolerance + tolerance * end));
      }
  }
  e.missed = std::max(0, ref.contacts - run.contacts);
  if (c.conservative) e.energy = std::abs(run.energy1 - run.energy0) / std::abs(run.energy0);
  if (c.free_space) e.momentum = glm::length(run.momentum1 - run.momentum0) / glm::length(run.momentum0);
  return e;
}

}  // namespace shotlab
