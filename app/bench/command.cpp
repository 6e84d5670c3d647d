// `shotlab bench`: the work-precision report (issue 4). Runs every case with every integrator setting, measures the
// error against a reference solution and the cost, and writes CSV and markdown (bench/report.hpp); the figures are
// drawn from the CSV by scripts/bench_plots.py (app/plot_script.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "app/plot_script.hpp"
#include "app/bench/report.hpp"
#include "app/bench/scaling.hpp"
#include "app/commands.hpp"
#include "app/paths.hpp"
#include "shotlab/io/json_reader.hpp"
#include "shotlab/io/scene_json.hpp"

namespace shotlab {
namespace {

struct BenchOptions {
  bool quick = false;
  bool scaling = false;             // issue 5's scene scaling instead of the sweep (bench/scaling.hpp)
  std::string out_dir = "docs/bench";
  std::vector<std::string> scenes;  // S1..S8, empty: all
  std::vector<std::string> methods;  // method columns (cash_karp54, rigid, ...) to run, empty: all
  int repeats = 0;                  // runs per setting; 0: 5, or 3 with --quick
  double budget = 0;                // s per run; 0: 1 s, or 0.2 s with --quick
};

std::string fmt_seconds(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One setting of one case: the first run gives the results, the repeats only the wall time (the runs are
// deterministic). Returns false when the first run alone took longer than the budget (then the repeats are
// skipped) or did not finish.
bool measure(const std::string& root, const BenchCase& c, const MethodSetting& s, int repeats, double budget,
             const RunResult* ref, BenchReport& report) {
  BenchRow row{&c, s, run_case(root, c, s), {}, 0, 1};
  std::vector<double> walls{row.run.stats.wall_seconds};
  const bool within = row.run.stats.wall_seconds <= budget;
  for (int k = 1; within && k < repeats; ++k) walls.push_back(run_case(root, c, s).stats.wall_seconds);
  row.wall = median(walls);
  row.repeats = static_cast<int>(walls.size());
  if (ref) row.err = errors(c, row.run, *ref, is_adaptive(s.method) ? s.value : 0.0);
  std::ostringstream line;
  line << "  " << c.id << " " << line_name(s) << " " << setting_text(s) << ": ";
  if (ref) line << "error " << std::scientific << std::setprecision(2) << row.err.worst() << std::defaultfloat << ", ";
  line << row.run.stats.steps << " steps, " << row.wall * 1e3 << " ms";
  if (row.run.status != Status::Ok) line << " " << status_name(row.run.status);
  std::cout << line.str() << std::endl;
  report.rows.push_back(std::move(row));
  return within && report.rows.back().run.status == Status::Ok;
}

// The reference run of a case (kReferenceMethods); null, with a note, when no method finishes. When no pair agrees
// to kReferenceAgreement, the closest pair is used and the references table shows how far apart it is.
std::unique_ptr<RunResult> reference(const std::string& root, const BenchCase& c, BenchReport& report) {
  BenchCase plain = c;
  plain.swap_exact = false;  // agreement of two methods, not against the exact answer
  std::unique_ptr<RunResult> best;
  ReferenceInfo info{&c, {}, {}, {}, -1, 0};
  for (double tol : kReferenceTols) {
    std::unique_ptr<RunResult> a;
    MethodSetting a_setting{};
    for (Method m : kReferenceMethods) {
      auto r = std::make_unique<RunResult>(run_case(root, c, {m, tol, true}, true));
      info.wall += r->stats.wall_seconds;
      if (r->status != Status::Ok) continue;
      if (!a) {
        a = std::move(r);
        a_setting = {m, tol, true};
        continue;
      }
      const Errors e = errors(plain, *r, *a);
      if (!best || e.worst() < info.agreement.worst()) {
        info.a = a_setting;
        info.b = {m, tol, true};
        info.agreement = e;
        best = std::make_unique<RunResult>(*a);
      }
      if (e.worst() <= kReferenceAgreement) break;
    }
    if (best && info.agreement.worst() <= kReferenceAgreement) break;
  }
  if (!best) {
    report.notes.push_back(c.id + ": no reference (no two methods finished at 1e-12); case skipped");
    return nullptr;
  }
  if (c.swap_exact) info.exact_velocity = errors(c, *best, *best).velocity;
  report.references.push_back(info);
  return best;
}

void bench_case(const std::string& root, const BenchCase& c, const BenchOptions& o, BenchReport& report) {
  std::cout << c.label << std::endl;
  std::unique_ptr<RunResult> ref;
  if (!c.until_rest && !(ref = reference(root, c, report))) return;
  std::set<std::string> over_budget;  // lines (line_name) whose tighter settings are skipped
  std::map<std::string, int> slow;    // consecutive settings over budget, per line
  // Rosenbrock 4 builds its Jacobian by finite differences, 9n + 1 right-hand sides a step: beyond the cradle's five
  // balls one run takes seconds, the sweep minutes.
  if (ref && ref->radius.size() > 5) {
    over_budget.insert(method_name(Method::Rosenbrock4));
    report.notes.push_back(c.id + ": rosenbrock4 not run (" + std::to_string(ref->radius.size()) +
                           " balls: a finite-difference Jacobian of " + std::to_string(9 * ref->radius.size() + 1) +
                           " right-hand sides a step, about 2 s a run)");
  }
  const std::vector<MethodSetting> settings = c.until_rest ? sweep_timed_only(o.quick) : sweep(o.quick || c.coarse);
  for (size_t k = 0; k < settings.size(); ++k) {
    const MethodSetting& s = settings[k];
    const std::string line = line_name(s);
    if (over_budget.count(line)) continue;
    if (!o.methods.empty() && !std::count(o.methods.begin(), o.methods.end(), method_column(s))) continue;
    if (s.rigid) {  // scenes the rigid model refuses (free space, rods) are left out, and the notes say why
      Scene scene = load_scene(root + "/" + c.file, c.overrides);
      scene.model.options.contact = ContactModel::Rigid;
      try {
        prepare(scene);
      } catch (const std::invalid_argument& e) {
        report.notes.push_back(c.id + ": rigid not run (" + e.what() + ")");
        continue;
      }
    }
    // A whole game (S7, S8) is long by nature: its few settings get ten times the budget.
    const double budget = c.until_rest ? 10 * o.budget : o.budget;
    // One slow setting may be a fluke of the error control (dopri5 at 1e-3 on the break rejects 9 steps in 10);
    // two in a row mean the tighter ones will only be slower.
    slow[line] = measure(root, c, s, o.repeats, budget, ref.get(), report) ? 0 : slow[line] + 1;
    const bool tighter_left = k + 1 < settings.size() && line_name(settings[k + 1]) == line;
    if (slow[line] == 2 && tighter_left) {
      over_budget.insert(line);
      report.notes.push_back(c.id + ": " + line + " stopped after " + setting_text(s) +
                             " (two settings in a row took over " + fmt_seconds(budget) +
                             " s a run or did not finish); tighter settings skipped");
    }
  }
}

// The options a bench cannot start with, as one message naming the option; empty when it can run. The output
// directory is made here, before a run of minutes, so that a bad one fails at once.
std::string check_bench_options(const BenchOptions& o) {
  if (!std::isfinite(o.budget) || o.budget < 0 || o.budget > 3600)
    return "--budget: must be 0 to 3600 s (0: the default), got " + fmt_seconds(o.budget);
  std::set<std::string> known;
  for (const BenchCase& c : bench_cases()) known.insert(c.scene);
  for (const std::string& s : o.scenes)
    if (!known.count(s)) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ",") + k;
      return "--scenes: no bench scene '" + s + "' (the scenes are " + list + ")";
    }
  for (const std::string& m : o.methods) {
    Method parsed;
    if (m != "rigid" && !parse_method(m, parsed))
      return "--methods: no method '" + m + "' (euler, rk4, cash_karp54, dopri5, bulirsch_stoer, rosenbrock4, rigid)";
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec || !std::filesystem::is_directory(o.out_dir))
    return "--out-dir " + o.out_dir + ": cannot make the directory: " + (ec ? ec.message() : "not a directory");
  return "";
}

int run_bench(BenchOptions o, const std::string& command) {
  if (const std::string problem = check_bench_options(o); !problem.empty()) {
    std::cerr << "shotlab bench: " << problem << "\n";
    return 1;
  }
  if (o.budget == 0) o.budget = o.quick ? 0.2 : 1.0;
  if (o.scaling) return run_scaling(o.out_dir, o.repeats) && draw_figures(o.out_dir) ? 0 : 1;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<BenchCase> cases = bench_cases();
  BenchReport report;
  report.command = command;
  try {
    for (const BenchCase& c : cases)
      if (o.scenes.empty() || std::count(o.scenes.begin(), o.scenes.end(), c.scene))
        bench_case(data_root(), c, o, report);
  } catch (const InputError& e) {
    std::cerr << "shotlab bench: " << e.what() << "\n";
    return 1;
  }
  report.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!write_report(o.out_dir, report)) return 1;
  std::cout << "wrote " << o.out_dir << "/results.{csv,md} in " << report.total_seconds << " s\n";
  return draw_figures(o.out_dir) ? 0 : 1;
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Speed against error of every integrator on the bench scenes S1-S8");
  cmd->add_flag("--quick", o->quick, "Whole decades only, short budget: a CI smoke run of under a minute");
  cmd->add_flag("--scaling", o->scaling, "Instead of the sweep: 16, 100 and 1000 resting balls and one moving ball, "
                                        "fast and plain path (writes scaling.csv; figure scaling_scenes.svg)");
  cmd->add_option("--out-dir", o->out_dir, "Directory for results.csv, results.md and the SVG figures (drawn by "
                                        "scripts/bench_plots.py, python3 + matplotlib)");
  cmd->add_option("--scenes", o->scenes, "Scenes to run, e.g. S1,S3 (default: all)")->delimiter(',');
  cmd->add_option("--methods", o->methods, "Methods to run, e.g. cash_karp54,rigid (rigid: the rigid contact model; "
                                           "default: all)")->delimiter(',');
  cmd->add_option("--repeats", o->repeats, "Runs per setting; the wall time is their median "
                                           "(default 5, or 3 with --quick)")->check(CLI::Range(1, 100));
  cmd->add_option("--budget", o->budget, "Seconds one run may take before the method's tighter settings are skipped "
                                         "(default 1, or 0.2 with --quick)")->check(CLI::NonNegativeNumber);
  cmd->callback([o] {
    std::ostringstream command;
    command << "shotlab bench";
    if (o->quick) command << " --quick";
    if (!o->scenes.empty()) {
      command << " --scenes ";
      for (size_t k = 0; k < o->scenes.size(); ++k) command << (k ? "," : "") << o->scenes[k];
    }
    if (o->repeats == 0) o->repeats = o->quick ? 3 : 5;
    command << " --repeats " << o->repeats;
    if (const int code = run_bench(*o, command.str())) throw CLI::RuntimeError(code);
  });
}

}  // namespace shotlab
