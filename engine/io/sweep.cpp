// Sweep runs: each row a headless run of the scene with its overrides, reduced to one CSV line; rows on a pool of
// threads, handed on in row order.
#include "shotlab/io/sweep.hpp"

#include <chrono>
#include <map>
#include <sstream>

#include "shotlab/io/json_reader.hpp"
#include "shotlab/io/parallel.hpp"
#include "shotlab/io/scene_json.hpp"
#include "csv.hpp"

namespace shotlab {
namespace {

constexpr double kSweepSampleRate = 60;  // Hz: how often a run checks for rest and its limits

// What a run's events say: contacts counted, pockets in order, the cue ball's first contacts.
struct EventSummary {
  size_t ball_contacts = 0, cushion_contacts = 0;
  std::string pocketed, first_contact, first_ball;
};

EventSummary summarise(const Simulation& sim, const std::string& cue_ball) {
  std::map<std::string, bool> is_ball;
  for (const BallSpec& b : sim.model().balls) is_ball[b.id] = true;
  EventSummary out;
  for (const Event& e : sim.events()) {
    if (e.kind == "pocketed" && e.bodies.size() == 2)
      out.pocketed += (out.pocketed.empty() ? "" : " ") + e.bodies[0] + "@" + e.bodies[1];
    if (e.kind != "contact_begin" || e.bodies.size() != 2) continue;
    const bool balls = is_ball.count(e.bodies[0]) && is_ball.count(e.bodies[1]);
    out.ball_contacts += balls;
    out.cushion_contacts += e.bodies[1].rfind("cushion", 0) == 0;
    if (e.bodies[0] != cue_ball && e.bodies[1] != cue_ball) continue;
    const std::string& other = e.bodies[0] == cue_ball ? e.bodies[1] : e.bodies[0];
    if (out.first_contact.empty() && other != "bed") out.first_contact = other;
    if (out.first_ball.empty() && balls) out.first_ball = other;
  }
  return out;
}

// The columns after the run's status: what the run ended with. Empty fields where it never started.
std::string outcome(const Simulation& sim, const std::vector<std::string>& ball_ids, const std::string& cue_ball) {
  const EventSummary ev = summarise(sim, cue_ball);
  const Stats& st = sim.stats();
  std::ostringstream row;
  row << number_text(sim.time()) << ',' << st.steps << ',' << st.rhs_evaluations << ',' << sim.events().size() << ','
      << ev.ball_contacts << ',' << ev.cushion_contacts << ',' << csv_field(ev.pocketed) << ',' << csv_field(ev.first_contact)
      << ',' << csv_field(ev.first_ball);
  const State& s = sim.state();
  for (const std::string& id : ball_ids) {
    int i = 0;
    while (i < s.ball_count() && sim.model().balls[i].id != id) ++i;
    if (i == s.ball_count()) {
      row << ",,,,";
      continue;
    }
    const Vec3 p = position(s.x, i);
    row << ',' << number_text(p.x) << ',' << number_text(p.y) << ',' << number_text(p.z) << ','
        << motion_name(sim.motion(i));
  }
  return row.str();
}

}  // namespace

Sweep::Sweep(const std::string& scene_text, const std::string& source, SweepPlan plan, SweepSettings settings)
    : doc_(parse_json_text(scene_text, source)), source_(source), plan_(std::move(plan)), settings_(std::move(settings)) {
  for (const std::string& o : settings_.overrides) apply_override(doc_, o);
  const Scene scene = parse_scene(doc_, settings_.overrides.empty() ? source : source + " (with --set overrides)");
  if (settings_.duration && !(*settings_.duration > 0 && *settings_.duration <= kMaxDuration))
    throw InputError("--duration: must be a number of seconds above 0 and at most " + number_text(kMaxDuration));
  // A path whose last name the format does not have (a misspelt field) fails every run alike: refused here, with the
  // nearest name, rather than as rows of errors. Its values are tried in the runs (a bad one fails only its rows).
  for (size_t a = 0; a < plan_.paths.size() && !plan_.rows.empty(); ++a) try {
      nlohmann::json doc = doc_;
      apply_override(doc, plan_.paths[a] + "=" + plan_.rows[0][a]);
      parse_scene(doc, source_);
    } catch (const UnknownFieldError& e) {
      const std::string& path = plan_.paths[a];
      if (path == e.name || path.ends_with("." + e.name)) throw InputError("--vary " + path + ": " + e.what());
    } catch (const InputError&) {  // a value the scene refuses: that row's error
    }
  for (const InitialBall& b : scene.balls) ball_ids_.push_back(b.spec.id);
  cue_ball_ = scene.cue ? scene.cue->ball : ball_ids_.empty() ? "" : ball_ids_[0];
}

std::string Sweep::header() const {
  std::string h = "run";
  for (const std::string& p : plan_.paths) h += ',' + csv_field(p);
  h += ",status,reason,wall_seconds,time,steps,rhs_evaluations,events,ball_contacts,cushion_contacts,pocketed,"
       "first_contact,first_ball";
  for (const std::string& id : ball_ids_)
    for (const char* c : {".x", ".y", ".z", ".motion"}) h += ',' + csv_field(id + c);
  return h + '\n';
}

std::string Sweep::row(size_t i) const {
  std::string head = std::to_string(i);
  for (const std::string& v : plan_.rows[i]) head += ',' + csv_field(v);
  const auto start = std::chrono::steady_clock::now();
  auto wall = [&] {
    return number_text(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  try {
    nlohmann::json doc = doc_;
    for (size_t a = 0; a < plan_.paths.size(); ++a) apply_override(doc, plan_.paths[a] + "=" + plan_.rows[i][a]);
    const Scene scene = parse_scene(doc, source_ + " (run " + std::to_string(i) + ")");
    HeadlessRun run = start_run(scene);
    const std::string limit = advance_run(*run.sim, run_duration(scene, settings_.duration, true), kSweepSampleRate,
                                          true, {}, settings_.limits);
    const Simulation& sim = *run.sim;
    const std::string status = !limit.empty() ? "limit" : sim.status() == Status::Ok ? "ok" : status_name(sim.status());
    const std::string reason = !limit.empty() ? limit : sim.diagnostic();
    return head + ',' + status + ',' + csv_field(reason) + ',' + wall() + ',' + outcome(sim, ball_ids_, cue_ball_) + '\n';
  } catch (const std::exception& e) {  // bad overrides (InputError), memory: the row says so, the sweep goes on
    std::string empty(9 + 4 * ball_ids_.size(), ',');
    return head + ",error," + csv_field(e.what()) + ',' + wall() + ',' + empty.substr(1) + '\n';
  }
}

std::string Sweep::status(const std::string& line) const {
  size_t field = 0;
  std::string text;
  bool quoted = false;
  for (size_t k = 0; k < line.size(); ++k) {  // RFC 4180: "" inside quotes is one quote
    const char c = line[k];
    if (c == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"') text += line[++k];
    else if (c == '"') quoted = !quoted;
    else if (c != ',' || quoted) text += c;
    else if (field++ == 1 + plan_.paths.size()) return text;
    else text.clear();
  }
  return text;
}

void Sweep::run(size_t begin, size_t end, int jobs, const std::function<void(size_t, const std::string&)>& on_row,
                const std::function<void(size_t, size_t)>& progress, const std::atomic<bool>* cancel) const {
  end = std::min(end, size());
  if (begin >= end) return;
  std::vector<std::string> lines(end - begin);
  parallel_in_order(
      begin, end, jobs, [&](size_t i) { lines[i - begin] = row(i); },
      [&](size_t i) {
        on_row(i, lines[i - begin]);
        std::string().swap(lines[i - begin]);  // a long sweep keeps only the rows not yet handed on
      },
      progress, cancel);
}

}  // namespace shotlab
