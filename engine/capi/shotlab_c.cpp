// The C ABI of libshotlab (engine/include/shotlab.h) over the public C++ engine: handles checked against a registry,
// every exception turned into a status and a message, nothing thrown across the boundary.
#include "shotlab.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

#include "shotlab/cue.hpp"
#include "shotlab/io/run.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/scene.hpp"
#include "shotlab/simulation.hpp"

struct shotlab_sim {
  shotlab::Scene scene;  // as created, with the materials set since
  std::unique_ptr<shotlab::Simulation> sim;
  std::vector<shotlab::Event> pending;  // not yet taken when the simulation was rebuilt
  size_t taken = 0;                     // of sim->events()
  std::string error;
};

namespace {

using namespace shotlab;

std::mutex registry_mutex;
std::unordered_set<const shotlab_sim*> live;
thread_local std::string thread_error;  // of a failed create, or a call on an invalid handle

bool is_live(const shotlab_sim* s) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  return s && live.count(s) > 0;
}

shotlab_status fail(std::string& where, shotlab_status status, const std::string& message) {
  where = message;
  return status;
}

// The status and message of the exception being handled (called inside a catch block).
shotlab_status caught(std::string& where) {
  try {
    throw;
  } catch (const InputError& e) {
    return fail(where, SHOTLAB_ERROR_INPUT, e.what());
  } catch (const std::invalid_argument& e) {
    return fail(where, SHOTLAB_ERROR_ARGUMENT, e.what());
  } catch (const std::exception& e) {
    return fail(where, SHOTLAB_ERROR_INTERNAL, e.what());
  } catch (...) {
    return fail(where, SHOTLAB_ERROR_INTERNAL, "unknown error");
  }
}

// Runs f on a live handle, turning every exception into a status and the handle's message.
template <class F>
shotlab_status guarded(const shotlab_sim* s, F&& f) {
  if (!is_live(s))
    return fail(thread_error, SHOTLAB_ERROR_HANDLE, s ? "sim: not a valid handle (destroyed or never created)"
                                                      : "sim: NULL");
  try {
    return f();
  } catch (...) {
    return caught(const_cast<shotlab_sim*>(s)->error);
  }
}

// The simulation of the handle's scene from its start (a miscue of the scene's cue is its first event).
void restart(shotlab_sim& s) {
  HeadlessRun run = start_run(s.scene);
  s.sim = std::move(run.sim);
  s.pending = std::move(run.extra);
  s.taken = 0;
}

// A new simulation of `scene` from its start.
shotlab_status start(Scene scene, shotlab_sim** out) {
  auto handle = std::make_unique<shotlab_sim>();
  handle->scene = std::move(scene);
  restart(*handle);
  std::lock_guard<std::mutex> lock(registry_mutex);
  *out = handle.release();
  live.insert(*out);
  return SHOTLAB_OK;
}

// Creates through make() (which builds the scene), with the thread's message on failure.
template <class Make>
shotlab_status create(shotlab_sim** out, Make&& make) {
  if (!out) return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, "out: NULL");
  *out = nullptr;
  try {
    return start(make(), out);
  } catch (...) {
    return caught(thread_error);
  }
}

// "name[k]: not finite" for the first of the n numbers at v (may be NULL) that is not, else "".
std::string non_finite(const char* name, const double* v, int n) {
  for (int k = 0; v && k < n; ++k)
    if (!std::isfinite(v[k])) return std::string(name) + "[" + std::to_string(k) + "]: not finite";
  return "";
}

// The simulation goes on from its current state with `model` (the events not yet taken kept).
void rebuild(shotlab_sim& s, Model model, State state) {
  const auto& events = s.sim->events();
  s.pending.insert(s.pending.end(), events.begin() + static_cast<long>(s.taken), events.end());
  s.sim = std::make_unique<Simulation>(std::move(model), std::move(state));
  s.taken = 0;
}

shotlab_status status_of(shotlab_sim& s, Status status) {
  return status == Status::Ok ? SHOTLAB_OK : fail(s.error, SHOTLAB_ERROR_STOPPED, s.sim->diagnostic());
}

void copy_name(char* to, size_t size, const std::string& from) {
  std::strncpy(to, from.c_str(), size - 1);
  to[size - 1] = '\0';
}

}  // namespace

extern "C" {

int shotlab_api_version(void) { return SHOTLAB_API_VERSION; }

const char* shotlab_last_error(const shotlab_sim* sim) {
  if (!sim) return thread_error.c_str();
  return is_live(sim) ? sim->error.c_str() : "the simulation handle is not valid (destroyed or never created)";
}

shotlab_status shotlab_create_from_file(const char* path, shotlab_sim** out) {
  if (!path) return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, "path: NULL");
  return create(out, [&] { return load_scene(path); });
}

shotlab_status shotlab_create_from_json(const char* json, shotlab_sim** out) {
  if (!json) return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, "json: NULL");
  return create(out, [&] { return parse_scene(parse_json_text(json, "scene JSON"), "scene JSON"); });
}

shotlab_status shotlab_create_from_balls(int n, const double* position, const double* velocity, const double* spin,
                                         const double* radius, const double* mass, const char* table,
                                         shotlab_sim** out) {
  if (n < 0 || n > 100000) return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, "n: must be 0 to 100000");
  for (const auto& [name, v] : {std::pair{"position", position}, {"radius", radius}, {"mass", mass}})
    if (n > 0 && !v) return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, std::string(name) + ": NULL");
  for (const auto& [name, v, count] : {std::tuple{"position", position, 3 * n}, {"velocity", velocity, 3 * n},
                                       {"spin", spin, 3 * n}, {"radius", radius, n}, {"mass", mass, n}})
    if (std::string bad = non_finite(name, v, count); !bad.empty())
      return fail(thread_error, SHOTLAB_ERROR_ARGUMENT, bad);
  return create(out, [&] {
    nlohmann::json doc = {{"balls", nlohmann::json::array()}};
    if (table) doc["table"] = {{"type", table}};
    auto vec = [](const double* v, int i) { return nlohmann::json{v[3 * i], v[3 * i + 1], v[3 * i + 2]}; };
    for (int i = 0; i < n; ++i) {
      std::string id = "b";
      id += std::to_string(i);
      nlohmann::json b = {{"id", id}, {"position", vec(position, i)}, {"radius", radius[i]},
                          {"mass", mass[i]}};
      if (velocity) b["velocity"] = vec(velocity, i);
      if (spin) b["angular_velocity"] = vec(spin, i);
      doc["balls"].push_back(b);
    }
    return parse_scene(doc, "balls");
  });
}

void shotlab_destroy(shotlab_sim* sim) {
  {
    std::lock_guard<std::mutex> lock(registry_mutex);
    if (!sim || live.erase(sim) == 0) return;
  }
  delete sim;
}

shotlab_status shotlab_advance(shotlab_sim* sim, double dt) {
  return guarded(sim, [&] {
    if (!std::isfinite(dt) || dt < 0) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "dt: must be a finite time >= 0");
    return status_of(*sim, sim->sim->advance(dt));
  });
}

shotlab_status shotlab_advance_within(shotlab_sim* sim, double dt, double wall_seconds, int go_on) {
  return guarded(sim, [&] {
    if (!std::isfinite(dt) || dt < 0) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "dt: must be a finite time >= 0");
    if (!(wall_seconds >= 0))  // NaN too; infinity is no budget
      return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "wall_seconds: must be a time >= 0");
    return status_of(*sim, sim->sim->advance_within(dt, wall_seconds, go_on == 0));
  });
}

shotlab_status shotlab_reset(shotlab_sim* sim) {
  return guarded(sim, [&] {
    restart(*sim);
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_time(const shotlab_sim* sim, double* seconds) {
  return guarded(sim, [&] {
    if (!seconds) return fail(const_cast<shotlab_sim*>(sim)->error, SHOTLAB_ERROR_ARGUMENT, "seconds: NULL");
    *seconds = sim->sim->time();
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_ball_count(const shotlab_sim* sim, int* count) {
  return guarded(sim, [&] {
    if (!count) return fail(const_cast<shotlab_sim*>(sim)->error, SHOTLAB_ERROR_ARGUMENT, "count: NULL");
    *count = sim->sim->state().ball_count();
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_ball_id(const shotlab_sim* sim, int index, char* id, int capacity) {
  return guarded(sim, [&] {
    std::string& error = const_cast<shotlab_sim*>(sim)->error;
    const auto& balls = sim->sim->model().balls;
    if (index < 0 || static_cast<size_t>(index) >= balls.size())
      return fail(error, SHOTLAB_ERROR_ARGUMENT, "index: " + std::to_string(index) + ", the simulation has " +
                                                   std::to_string(balls.size()) + " balls");
    if (!id) return fail(error, SHOTLAB_ERROR_ARGUMENT, "id: NULL");
    const std::string& name = balls[index].id;
    if (capacity < 0 || static_cast<size_t>(capacity) <= name.size())
      return fail(error, SHOTLAB_ERROR_BUFFER, "capacity: " + std::to_string(capacity) + " bytes, the id needs " +
                                                   std::to_string(name.size() + 1));
    std::memcpy(id, name.c_str(), name.size() + 1);
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_balls(const shotlab_sim* sim, double* position, double* velocity, double* spin, int* in_play,
                             int capacity) {
  return guarded(sim, [&] {
    const State& s = sim->sim->state();
    const int n = s.ball_count();
    if (capacity < 0) return fail(const_cast<shotlab_sim*>(sim)->error, SHOTLAB_ERROR_ARGUMENT, "capacity: below 0");
    if (capacity < n)
      return fail(const_cast<shotlab_sim*>(sim)->error, SHOTLAB_ERROR_BUFFER,
                  "capacity: " + std::to_string(capacity) + " balls, the simulation has " + std::to_string(n));
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        if (position) position[3 * i + k] = s.x[kBallDofs * i + k];
        if (velocity) velocity[3 * i + k] = s.x[kBallDofs * i + 3 + k];
        if (spin) spin[3 * i + k] = s.x[kBallDofs * i + kSpinDof + k];
      }
      if (in_play) in_play[i] = s.in_play[i] ? 1 : 0;
    }
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_events(shotlab_sim* sim, shotlab_event* events, int capacity, int* count) {
  return guarded(sim, [&] {
    if (!count) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "count: NULL");
    if (capacity < 0) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "capacity: below 0");
    const auto& fresh = sim->sim->events();
    const size_t n = sim->pending.size() + (fresh.size() - sim->taken);
    *count = static_cast<int>(n);
    if (static_cast<size_t>(capacity) < n || (n > 0 && !events))
      return fail(sim->error, SHOTLAB_ERROR_BUFFER, "capacity: " + std::to_string(capacity) + " events, " +
                                                        std::to_string(n) + " waiting");
    size_t k = 0;
    auto put = [&](const Event& e) {
      shotlab_event& out = events[k++];
      out.time = e.time;
      copy_name(out.kind, sizeof out.kind, e.kind);
      copy_name(out.body_a, sizeof out.body_a, e.bodies.empty() ? "" : e.bodies[0]);
      copy_name(out.body_b, sizeof out.body_b, e.bodies.size() < 2 ? "" : e.bodies[1]);
    };
    for (const Event& e : sim->pending) put(e);
    for (size_t i = sim->taken; i < fresh.size(); ++i) put(fresh[i]);
    sim->pending.clear();
    sim->taken = fresh.size();
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_set_material(shotlab_sim* sim, const char* pair, const char* field, double value) {
  return guarded(sim, [&] {
    if (sim->sim->status() != Status::Ok) return status_of(*sim, sim->sim->status());  // stays stopped until reset
    if (!pair || !field) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "pair and field: NULL");
    if (!std::isfinite(value)) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "value: not finite");
    nlohmann::json doc = scene_to_json(sim->scene);
    if (!doc["materials"].contains(pair))
      return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, std::string("pair: no material '") + pair + "'");
    nlohmann::json& material = doc["materials"][pair];  // as written, it names every field a material has
    if (!material.contains(field) || !material[field].is_number()) {
      std::string known;
      for (const auto& item : material.items())
        if (item.value().is_number()) known += (known.empty() ? "" : ", ") + item.key();
      return fail(sim->error, SHOTLAB_ERROR_ARGUMENT,
                  std::string("field: no number '") + field + "' in a material (" + known + ")");
    }
    material[field] = value;
    Scene changed = parse_scene(doc, "shotlab_set_material");  // checks the value, naming materials.PAIR.FIELD
    sim->scene.model.materials = changed.model.materials;
    Model model = sim->sim->model();
    model.materials = changed.model.materials;
    rebuild(*sim, std::move(model), sim->sim->state());
    return SHOTLAB_OK;
  });
}

shotlab_status shotlab_strike(shotlab_sim* sim, const char* ball, double speed, double aim, double side, double height,
                              double elevation) {
  return guarded(sim, [&] {
    if (sim->sim->status() != Status::Ok) return status_of(*sim, sim->sim->status());  // stays stopped until reset
    if (!ball) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, "ball: NULL");
    const int i = sim->sim->model().ball_index(ball);
    if (i < 0) return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, std::string("ball: no ball '") + ball + "'");
    if (!sim->sim->state().in_play[i])
      return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, std::string("ball: '") + ball + "' is out of play");
    CueStrike cue;
    cue.ball = ball, cue.speed = speed, cue.aim = aim, cue.side = side, cue.height = height, cue.elevation = elevation;
    if (std::string problem = cue_problem(cue); !problem.empty())  // what a scene's cue may not be either
      return fail(sim->error, SHOTLAB_ERROR_ARGUMENT, problem);
    const BallSpec& b = sim->sim->model().balls[i];
    const StrikeResult r = strike(cue, b.mass, b.radius);
    State state = sim->sim->state();
    set_velocity(state.x, i, r.velocity);
    set_spin(state.x, i, r.spin);
    if (static_cast<size_t>(i) < state.asleep.size()) state.asleep[i] = 0;  // and out of any closed-form regime
    if (static_cast<size_t>(i) < state.rolling_on.size()) state.rolling_on[i] = -1;
    if (static_cast<size_t>(i) < state.sliding_on.size()) state.sliding_on[i] = -1;
    if (static_cast<size_t>(i) < state.still_for.size()) state.still_for[i] = 0;
    const double now = sim->sim->time();
    rebuild(*sim, sim->sim->model(), std::move(state));
    if (r.miscue) sim->pending.push_back({now, "miscue", {ball}});  // as a scene's cue reports it
    return SHOTLAB_OK;
  });
}

}  // extern "C"
