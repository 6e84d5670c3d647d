#include "ui/contact_log.hpp"

#include <algorithm>
#include <map>

#include "shotlab/diagnostics.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

namespace {

constexpr int kSamplesPerStep = 4;  // points on each step's dense output, besides its end

}  // namespace

std::vector<ContactTrace> contact_spans(const std::vector<Event>& events, const Model& model) {
  std::vector<ContactTrace> out;
  std::map<std::pair<std::string, std::string>, size_t> open;
  for (const Event& e : events) {
    if (e.bodies.size() != 2 || e.bodies[1] == "bed") continue;
    const auto key = std::make_pair(e.bodies[0], e.bodies[1]);
    if (e.kind == "contact_begin") {
      ContactTrace t;
      t.a = e.bodies[0], t.b = e.bodies[1], t.begin = e.time;
      t.ball_ball = model.ball_index(t.b) >= 0;
      open[key] = out.size();
      out.push_back(std::move(t));
    } else if (e.kind == "contact_end") {
      if (auto it = open.find(key); it != open.end()) out[it->second].end = e.time, open.erase(it);
    }
  }
  // A ball that leaves play (down a pocket, off the table) ends its contacts there: no contact_end comes for them.
  for (const Event& e : events) {
    if ((e.kind != "pocketed" && e.kind != "off_table") || e.bodies.empty()) continue;
    for (auto it = open.begin(); it != open.end();) {
      const bool mine = it->first.first == e.bodies[0] || it->first.second == e.bodies[0];
      if (mine && out[it->second].begin <= e.time) out[it->second].end = e.time, it = open.erase(it);
      else ++it;
    }
  }
  return out;
}

namespace {

// Index of a body named `name` among the island's balls (as a ball) or the model's colliders.
bool matches(const Contact& c, const Model& m, int ball, const std::string& other) {
  if (c.ball != ball) return false;
  if (c.other_ball >= 0) return m.balls[c.other_ball].id == other;
  return c.collider >= 0 && m.colliders[c.collider].name == other;
}

// Samples, at time t of the island's last step, every trace in `live` (indices into traces) whose ball is in it.
void sample(const StepView& step, double t, const std::vector<size_t>& live, std::vector<ContactTrace>& traces) {
  const Model& m = step.model;
  State probe{t, {}, step.state.in_play, {}, {}, {}, {}};
  step.state_at(t, probe.x);
  // A traced ball that left play in this step was in play until then (the trace ends where it left).
  for (size_t k : live)
    for (const std::string* body : {&traces[k].a, &traces[k].b})
      if (const int ball = m.ball_index(*body); ball >= 0) probe.in_play[ball] = 1;
  const std::vector<Contact> list = contacts(m, probe);
  for (size_t k : live) {
    ContactTrace& tr = traces[k];
    const int ball = m.ball_index(tr.a);
    for (const Contact& c : list)
      if (matches(c, m, ball, tr.b)) {
        tr.time.push_back(t), tr.force.push_back(c.force.normal), tr.depth.push_back(c.depth);
        break;
      }
  }
}

// In time order without repeats (a step redone to end at an island's regroup is observed twice), and inside the
// contact's located begin and end (a step straddles them).
void tidy(ContactTrace& tr) {
  std::vector<size_t> order(tr.time.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return tr.time[i] < tr.time[j]; });
  std::vector<double> t, f, d;
  for (size_t k : order) {
    const double at = tr.time[k];
    if (at < tr.begin || (tr.end >= 0 && at > tr.end) || (!t.empty() && at <= t.back())) continue;
    t.push_back(at), f.push_back(tr.force[k]), d.push_back(tr.depth[k]);
  }
  tr.time = std::move(t), tr.force = std::move(f), tr.depth = std::move(d);
}

}  // namespace

double ContactTrace::peak_force() const { return force.empty() ? 0 : *std::max_element(force.begin(), force.end()); }
double ContactTrace::max_depth() const { return depth.empty() ? 0 : *std::max_element(depth.begin(), depth.end()); }

ContactTracer::ContactTracer(const Scene& start) {
  Prepared p = prepare(start);
  sim_ = std::make_unique<Simulation>(std::move(p.model), std::move(p.state));
}

ContactTracer::~ContactTracer() = default;

const ContactLog& ContactTracer::extend(const std::vector<Event>& events, double until) {
  // The spans again from every event: those known already come first, in the same order (events only grow), with
  // their samples; a contact's end may have come since.
  std::vector<ContactTrace> spans = contact_spans(events, sim_->model());
  for (size_t k = 0; k < spans.size() && k < log_.contacts.size(); ++k) {
    ContactTrace& old = log_.contacts[k];
    if (old.a != spans[k].a || old.b != spans[k].b || old.begin != spans[k].begin) break;
    spans[k].time = std::move(old.time), spans[k].force = std::move(old.force), spans[k].depth = std::move(old.depth);
  }
  log_.contacts = std::move(spans);
  log_.events = events.size();
  log_.until = std::max(log_.until, until);
  if (log_.contacts.empty()) return log_;  // nothing to trace yet: the run catches up when there is
  std::vector<size_t> live;
  sim_->set_observer([&](const StepView& s) {
    live.clear();
    for (size_t k = 0; k < log_.contacts.size(); ++k) {
      const ContactTrace& tr = log_.contacts[k];
      if (tr.begin > s.t1 || (tr.end >= 0 && tr.end < s.t0)) continue;
      if (s.model.ball_index(tr.a) >= 0) live.push_back(k);
    }
    if (live.empty()) return;
    for (int j = 1; j <= kSamplesPerStep; ++j)
      sample(s, s.t0 + (s.t1 - s.t0) * j / kSamplesPerStep, live, log_.contacts);
  });
  while (sim_->time() < until && sim_->status() == Status::Ok) sim_->advance(std::min(1.0, until - sim_->time()));
  sim_->set_observer(nullptr);
  for (ContactTrace& tr : log_.contacts) tidy(tr);
  return log_;
}

ContactLog trace_contacts(const Scene& start, const std::vector<Event>& events, double until) {
  ContactTracer tracer(start);
  return tracer.extend(events, until);
}

}  // namespace shotlab
