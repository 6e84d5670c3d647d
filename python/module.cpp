// The Python module `shotlab` (pybind11, numpy) over the engine's public headers: scenes from a file, JSON text or a
// dict with --set style overrides, a Simulation to advance and read as numpy arrays, and run() returning what
// `shotlab run --out` writes. docs/python.md.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/io/result_json.hpp"
#include "shotlab/io/run.hpp"
#include "shotlab/io/scene_json.hpp"

namespace py = pybind11;
using namespace shotlab;

namespace {

// A scene from a path, JSON text (starting with '{') or a dict, with PATH=VALUE overrides as --set takes them.
Scene load(const py::object& scene, const std::vector<std::string>& overrides) {
  nlohmann::json doc;
  std::string source = "scene";
  if (py::isinstance<py::dict>(scene)) {
    doc = nlohmann::json::parse(py::module_::import("json").attr("dumps")(scene).cast<std::string>());
  } else {
    const std::string text = scene.cast<std::string>();
    if (text.find_first_not_of(" \t\r\n") != std::string::npos && text[text.find_first_not_of(" \t\r\n")] == '{') {
      doc = parse_json_text(text, "scene JSON");
    } else {
      return load_scene(text, overrides);  // a path
    }
  }
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

struct PySimulation {
  HeadlessRun run;
  PySimulation(const py::object& scene, const std::vector<std::string>& overrides) : run(start_run(load(scene, overrides))) {}
  Simulation& sim() { return *run.sim; }
};

}  // namespace

PYBIND11_MODULE(shotlab, m) {
  m.doc() = "shotlab: billiard-ball physics (docs/python.md)";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PySimulation>(m, "Simulation")
      .def(py::init<const py::object&, const std::vector<std::string>&>(), py::arg("scene"),
           py::arg("overrides") = std::vector<std::string>{},
           "A simulation of a scene: a file path, JSON text or a dict; overrides as PATH=VALUE strings")
      .def("advance", [](PySimulation& s, double dt) {
        if (!(dt >= 0)) throw py::value_error("dt: must be a time >= 0 s");
        const Status status = s.sim().advance(dt);
        if (status != Status::Ok) throw std::runtime_error(s.sim().diagnostic());
      }, py::arg("dt"), "Moves the clock by dt seconds; raises RuntimeError with the diagnostic if the run stops")
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
        for (const Event& e : s.sim().events()) out.append(py::dict(py::arg("time") = e.time, py::arg("kind") = e.kind,
                                                                    py::arg("bodies") = e.bodies));
        return out;
      })
      .def_property_readonly("stats", [](PySimulation& s) { return to_python(result_to_json(s.sim())["stats"]); })
      .def("result", [](PySimulation& s) { return to_python(result_to_json(s.sim(), s.run.extra)); },
           "What `shotlab run --out` writes for the simulation as it is now");

  m.def("run", [](const py::object& scene, const std::vector<std::string>& overrides, std::optional<double> duration,
                  bool until_rest, double sample_rate) {
    const Scene s = load(scene, overrides);
    const double d = duration.value_or(s.duration);
    if (!(d > 0) || d > kMaxDuration) throw py::value_error("duration: must be above 0 and at most 3600 s");
    if (!(sample_rate > 0)) throw py::value_error("sample_rate: must be above 0");
    HeadlessRun run = start_run(s);
    {
      py::gil_scoped_release release;  // other Python threads run while the engine does
      advance_run(*run.sim, d, sample_rate, until_rest);
    }
    return to_python(result_to_json(*run.sim, run.extra));
  }, py::arg("scene"), py::arg("overrides") = std::vector<std::string>{}, py::arg("duration") = py::none(),
     py::arg("until_rest") = false, py::arg("sample_rate") = 60.0,
     "Runs a scene headless as `shotlab run` does and returns what `shotlab run --out` writes, as a dict");
}
