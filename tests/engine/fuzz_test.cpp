// The project's own fuzzer: presets mutated at random (values of every kind put at random places, fields removed,
// bytes of the text changed) and random --set assignments. Every input is either refused with an InputError or
// simulated for a moment; nothing else may happen: no other exception, no crash, no hang (CI runs it under ASan and
// UBSan too). SHOTLAB_FUZZ_SEED and SHOTLAB_FUZZ_CASES choose the run (default: seed 1, 300 cases of each kind); a
// longer run: docs/testing.md.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include "support.hpp"

namespace shotlab::test {
namespace {

using nlohmann::json;

unsigned env_number(const char* name, unsigned fallback) {
  const char* v = std::getenv(name);
  return v && *v ? static_cast<unsigned>(std::strtoul(v, nullptr, 10)) : fallback;
}

struct Fuzzer {
  std::mt19937_64 rng{env_number("SHOTLAB_FUZZ_SEED", 1)};
  std::vector<json> presets;

  Fuzzer() {
    for (const auto& e : std::filesystem::directory_iterator(std::string(SHOTLAB_SOURCE_DIR) + "/presets"))
      if (e.path().extension() == ".json") presets.push_back(json::parse(std::ifstream(e.path())));
  }
  size_t pick(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); }

  json value() {
    static const std::vector<json> odd = {
        0, -1, 1, 1e308, -1e308, 1e-320, 2147483648LL, -2147483649LL, 1e19, 0.5, true, nullptr, "", "x", "\xff\xfe",
        "rk4", "pool", "linear", json::array(), json::array({1, 2}), json::array({0, 0, 0}), json::array({1e308, 0, 0}),
        json::object(), json::object({{"id", 1}}), json::array({json::array({json::array()})})};
    return odd[pick(odd.size())];
  }

  // Every place in the document: (parent, key or index).
  void places(json& j, std::vector<std::pair<json*, json>>& out) {
    if (j.is_object()) {
      for (auto& [k, v] : j.items()) {
        out.push_back({&j, k});
        places(v, out);
      }
    } else if (j.is_array()) {
      for (size_t i = 0; i < j.size(); ++i) {
        out.push_back({&j, i});
        places(j[i], out);
      }
    }
  }

  json mutated() {
    json doc = presets[pick(presets.size())];
    for (int n = 1 + static_cast<int>(pick(3)); n > 0; --n) {
      std::vector<std::pair<json*, json>> where;
      places(doc, where);
      if (where.empty()) break;
      auto [parent, key] = where[pick(where.size())];
      const bool remove = pick(4) == 0;
      if (parent->is_object()) {
        if (remove) parent->erase(key.get<std::string>());
        else (*parent)[key.get<std::string>()] = value();
      } else {
        if (remove) parent->erase(key.get<size_t>());
        else (*parent)[key.get<size_t>()] = value();
      }
    }
    return doc;
  }

  std::string mangled_text() {
    std::string text = presets[pick(presets.size())].dump(1);
    for (int n = 1 + static_cast<int>(pick(4)); n > 0; --n) {
      const size_t at = pick(text.size());
      switch (pick(3)) {
        case 0: text[at] = static_cast<char>(pick(256)); break;
        case 1: text.erase(at, 1 + pick(8)); break;
        default: text.insert(at, std::string("[{\"9e999,\xff-").substr(pick(8), 1 + pick(3))); break;
      }
      if (text.empty()) break;
    }
    return text;
  }

  std::string assignment(const json& doc) {
    static const std::vector<std::string> paths = {
        "duration", "balls[0].mass", "balls[0].position", "balls.cue.velocity", "balls[99].id", "rack.rows",
        "rack.seed", "materials.ball_ball.stiffness", "integrator.method", "integrator.max_steps_per_call",
        "table.length", "cue.speed", "cue.side", "rods[0].length", ".", "a..b", "balls[-1]", "gravity"};
    static const std::vector<std::string> values = {
        "1", "-1", "0", "1e400", "nan", "[1,2,3]", "[1,2]", "{}", "{bad", "\"s\"", "rk4", "null", "true",
        "18446744073709551616", "\xff", "[[[[[[1]]]]]]", "1e-400", "{\"a\":1,\"a\":2}"};
    (void)doc;
    return paths[pick(paths.size())] + "=" + values[pick(values.size())];
  }
};

// Simulates a scene that loaded for a moment, with a bounded step count: the engine may stop with a status, never
// crash.
void simulate_briefly(Scene s) {
  s.model.integrator.max_steps_per_call = std::min(s.model.integrator.max_steps_per_call, 5000);
  try {
    validate(s);
  } catch (const std::invalid_argument&) {
    return;  // refused before it runs, with a message (the GUI shows it)
  }
  Prepared p = prepare(s);
  Simulation sim(std::move(p.model), std::move(p.state));
  sim.advance(0.02);
  (void)sim.status();
}

TEST(Fuzz, MutatedScenesAreRefusedOrSimulated) {
  Fuzzer f;
  const unsigned cases = env_number("SHOTLAB_FUZZ_CASES", 300);
  unsigned refused = 0, simulated = 0;
  for (unsigned k = 0; k < cases; ++k) {
    const json doc = f.mutated();
    SCOPED_TRACE(doc.dump(-1, ' ', false, json::error_handler_t::replace).substr(0, 400));
    try {
      simulate_briefly(parse_scene(doc, "fuzz"));
      ++simulated;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << k << ": " << e.what();
    }
  }
  std::cout << "fuzz scenes: " << cases << " cases, " << refused << " refused, " << simulated << " simulated\n";
}

TEST(Fuzz, MangledTextIsRefusedOrRead) {
  Fuzzer f;
  const unsigned cases = env_number("SHOTLAB_FUZZ_CASES", 300);
  unsigned refused = 0;
  for (unsigned k = 0; k < cases; ++k) {
    const std::string text = f.mangled_text();
    try {
      parse_scene(parse_json_text(text, "fuzz"), "fuzz");
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << k << ": " << e.what();
    }
  }
  std::cout << "fuzz text: " << cases << " cases, " << refused << " refused\n";
}

TEST(Fuzz, SetAssignmentsAreRefusedOrApplied) {
  Fuzzer f;
  const unsigned cases = env_number("SHOTLAB_FUZZ_CASES", 300);
  unsigned refused = 0;
  for (unsigned k = 0; k < cases; ++k) {
    json doc = f.presets[f.pick(f.presets.size())];
    const std::string set = f.assignment(doc);
    SCOPED_TRACE(set);
    try {
      apply_override(doc, set);
      parse_scene(doc, "fuzz");
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << k << ": " << e.what();
    }
  }
  std::cout << "fuzz --set: " << cases << " cases, " << refused << " refused\n";
}

}  // namespace
}  // namespace shotlab::test
