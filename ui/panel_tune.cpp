// The Tuning tab (developers): what changed from the scene file (with a reset and the A/B overlay), every contact
// parameter of the material pairs (the pockets' lining too, on a table with pockets) with an elasticity control, what
// one collision does at a chosen impact speed (measured by probe_collision on a worker thread, with its force-time
// curve), the world and integrator, pause on events, integrator diagnostics and the per-contact inspector. Any change
// re-simulates the current shot.
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "shotlab/restitution.hpp"
#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

// The tuned pairs, named as in model.hpp (by address: no order of initialisation to rely on).
const std::string* const kPairs[kTunedPairs] = {&kBallBall, &kBallCloth, &kBallCushion, &kBallPocket};

// Whether the scene has pair k (a table without pockets has no ball_pocket).
bool has_pair(const Lab& lab, int k) { return lab.scene.model.materials.count(*kPairs[k]) > 0; }

bool same(const ContactMaterial& a, const ContactMaterial& b) {
  return a.stiffness == b.stiffness && a.damping == b.damping && a.exponent == b.exponent &&
         a.damping_law == b.damping_law;
}

template <class T> bool ready(const std::future<T>& f) {
  return f.valid() && f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

BallSpec probe_ball(const Lab& lab) {
  return lab.scene.balls.empty() ? BallSpec{"", kPoolBall.mass, kPoolBall.radius} : lab.scene.balls[0].spec;
}

void update_probes(const Lab& lab, Tuning& t) {
  if (ready(t.probe_job)) t.probes = t.probe_job.get();
  bool stale = t.probes.speed != lab.settings.impact_speed;
  for (int k = 0; k < kTunedPairs; ++k)
    stale |= has_pair(lab, k) && !same(t.probes.material[k], lab.scene.model.material(*kPairs[k]));
  if (!stale || t.probe_job.valid()) return;
  ProbeReadouts next;
  next.speed = lab.settings.impact_speed;
  next.integrator = lab.scene.model.integrator;
  next.integrator.max_steps_per_call = 200000;
  bool present[kTunedPairs];
  for (int k = 0; k < kTunedPairs; ++k)
    if ((present[k] = has_pair(lab, k))) next.material[k] = lab.scene.model.material(*kPairs[k]);
  t.probe_job = std::async(std::launch::async, [next, present, ball = probe_ball(lab)]() mutable {
    for (int k = 0; k < kTunedPairs; ++k) try {
        if (!present[k]) continue;
        next.result[k] = probe_collision(next.material[k], ball.mass, ball.radius, next.speed, k == 0, next.integrator);
        next.valid[k] = std::isfinite(next.result[k].restitution);
      } catch (const std::exception&) {
        next.valid[k] = false;
      }
    return next;
  });
}

// The elasticity control: the restitution wanted at the probe speed, turned into the damping that gives it.
bool elasticity(Lab& lab, Tuning& t, int k, ContactMaterial& m) {
  bool changed = false;
  if (ready(t.damping_job)) {
    const auto [pair, damping] = t.damping_job.get();
    lab.scene.model.materials[*kPairs[pair]].damping = damping;
    changed = true;
  }
  double e = t.restitution[k] >= 0 ? t.restitution[k] : t.probes.valid[k] ? t.probes.result[k].restitution : 0.9;
  char format[48];
  std::snprintf(format, sizeof format, "%%.3f at %.2f m/s", lab.settings.impact_speed);
  if (slider("##elasticity", e, 0.05, 0.999, format)) t.restitution[k] = e;
  mark(std::string("elasticity ") + *kPairs[k]);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("restitution: the share of the approach speed a head-on hit gives "
                                                "back; sets the damping that does it (at the probe speed)");
  if (ImGui::IsItemDeactivatedAfterEdit() && !t.damping_job.valid()) {
    const BallSpec ball = probe_ball(lab);
    const double speed = lab.settings.impact_speed;
    t.damping_job = std::async(std::launch::async, [=] {
      return std::make_pair(k, damping_for_restitution(m, effective_mass(k == 0, ball.mass), speed, e));
    });
  }
  return changed;
}

// Ball-ball friction: constant, or falling with the slip speed (the fit to measurements, docs/model.md#friction-speed).
bool friction_law_editor(const Fields& f, ContactMaterial& m) {
  bool c = false;
  int law = static_cast<int>(m.friction_law);
  f.label("friction law");
  if (ImGui::Combo("##friction_law", &law, "constant\0falls with slip speed\0")) {
    m.friction_law = static_cast<FrictionLaw>(law), c = true;
    if (m.friction_law == FrictionLaw::SpeedDependent && m.friction_decay == 0) {
      const ContactMaterial fit = default_ball_ball();  // start from the measured curve
      m.friction = fit.friction, m.friction_fast_ratio = fit.friction_fast_ratio, m.friction_decay = fit.friction_decay;
    }
  }
  mark("friction law");
  if (m.friction_law != FrictionLaw::SpeedDependent) return c;
  f.label("fast ratio");
  c |= slider("##fast_ratio", m.friction_fast_ratio, 0.0, 1.0, "%.3f");
  f.label("decay");
  c |= slider("##decay", m.friction_decay, 0.0, 10.0, "%.3f s/m");
  return c;
}

bool material_editor(Lab& lab, Tuning& t, int k) {
  ContactMaterial& m = lab.scene.model.materials[*kPairs[k]];
  bool c = false;
  const Fields f({"elasticity e", "stiffness", "damping law", "damping", "exponent", "friction", "friction law",
                  "fast ratio", "decay", "rolling resist.", "spin friction"});
  f.label("elasticity e");
  c |= elasticity(lab, t, k, m);
  char unit[32];
  std::snprintf(unit, sizeof unit, "%%.3g N/m^%g", m.exponent);
  f.label("stiffness");
  c |= slider("##stiffness", m.stiffness, 1e4, 1e12, unit, true);
  mark(std::string("stiffness ") + *kPairs[k]);
  int law = static_cast<int>(m.damping_law);
  f.label("damping law");
  if (ImGui::Combo("##law", &law, "linear (thesis)\0Hunt-Crossley\0")) {  // the same elasticity under the new law
    if (!switch_damping_law(m, static_cast<DampingLaw>(law), effective_mass(k == 0, probe_ball(lab).mass),
                            lab.settings.impact_speed))
      lab.say(MessageKind::Note, "overdamped: no damping under the new law gives this contact's restitution; the "
                                 "number is kept, in the new law's unit (" + std::string(law == 0 ? "N s/m" : "s/m") +
                                 ")");
    c = true;
  }
  const bool linear = m.damping_law == DampingLaw::Linear;
  f.label("damping");
  c |= slider("##damping", m.damping, 0.0, linear ? 1e5 : 10.0, linear ? "%.4g N s/m" : "%.4g s/m", true);
  f.label("exponent");
  c |= slider("##exponent", m.exponent, 1.0, 2.0, "%.2f");
  f.label("friction");
  c |= slider("##friction", m.friction, 0.0, 1.0, "%.3f");
  mark(std::string("friction ") + *kPairs[k]);
  if (k == 0) c |= friction_law_editor(f, m);
  f.label("rolling resist.");
  c |= slider("##rolling", m.rolling_resistance, 0.0, 0.1, "%.4f");
  f.label("spin friction");
  c |= slider("##spin", m.spin_friction, 0.0, 0.2, "%.4f");
  if (c) t.restitution[k] = -1;  // the slider shows the measured value again
  return c;
}

void probe_readout(Lab& lab, const Tuning& t, int k) {
  if (!t.probes.valid[k]) return ImGui::TextDisabled("measuring...");
  const CollisionProbe& p = t.probes.result[k];
  if (!p.failure.empty())
    coloured_wrapped(ImVec4(1, 0.5f, 0.4f, 1), "the probe's collision stopped: %s", p.failure.c_str());
  else if (p.parted)
    coloured_wrapped(ImVec4(0.6f, 0.9f, 1, 1), "contact %.3f ms, penetration %.3f mm, restitution %.3f, peak %.0f N",
                     p.contact_time * 1e3, p.peak_penetration * 1e3, p.restitution, p.peak_force);
  else  // overdamped: the damper holds the bodies together; what the probe saw in its time
    coloured_wrapped(ImVec4(1, 0.7f, 0.3f, 1), "overdamped: still in contact after %.0f ms (parting at %.3f of the "
                     "impact speed), penetration %.3f mm, peak %.0f N", p.contact_time * 1e3, p.restitution,
                     p.peak_penetration * 1e3, p.peak_force);
  mark(std::string("probe ") + *kPairs[k]);
  readout(std::string("contact_time ") + *kPairs[k], p.contact_time);
  readout(std::string("restitution ") + *kPairs[k], p.restitution);
  PlotSpec spec{"probe force", "N", -1, 0, std::max(p.contact_time, 1e-9)};
  spec.seekable = false;  // its own collision, not the shot's: no time of the shot to go to
  lab_plot(lab, (std::string("probe_") + *kPairs[k]).c_str(), spec,
           {{"normal force", IM_COL32(255, 110, 90, 255), p.time, p.force}}, em(110));
  // A class asks why the force does not start at zero: the linear law's damping term is C_d times the closing speed.
  if (!p.force.empty() && p.force.front() > 0.05 * p.peak_force &&
      lab.scene.model.material(*kPairs[k]).damping_law == DampingLaw::Linear)
    hint("It starts at C_d v, not 0: the linear damping law (the thesis's) pushes back from the first touch "
         "(docs/model.md#damping).");
}

// In a box of fixed height, and the A line always there: a change never moves the sliders below, where the next
// click would otherwise land on another field than the one just edited.
void changes_section(Lab& lab) {
  const auto changes = lab.physics_changes();
  const float box = 3 * ImGui::GetTextLineHeightWithSpacing() + 2 * ImGui::GetStyle().WindowPadding.y;
  ImGui::BeginChild("changes", ImVec2(0, box), true);
  if (changes.empty()) hint("the scene file's values (nothing changed)");
  for (const std::string& c : changes) {
    ImGui::Bullet();
    text_wrapped("%s", c.c_str());
  }
  pass_wheel_on();
  ImGui::EndChild();
  ImGui::BeginDisabled(changes.empty());
  if (fitting_button("Reset to the scene's values", "Reset all")) lab.reset_physics();
  mark("Reset physics");
  ImGui::EndDisabled();
  same_line_if_fits("Pin as A");
  ImGui::BeginDisabled(!lab.can_pin());
  if (ImGui::Button("Pin as A")) lab.pin_compare();
  mark("Pin as A");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(lab.shot ? "keep this shot's trails as A: later changes are drawn as B over it"
                               : "keep the predicted paths as A: later changes' predictions are drawn as B over them");
  ImGui::EndDisabled();
  ImGui::Checkbox("A/B overlay", &lab.settings.view.compare);
  // A short line, wrapped in a narrow panel (presentation mode cut it), the rest in its tooltip.
  hint(lab.compare.empty() ? "A: none yet" : lab.compare_label);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", !lab.compare.empty()       ? "A's trails are the dashed grey lines"
                            : lab.settings.view.compare ? "the first change pins the shot (or prediction) before it"
                                                        : "Pin as A, or the overlay on: the first change pins one");
}

bool world_section(Lab& lab) {
  Options& o = lab.scene.model.options;
  IntegratorOptions& in = lab.scene.model.integrator;
  bool changed = false;
  const Fields f({"contact model", "friction sharpness", "rate limit", "gravity", "method", "abs tol", "rel tol",
                  "fixed step", "max steps/call", "physics/frame"});
  int contact = static_cast<int>(o.contact);
  f.label("contact model");
  if (ImGui::Combo("##contact", &contact, "soft (integrated)\0rigid (events)\0"))
    o.contact = static_cast<ContactModel>(contact), changed = true;
  mark("contact model");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("soft: compliant contacts integrated in time, the reference. rigid: balls kept on the bed, "
                      "moved in closed form between instant impulses; tens of times faster, a different model "
                      "(no hops, jumps or rods; docs/model.md#rigid-model)");
  // The rigid model has sharp friction switches and no integrator: those rows do not apply to it (greyed out).
  const bool rigid = o.contact == ContactModel::Rigid;
  if (rigid) hint("greyed out: not used by the rigid model");
  ImGui::BeginDisabled(rigid);
  f.label("friction sharpness");
  changed |= slider("##sharpness", o.friction_sharpness, 1.0, 1e6, "%.4g s/m", true);
  // 0 (no limit) is off the log scale: a checkbox switches the limit off and back to the default.
  bool limited = o.friction_rate_limit > 0;
  f.label("rate limit");
  if (ImGui::Checkbox("##rate_limited", &limited)) o.friction_rate_limit = limited ? Options{}.friction_rate_limit : 0.0, changed = true;
  ImGui::SameLine();
  if (limited) changed |= slider("##rate", o.friction_rate_limit, 1e3, 1e9, "%.3g 1/s", true);
  else ImGui::TextDisabled("off");
  ImGui::EndDisabled();
  double g = -o.gravity.y;
  f.label("gravity");
  if (slider("##gravity", g, 0.0, 30.0, "%.2f m/s^2")) o.gravity.y = -g, changed = true;
  ImGui::BeginDisabled(rigid);
  int method = static_cast<int>(in.method);
  f.label("method");
  if (ImGui::Combo("##method", &method, "Euler\0RK4\0Cash-Karp 54\0Dormand-Prince 5\0Bulirsch-Stoer\0Rosenbrock 4\0"))
    in.method = static_cast<Method>(method), changed = true;
  if (is_adaptive(in.method)) {
    f.label("abs tol");
    changed |= slider("##abs", in.abs_tol, 1e-12, 1e-2, "%.1e", true);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("error allowed per step: m for positions, m/s for velocities and, with Cash-Karp and "
                        "Dormand-Prince, for the speed R|w| a spin gives the ball's surface (rad/s with the others)");
    f.label("rel tol");
    changed |= slider("##rel", in.rel_tol, 1e-12, 1e-2, "%.1e", true);
  } else {
    f.label("fixed step");
    changed |= slider("##step", in.fixed_step, 1e-7, 1e-2, "%.1e s", true);
  }
  ImGui::EndDisabled();
  f.label("max steps/call");
  changed |= ImGui::SliderInt("##maxsteps", &in.max_steps_per_call, 100, 1000000, "%d",
                              ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  integer_entry();
  mark("max steps");
  f.label("physics/frame");
  slider("##budget", lab.settings.budget_ms, 1.0, 50.0, "%.0f ms");  // display only: no re-run
  return changed;
}

// Wrapped: in a narrow inspector a line cut at the edge loses its last figure.
void diagnostics(const Lab& lab) {
  if (!lab.shot) return hint("Shoot to see the integrator at work.");
  const Simulation& sim = lab.shot->sim();
  const Stats& s = sim.stats();
  if (sim.model().options.contact == ContactModel::Rigid) {  // no integration: events only
    text_wrapped("rigid model: %ld collisions and changes of motion", s.steps);
    text_wrapped("last frame: %ld event(s), %.2f ms", lab.shot->last_steps(), lab.shot->last_wall() * 1e3);
    text_wrapped("%zu ball(s) moving", sim.island_balls().size());
    if (sim.status() != Status::Ok)
      coloured_wrapped(ImVec4(1, 0.4f, 0.3f, 1), "stopped: %s", status_name(sim.status()));
    return;
  }
  text_wrapped("%s: %ld steps, %ld rejected, %ld rhs", method_name(sim.model().integrator.method), s.steps,
              s.rejected_steps, s.rhs_evaluations);
  text_wrapped("last frame: %ld steps, %ld rhs, %.2f ms", lab.shot->last_steps(), lab.shot->last_rhs(),
              lab.shot->last_wall() * 1e3);
  text_wrapped("last step %.3g s   real-time factor %.1f", s.last_step, lab.shot->realtime_factor());
  size_t largest = 0;
  const std::vector<std::vector<int>> islands = sim.island_balls();
  for (const auto& balls : islands) largest = std::max(largest, balls.size());
  text_wrapped("islands: %zu (the largest holds %zu ball%s)", islands.size(), largest, largest == 1 ? "" : "s");
  if (sim.status() == Status::StepLimit)
    coloured_wrapped(ImVec4(1, 0.4f, 0.3f, 1), "STEP LIMIT HIT: raise max steps or loosen the model");
  else if (sim.status() != Status::Ok)
    coloured_wrapped(ImVec4(1, 0.4f, 0.3f, 1), "stopped: %s", status_name(sim.status()));
}

void step_plot(Lab& lab) {
  if (!lab.shot || lab.shot->step_sizes().empty()) return;
  PlotSeries h{"accepted steps", IM_COL32(120, 200, 255, 255), {}, {}};
  for (const Sample& x : lab.shot->step_sizes()) h.time.push_back(x.time), h.value.push_back(std::log10(x.value));
  PlotSpec spec{"step size", "log10 s", lab.view_time, 0, std::max(lab.shot->sim().time(), 1e-6), false};
  if (const auto t = lab_plot(lab, "steps", spec, {h}, em(110))) lab.seek(*t);
}

}  // namespace

bool Tuning::busy() const {
  return (probe_job.valid() && !ready(probe_job)) || (damping_job.valid() && !ready(damping_job));
}

void tune_panel(Lab& lab, Tuning& tuning) {
  update_probes(lab, tuning);
  if (section("Changes from the scene file", "Changes", ImGuiTreeNodeFlags_DefaultOpen)) changes_section(lab);
  bool changed = false;
  const Fields f({"probe impact speed"});
  f.label("probe impact speed");
  slider("##probe speed", lab.settings.impact_speed, 0.01, 20.0, "%.2f m/s", true);
  // Open at first: ball-ball, or the cloth in a scene of one ball (it has no ball-ball contact to tune).
  const int first = lab.scene.balls.size() < 2 && has_pair(lab, 1) ? 1 : 0;
  for (int k = 0; k < kTunedPairs; ++k) {
    if (!has_pair(lab, k)) continue;
    ImGui::PushID(k);
    const bool open = ImGui::CollapsingHeader(kPairs[k]->c_str(), k == first ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    mark(*kPairs[k]);
    if (open) {
      changed |= material_editor(lab, tuning, k);
      probe_readout(lab, tuning, k);
    }
    ImGui::PopID();
  }
  const bool world = section("World and integrator", "World");
  mark("World and integrator");
  if (world) changed |= world_section(lab);
  const bool pauses = section("Pause on events", "Pauses");
  mark("Pause on events");
  if (pauses) {
    PauseOn& p = lab.settings.pause_on;
    ImGui::Checkbox("ball-ball contact", &p.ball_ball);
    mark("pause at ball-ball contacts");
    same_line_if_checkbox_fits("cushion contact");
    ImGui::Checkbox("cushion contact", &p.cushion);
    same_line_if_checkbox_fits("pocketed");
    ImGui::Checkbox("pocketed", &p.pocketed);
  }
  if (section("Integrator diagnostics", "Integrator", ImGuiTreeNodeFlags_DefaultOpen)) {
    diagnostics(lab);
    step_plot(lab);
  }
  const bool contacts = section("Contacts of the shot", "Contacts");
  mark("Contacts of the shot");
  if (contacts) contacts_section(lab);
  const bool measured = section("Measured shot", "Measured", lab.measured.shot ? ImGuiTreeNodeFlags_DefaultOpen : 0);
  mark("Measured shot");
  if (measured) measured_section(lab);
  else lab.apply_fit();  // a fit that finished while the section was closed still lands
  if (changed) lab.physics_changed();
}

}  // namespace shotlab
