// The engine's behaviour, pinned bit for bit: every preset (frames of 1/60 s until rest, as the shot lab runs them)
// and every bench case with a spread of integrator settings on the fast and the plain path, each reduced to one hash
// of its end state, regime flags, events and step counts. A change of structure must leave every hash as it is;
// a commit that changes the model on purpose updates tests/app/behaviour_hashes.txt and says why:
//   SHOTLAB_UPDATE_HASHES=1 ./build/tests/app_tests --gtest_filter='Behaviour.*'
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "app/bench/cases.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {
namespace {

const std::string kRoot = SHOTLAB_SOURCE_DIR;
const std::string kHashFile = kRoot + "/tests/app/behaviour_hashes.txt";

// FNV-1a over the bytes of what the run produced.
struct Hash {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    for (size_t k = 0; k < n; ++k) h = (h ^ static_cast<const unsigned char*>(p)[k]) * 1099511628211ull;
  }
  template <class T> void add(const T& v) { bytes(&v, sizeof v); }
  template <class T> void add(const std::vector<T>& v) {
    add(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }
  void add(const std::string& s) {
    add(s.size());
    bytes(s.data(), s.size());
  }
};

std::string digest(const Simulation& sim) {
  Hash h;
  const State& s = sim.state();
  h.add(s.time);
  h.add(s.x);
  h.add(s.in_play);
  h.add(s.asleep);
  h.add(s.rolling_on);
  h.add(s.sliding_on);
  h.add(s.still_for);
  h.add(static_cast<int>(sim.status()));
  h.add(sim.events().size());
  for (const Event& e : sim.events()) {
    h.add(e.time);
    h.add(e.kind);
    for (const std::string& b : e.bodies) h.add(b);
  }
  const Stats& st = sim.stats();
  for (long n : {st.steps, st.rejected_steps, st.redone_steps, st.rhs_evaluations}) h.add(n);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h.h));
  return text;
}

// A preset as the shot lab runs it: frames of 1/60 s until every ball rests, or the scene's duration.
std::string run_preset(const std::string& path) {
  Prepared p = prepare(load_scene(path));
  const double duration = load_scene(path).duration;
  Simulation sim(std::move(p.model), std::move(p.state));
  while (sim.time() < duration && sim.status() == Status::Ok && !sim.at_rest()) sim.advance(1.0 / 60);
  return digest(sim);
}

std::string run_bench_case(const BenchCase& c, const MethodSetting& setting) {
  Scene scene = load_scene(kRoot + "/" + c.file, c.overrides);
  scene.model.integrator = integrator_options(setting);
  if (setting.plain) use_path(scene.model.options, SolverPath::Plain);
  Prepared p = prepare(scene);
  Simulation sim(std::move(p.model), std::move(p.state));
  if (c.until_rest)
    while (sim.time() < scene.duration && sim.status() == Status::Ok && !sim.at_rest()) sim.advance(1.0 / 60);
  else
    sim.advance(scene.duration);
  return digest(sim);
}

// Every run's name and hash.
std::map<std::string, std::string> measure() {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(kRoot + "/presets"))
    if (e.path().extension() == ".json") out["preset " + e.path().stem().string()] = run_preset(e.path().string());
  const std::vector<MethodSetting> settings = {
      {Method::CashKarp54, 1e-7},           {Method::CashKarp54, 1e-7, true}, {Method::DormandPrince5, 1e-6},
      {Method::DormandPrince5, 1e-6, true}, {Method::BulirschStoer, 1e-6},    {Method::Rosenbrock4, 1e-6},
      {Method::RK4, 1e-5},            {Method::Euler, 1e-5},            {Method::CashKarp54, 1e-9},
      {Method::DormandPrince5, 1e-9}};
  for (const BenchCase& c : bench_cases())
    for (const MethodSetting& s : settings) {
      if (c.until_rest && (s.plain || !is_adaptive(s.method) || s.method == Method::Rosenbrock4)) continue;
      char value[32];
      std::snprintf(value, sizeof value, "%g", s.value);
      out["bench " + c.id + " " + line_name(s) + " " + value] = run_bench_case(c, s);
    }
  return out;
}

TEST(Behaviour, EveryRunIsBitIdenticalToItsRecordedHash) {
  const std::map<std::string, std::string> now = measure();
  if (const char* update = std::getenv("SHOTLAB_UPDATE_HASHES"); update && *update) {
    std::ofstream out(kHashFile);
    for (const auto& [name, hash] : now) out << hash << " " << name << "\n";
    GTEST_SKIP() << "wrote " << now.size() << " hashes to " << kHashFile;
  }
  std::map<std::string, std::string> recorded;
  std::ifstream in(kHashFile);
  for (std::string line; std::getline(in, line);)
    if (line.size() > 17) recorded[line.substr(17)] = line.substr(0, 16);
  ASSERT_FALSE(recorded.empty()) << "no hashes in " << kHashFile;
  for (const auto& [name, hash] : now) {
    const auto it = recorded.find(name);
    if (it == recorded.end()) ADD_FAILURE() << name << ": no recorded hash";
    else EXPECT_EQ(hash, it->second) << name << ": the run changed";
  }
  EXPECT_EQ(now.size(), recorded.size()) << "runs recorded but no longer made";
}

}  // namespace
}  // namespace shotlab
