// The tuning panel (for developers): every contact parameter of the three material pairs, the friction sharpness
// and gravity, the integrator and its tolerances. Any change re-simulates the current shot from its start. Next to
// the sliders: what the stiffness and damping give in one collision at a chosen impact speed, measured by
// probe_collision (a short engine run, in the background), and the integrator's diagnostics.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

#include "ui/panels.hpp"

namespace shotlab {

namespace {

const char* const kPairs[3] = {"ball_ball", "ball_cloth", "ball_cushion"};

bool same(const ContactMaterial& a, const ContactMaterial& b) {
  return a.stiffness == b.stiffness && a.damping == b.damping && a.exponent == b.exponent &&
         a.damping_law == b.damping_law;
}

bool material_editor(ContactMaterial& m) {
  bool c = false;
  c |= slider("stiffness", m.stiffness, 1e4, 1e12, "%.3g N/m^m", true);
  int law = static_cast<int>(m.damping_law);
  if (ImGui::Combo("damping law", &law, "linear (thesis)\0Hunt-Crossley\0")) {
    m.damping_law = static_cast<DampingLaw>(law);
    c = true;
  }
  c |= slider("damping", m.damping, 0.0, m.damping_law == DampingLaw::Linear ? 1e5 : 10.0,
              m.damping_law == DampingLaw::Linear ? "%.4g N s/m" : "%.4g s/m", true);
  c |= slider("exponent", m.exponent, 1.0, 2.0, "%.2f", false);
  c |= slider("friction", m.friction, 0.0, 1.0, "%.3f", false);
  c |= slider("rolling resistance", m.rolling_resistance, 0.0, 0.1, "%.4f", false);
  c |= slider("spin friction", m.spin_friction, 0.0, 0.2, "%.4f", false);
  return c;
}

// Runs the three probes on a worker thread whenever their inputs change; a probe at an absurd stiffness can take a
// while and must not stall the window.
void update_probes(const Lab& lab, ProbeReadouts& p) {
  static std::future<ProbeReadouts> job;  // the one probe run in flight
  if (job.valid() && job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) p = job.get();
  bool stale = p.speed != lab.settings.impact_speed;
  for (int k = 0; k < 3; ++k) stale |= !same(p.material[k], lab.scene.model.material(kPairs[k]));
  if (!stale || job.valid()) return;
  ProbeReadouts next;
  next.speed = lab.settings.impact_speed;
  next.integrator = lab.scene.model.integrator;
  next.integrator.max_steps_per_call = 200000;
  for (int k = 0; k < 3; ++k) next.material[k] = lab.scene.model.material(kPairs[k]);
  const BallSpec ball = lab.scene.balls.empty() ? BallSpec{"", kPoolBall.mass, kPoolBall.radius} : lab.scene.balls[0].spec;
  job = std::async(std::launch::async, [next, ball]() mutable {
    for (int k = 0; k < 3; ++k) try {
        next.result[k] = probe_collision(next.material[k], ball.mass, ball.radius, next.speed, k == 0, next.integrator);
        next.valid[k] = std::isfinite(next.result[k].restitution);
      } catch (const std::exception&) {
        next.valid[k] = false;
      }
    return next;
  });
}

void diagnostics(const Lab& lab) {
  if (!lab.shot) {
    ImGui::TextDisabled("Shoot to see the integrator at work.");
    return;
  }
  const Simulation& sim = lab.shot->sim();
  const Stats& s = sim.stats();
  ImGui::Text("%s: %ld steps, %ld rejected, %ld rhs", method_name(sim.model().integrator.method), s.steps,
              s.rejected_steps, s.rhs_evaluations);
  ImGui::Text("this frame: %ld steps, %ld rhs", lab.shot->last_steps(), lab.shot->last_rhs());
  ImGui::Text("last step %.3g s   real-time factor %.2f", s.last_step, lab.shot->realtime_factor());
  // Islands integrate apart (engine/partition.hpp): how the scene is split right now.
  size_t largest = 0;
  for (const auto& island : sim.islands()) largest = std::max(largest, island->balls().size());
  ImGui::Text("islands: %zu (largest %zu balls)", sim.islands().size(), largest);
  if (sim.status() == Status::StepLimit)
    ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "STEP LIMIT HIT: raise max steps or loosen the model");
  else if (sim.status() != Status::Ok)
    ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "stopped: %s", status_name(sim.status()));
  std::vector<float> log_h;
  for (const Sample& x : lab.shot->step_sizes())
    if (x.time <= lab.view_time || !lab.shot->finished()) log_h.push_back(static_cast<float>(std::log10(x.value)));
  if (!log_h.empty())
    ImGui::PlotLines("log10 step", log_h.data(), static_cast<int>(log_h.size()), 0, "step size (s), per step", -8.0f,
                     -1.0f, ImVec2(0, 70));
}

}  // namespace

void tune_panel(Lab& lab, ProbeReadouts& probes) {
  update_probes(lab, probes);
  bool changed = false;
  slider("probe impact speed", lab.settings.impact_speed, 0.01, 20.0, "%.2f m/s", true);
  for (int k = 0; k < 3; ++k) {
    ImGui::PushID(k);
    if (ImGui::CollapsingHeader(kPairs[k], k == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
      changed |= material_editor(lab.scene.model.materials[kPairs[k]]);
      if (probes.valid[k])
        ImGui::TextColored(ImVec4(0.6f, 0.9f, 1, 1), "contact %.3f ms, penetration %.3f mm,\nrestitution %.3f, peak %.0f N",
                           probes.result[k].contact_time * 1e3, probes.result[k].peak_penetration * 1e3,
                           probes.result[k].restitution, probes.result[k].peak_force);
      else
        ImGui::TextDisabled("measuring...");
    }
    ImGui::PopID();
  }
  if (ImGui::CollapsingHeader("World and integrator", ImGuiTreeNodeFlags_DefaultOpen)) {
    Options& o = lab.scene.model.options;
    IntegratorOptions& in = lab.scene.model.integrator;
    changed |= slider("friction sharpness", o.friction_sharpness, 1.0, 1e6, "%.4g s/m", true);
    // 0 (no limit) is off the log scale: a checkbox switches the limit off and back to the default.
    bool limited = o.friction_rate_limit > 0;
    if (ImGui::Checkbox("##rate_limited", &limited)) {
      o.friction_rate_limit = limited ? Options{}.friction_rate_limit : 0.0;
      changed = true;
    }
    ImGui::SameLine();
    if (limited) changed |= slider("friction rate limit", o.friction_rate_limit, 1e3, 1e9, "%.3g 1/s", true);
    else ImGui::TextDisabled("friction rate limit: off");
    double g = -o.gravity.y;
    if (slider("gravity", g, 0.0, 30.0, "%.2f m/s^2", false)) o.gravity.y = -g, changed = true;
    int method = static_cast<int>(in.method);
    if (ImGui::Combo("method", &method, "Euler\0RK4\0Cash-Karp 54\0Dormand-Prince 5\0Bulirsch-Stoer\0Rosenbrock 4\0")) {
      in.method = static_cast<Method>(method);
      changed = true;
    }
    if (is_adaptive(in.method)) {
      changed |= slider("abs tol", in.abs_tol, 1e-12, 1e-2, "%.1e", true);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("error allowed per step: m for positions, m/s for velocities and, with Cash-Karp and "
                          "Dormand-Prince, for the speed R|w| a spin gives the ball's surface (rad/s with the others)");
      changed |= slider("rel tol", in.rel_tol, 1e-12, 1e-2, "%.1e", true);
    } else {
      changed |= slider("fixed step", in.fixed_step, 1e-7, 1e-2, "%.1e s", true);
    }
    changed |= ImGui::SliderInt("max steps/call", &in.max_steps_per_call, 100, 1000000, "%d",
                                ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    slider("physics per frame", lab.settings.budget_ms, 1.0, 50.0, "%.0f ms", false);  // display only: no re-run
  }
  if (ImGui::CollapsingHeader("Integrator diagnostics", ImGuiTreeNodeFlags_DefaultOpen)) diagnostics(lab);
  if (changed) lab.physics_changed();
}

}  // namespace shotlab
