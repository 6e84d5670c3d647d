// The Python module `shotlab` (pybind11, numpy) over the engine's public headers: scenes from a file, JSON text or a
// dict with --set style overrides, a Simulation to advance and read as numpy arrays, and run() returning what
// `shotlab run --out` writes. docs/python.md.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/io/result_json.hpp"
#include "shotlab/io/run.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/io/sweep.hpp"

namespace py = pybind11;
using namespace shotlab;

namespace {

// A dict's value as JSON: numbers (numpy's too, and numpy arrays as lists), strings, booleans, None, lists and
// tuples, dicts with string keys. A non-finite number, an integer past 64 bits and nesting deeper than a scene file
// may have are InputErrors, anything else a TypeError, naming `path`.
nlohmann::json to_json(const py::handle& v, const std::string& path, int depth = 0) {
  if (depth > kMaxJsonDepth)
    throw InputError("scene: " + path + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  // Kept for the process (a static py::object would be released after the interpreter is gone).
  static const py::handle numpy_bool = py::object(py::module_::import("numpy").attr("bool_")).release();
  if (v.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(v) || py::isinstance(v, numpy_bool))
    return py::bool_(py::reinterpret_borrow<py::object>(v)).cast<bool>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::dict>(v)) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, item] : v.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw py::type_error("scene: " + path + ": a key that is not a string");
      const std::string k = key.cast<std::string>();
      out[k] = to_json(item, path.empty() ? k : path + "." + k, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) || py::isinstance<py::array>(v)) {
    const py::object items = py::isinstance<py::array>(v) ? v.attr("tolist")() : py::reinterpret_borrow<py::object>(v);
    if (!py::isinstance<py::list>(items) && !py::isinstance<py::tuple>(items)) return to_json(items, path, depth);
    nlohmann::json out = nlohmann::json::array();
    size_t k = 0;
    for (const auto& item : items) out.push_back(to_json(item, path + "[" + std::to_string(k++) + "]", depth + 1));
    return out;
  }
  if (py::isinstance<py::int_>(v) || (py::hasattr(v, "__index__") && py::hasattr(v, "__float__"))) {
    const py::int_ i = py::module_::import("operator").attr("index")(v);
    if (i < py::int_(std::numeric_limits<long long>::min()) || i > py::int_(std::numeric_limits<long long>::max()))
      throw InputError("scene: " + path + ": the integer " + std::string(py::str(py::object(i))) + " is past 64 bits");
    return i.cast<long long>();
  }
  if (py::hasattr(v, "__float__") && !py::isinstance<py::bytes>(v)) {  // float, numpy.float64, ...
    const double x = py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
    if (!std::isfinite(x)) throw InputError("scene: " + path + ": must be a finite number, got " + std::to_string(x));
    return x;
  }
  throw py::type_error("scene: " + path + ": a " + py::str(py::type::of(v).attr("__name__")).cast<std::string>() +
                       " is not a scene value (numbers, strings, booleans, None, lists and dicts are)");
}

// A scene's JSON text and the name its messages use, from a path (str or os.PathLike), JSON text (starting with '{')
// or a dict; anything else is a TypeError.
std::pair<std::string, std::string> scene_text(const py::object& scene) {
  if (py::isinstance<py::dict>(scene)) return {to_json(scene, "").dump(), "scene"};
  if (py::hasattr(scene, "__fspath__")) {  // a pathlib.Path
    const std::string path = py::str(py::module_::import("os").attr("fspath")(scene)).cast<std::string>();
    return {read_scene_file(path), path};
  }
  if (py::isinstance<py::bytes>(scene) || !py::isinstance<py::str>(scene))
    throw py::type_error("scene: a path, JSON text or a dict, got " +
                         py::str(py::type::of(scene).attr("__name__")).cast<std::string>());
  const std::string text = scene.cast<std::string>();
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return {text, "scene JSON"};
  return {read_scene_file(text), text};
}

// A scene from a path, JSON text or a dict, with PATH=VALUE overrides as --set takes them.
Scene load(const py::object& scene, const std::vector<std::string>& overrides) {
  const auto [text, source] = scene_text(scene);
  nlohmann::json doc = parse_json_text(text, source);
  for (const std::string& o : overrides) apply_override(doc, o);
  return parse_scene(doc, overrides.empty() ? source : source + " (with overrides)");
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

// n x 3 array of one of a ball's three vectors (0: position, 3: velocity, 6: spin).
py::array_t<double> vectors(const Simulation& sim, int offset) {
  const State& s = sim.state();
  py::array_t<double> out({static_cast<py::ssize_t>(s.ball_count()), static_cast<py::ssize_t>(3)});
  auto a = out.mutable_unchecked<2>();
  for (int i = 0; i < s.ball_count(); ++i)
    for (int k = 0; k < 3; ++k) a(i, k) = s.x[kBallDofs * i + offset + k];
  return out;
}

// A sweep as Python holds it: what made it (so that it pickles to Dask's workers, which rebuild the plan) and the
// sweep itself.
struct PySweep {
  std::string text, source;
  std::vector<std::string> vary, overrides;
  size_t samples;
  uint64_t seed;
  std::optional<double> duration;
  double timeout;
  size_t max_events;
  std::unique_ptr<Sweep> sweep;

  void build() {
    std::vector<SweepAxis> axes;
    for (const std::string& v : vary) axes.push_back(parse_sweep_axis(v));
    if (!(timeout > 0)) throw InputError("timeout: must be a number of seconds above 0");
    sweep = std::make_unique<Sweep>(text, source, plan_sweep(axes, samples, seed),
                                    SweepSettings{overrides, duration, {timeout, max_events, {}}});
  }
  py::tuple state() const {
    return py::make_tuple(SHOTLAB_PY_VERSION, text, source, vary, overrides, samples, seed, duration, timeout, max_events);
  }
  static PySweep from_state(const py::tuple& t) {
    const std::string version = t.size() == 10 ? t[0].cast<std::string>() : "unknown";
    if (version != SHOTLAB_PY_VERSION)
      throw std::runtime_error("a sweep from shotlab " + version + " on shotlab " SHOTLAB_PY_VERSION
                               ": install the same version on the client and every worker");
    PySweep s{t[1].cast<std::string>(), t[2].cast<std::string>(), t[3].cast<std::vector<std::string>>(),
              t[4].cast<std::vector<std::string>>(), t[5].cast<size_t>(), t[6].cast<uint64_t>(),
              t[7].cast<std::optional<double>>(), t[8].cast<double>(), t[9].cast<size_t>(), nullptr};
    s.build();
    return s;
  }
  std::vector<std::string> lines(size_t begin, std::optional<size_t> end, int jobs) const {
    if (jobs < 0) throw py::value_error("jobs: 0 (one thread per core) or more, got " + std::to_string(jobs));
    std::vector<std::string> out;
    py::gil_scoped_release release;  // the engine runs while other Python threads (Dask's) do
    sweep->run(begin, end.value_or(sweep->size()), jobs, [&](size_t, const std::string& line) { out.push_back(line); });
    return out;
  }
};

struct PySimulation {
  HeadlessRun run;
  PySimulation(const py::object& scene, const std::vector<std::string>& overrides) : run(start_run(load(scene, overrides))) {}
  Simulation& sim() { return *run.sim; }
};

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "shotlab's engine (the package shotlab re-exports it; docs/python.md)";
  m.attr("version") = SHOTLAB_PY_VERSION;
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PySimulation>(m, "Simulation")
      .def(py::init<const py::object&, const std::vector<std::string>&>(), py::arg("scene"),
           py::arg("overrides") = std::vector<std::string>{},
           "A simulation of a scene: a file path, JSON text or a dict; overrides as PATH=VALUE strings")
      .def("advance", [](PySimulation& s, double dt) {
        const Status status = s.sim().advance(dt);
        if (status != Status::Ok) throw std::runtime_error(s.sim().diagnostic());
      }, py::arg("dt"), "Moves the clock by dt seconds; raises RuntimeError with the diagnostic if the run stops")
      .def("advance_within", [](PySimulation& s, double dt, double wall_seconds, bool go_on) {
        if (!(wall_seconds >= 0)) throw py::value_error("wall_seconds: must be a time >= 0");
        const Status status = s.sim().advance_within(dt, wall_seconds, !go_on);
        if (status != Status::Ok) throw std::runtime_error(s.sim().diagnostic());
        return s.sim().time();
      }, py::arg("dt"), py::arg("wall_seconds"), py::arg("go_on") = false,
           "As advance, but it may stop short once wall_seconds of wall time have passed (one step at least), for a "
           "loop that draws frames; returns the time reached. The step limit counts from this call, or with go_on "
           "on from the last")
      .def("at_rest", [](PySimulation& s) { return s.sim().at_rest(); })
      .def_property_readonly("time", [](PySimulation& s) { return s.sim().time(); })
      .def_property_readonly("ids", [](PySimulation& s) {
        std::vector<std::string> ids;
        for (const BallSpec& b : s.sim().model().balls) ids.push_back(b.id);
        return ids;
      })
      .def_property_readonly("positions", [](PySimulation& s) { return vectors(s.sim(), 0); }, "n x 3, m")
      .def_property_readonly("velocities", [](PySimulation& s) { return vectors(s.sim(), 3); }, "n x 3, m/s")
      .def_property_readonly("spins", [](PySimulation& s) { return vectors(s.sim(), kSpinDof); }, "n x 3, rad/s")
      .def_property_readonly("in_play", [](PySimulation& s) {
        const auto& in = s.sim().state().in_play;
        py::array_t<bool> out(static_cast<py::ssize_t>(in.size()));
        auto a = out.mutable_unchecked<1>();
        for (size_t i = 0; i < in.size(); ++i) a(static_cast<py::ssize_t>(i)) = in[i] != 0;
        return out;
      })
      .def_property_readonly("events", [](PySimulation& s) {
        py::list out;
        auto put = [&](const Event& e) {
          out.append(py::dict(py::arg("time") = e.time, py::arg("kind") = e.kind, py::arg("bodies") = e.bodies));
        };
        for (const Event& e : s.run.extra) put(e);  // a miscue at the strike, which the engine does not make
        for (const Event& e : s.sim().events()) put(e);
        return out;
      })
      .def_property_readonly("stats", [](PySimulation& s) { return to_python(result_to_json(s.sim())["stats"]); })
      .def("result", [](PySimulation& s) { return to_python(result_to_json(s.sim(), s.run.extra)); },
           "What `shotlab run --out` writes for the simulation as it is now");

  m.def("run", [](const py::object& scene, const std::vector<std::string>& overrides, std::optional<double> duration,
                  bool until_rest, double sample_rate) {
    const Scene s = load(scene, overrides);
    const double d = run_duration(s, duration, until_rest);
    if (!(d > 0) || d > kMaxDuration) throw py::value_error("duration: must be above 0 and at most 3600 s");
    if (!(sample_rate > 0)) throw py::value_error("sample_rate: must be above 0");
    HeadlessRun run = start_run(s);
    {
      py::gil_scoped_release release;  // other Python threads run while the engine does
      advance_run(*run.sim, d, sample_rate, until_rest);
    }
    if (std::string why = unfinished_rest(*run.sim, until_rest); !why.empty()) {
      why += " (a longer duration runs on to rest)";
      if (PyErr_WarnEx(PyExc_RuntimeWarning, why.c_str(), 1) != 0) throw py::error_already_set();  // warnings as errors
    }
    return to_python(result_to_json(*run.sim, run.extra));
  }, py::arg("scene"), py::arg("overrides") = std::vector<std::string>{}, py::arg("duration") = py::none(),
     py::arg("until_rest") = false, py::arg("sample_rate") = 60.0,
     "Runs a scene headless as `shotlab run` does and returns what `shotlab run --out` writes, as a dict");

  py::class_<PySweep>(m, "Sweep")
      .def(py::init([](const py::object& scene, const std::vector<std::string>& vary, size_t samples, uint64_t seed,
                       const std::vector<std::string>& overrides, std::optional<double> duration, double timeout,
                       size_t max_events) {
             auto [text, source] = scene_text(scene);
             PySweep s{text, source, vary, overrides, samples, seed, duration, timeout, max_events, nullptr};
             s.build();
             return s;
           }),
           py::arg("scene"), py::arg("vary"), py::arg("samples") = 0, py::arg("seed") = 1,
           py::arg("overrides") = std::vector<std::string>{}, py::arg("duration") = py::none(),
           py::arg("timeout") = 60.0, py::arg("max_events") = 100000,
           "A sweep as `shotlab sweep` makes it: vary as PATH=VALUES strings, samples 0 for the grid")
      .def("__len__", [](const PySweep& s) { return s.sweep->size(); })
      .def_property_readonly("header", [](const PySweep& s) { return s.sweep->header(); }, "the CSV header line")
      .def("lines", &PySweep::lines, py::arg("begin") = 0, py::arg("end") = py::none(), py::arg("jobs") = 0,
           "Runs rows [begin, end) on `jobs` threads (0: one per core); their CSV lines in row order")
      .def(py::pickle([](const PySweep& s) { return s.state(); }, &PySweep::from_state));
}
