// Calibration against measured shots (docs/fit.md): a shot's simulated centres at the measured times, the residuals
// Ceres minimises, the per-shot fits on growing time windows, then the joint fit with the shared scene values.
#include "shotlab/io/fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>

#include "shotlab/io/json_reader.hpp"
#include "shotlab/io/parallel.hpp"
#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"
#include "csv.hpp"

namespace shotlab {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
// The optimiser works on u = 1 + (value - start) / scale (shared values: value / start), so that its numeric
// derivative steps (1e-4 of u) are 1e-4 m/s, 1e-4 deg, 1e-4 R, 1 us of strike time: small against the paths'
// curvature, large against the integrator's error.
constexpr double kCueScale[] = {1.0, 1.0, 1.0, 1.0, 0.01, 1.0};  // speed, aim_deg, side, height, strike_time, elevation
constexpr double kStepSize = 1e-4;
constexpr double kJointRobust = 0.05;  // m: the joint fit's robust scale (Context::robust)
constexpr int kJointRounds = 6;        // rounds of refits (each but the last followed by a joint fit) at most
constexpr double kFollowed = 0.1;      // m: the joint fit sees each shot while its path is this close (followed())
constexpr double kSideStarts[] = {0.0, -0.3, 0.3, -0.6, 0.6};  // tip offsets tried, the data cannot tell side's sign

// The number at a --set style path of a scene document, or an InputError.
double number_at(const nlohmann::json& doc, const std::string& path) {
  const nlohmann::json* node = &doc;
  std::string key;
  std::istringstream parts(path);
  while (std::getline(parts, key, '.')) {
    if (!node->is_object() || !node->contains(key))
      throw InputError("--fit " + path + ": the scene has no value there (the paths are those of --set)");
    node = &(*node)[key];
  }
  if (!node->is_number()) throw InputError("--fit " + path + ": not a number in the scene");
  return node->get<double>();
}

struct Context {
  const Scene& base;
  nlohmann::json doc;  // base as a document, for the shared values
  const std::vector<MeasuredShot>& shots;
  std::vector<std::string> paths;
  std::vector<double> start;          // shared values at the start
  std::vector<double> fixed;          // shared values while strikes are fitted alone
  std::vector<CueFit> cue_start;      // per shot
  std::vector<std::vector<double>> times;  // per shot: the measured times, sorted, unique
  std::vector<size_t> residuals;      // per shot: 2 per sample
  int cue_params;                     // 5, or 6 with elevation
  const std::atomic<bool>* cancel = nullptr;
  std::function<void()> window_done;  // after each window of a strike fitted alone
  bool cancelled() const { return cancel && *cancel; }
  // s from shot s's first sample to its cue ball's first move: the fit windows are counted from there.
  double lead(size_t s) const { return shots[s].first_move - times[s].front(); }

  CueFit cue(size_t s, const double* u) const {
    const CueFit& c0 = cue_start[s];
    auto v = [&](int k, double x0) { return x0 + (u[k] - 1) * kCueScale[k]; };
    return {v(0, c0.speed), v(1, c0.aim_deg), v(2, c0.side), v(3, c0.height),
            cue_params > 5 ? v(5, c0.elevation_deg) : 0.0, v(4, c0.strike_time)};
  }
  std::vector<double> shared(const double* u) const {
    std::vector<double> out(paths.size());
    for (size_t k = 0; k < paths.size(); ++k) out[k] = start[k] != 0 ? u[k] * start[k] : u[k] - 1;
    return out;
  }
  Scene with(const std::vector<double>& values) const {
    if (paths.empty()) return base;
    nlohmann::json d = doc;
    for (size_t k = 0; k < paths.size(); ++k) apply_override(d, paths[k] + "=" + number_text(values[k]));
    return parse_scene(d, "the fitted scene");
  }
  // Simulated centres of every ball at each measured time up to `window` s after the first sample.
  std::vector<std::vector<Vec3>> simulate(size_t s, const Scene& scene, const CueFit& c, double window) const;
  bool fill(size_t s, const Scene& scene, const CueFit& c, double window, double* r) const;
  double robust = 0;  // m: the scale of the robust weight of fill (0: plain least squares)
};

std::vector<std::vector<Vec3>> Context::simulate(size_t s, const Scene& scene, const CueFit& c, double window) const {
  const MeasuredShot& m = shots[s];
  Prepared p = prepare(measured_scene(scene, m, c));
  Simulation sim(std::move(p.model), std::move(p.state));
  const double t0 = times[s].front();
  std::vector<std::vector<Vec3>> out;
  for (double t : times[s]) {
    if (t - t0 > window) break;
    if (const double tau = t - c.strike_time; tau > sim.time() && sim.status() == Status::Ok) sim.advance(tau - sim.time());
    std::vector<Vec3> at;
    for (int i = 0; i < sim.state().ball_count(); ++i) at.push_back(position(sim.state().x, i));
    out.push_back(std::move(at));
  }
  return out;
}

bool Context::fill(size_t s, const Scene& scene, const CueFit& c, double window, double* r) const {
  std::vector<std::vector<Vec3>> at;
  try {
    at = simulate(s, scene, c, window);
  } catch (const std::exception&) {  // a strike the scene refuses: no step there
    return false;
  }
  const MeasuredShot& m = shots[s];
  size_t k = 0;
  for (size_t b = 0; b < m.balls.size(); ++b)
    for (const MeasuredSample& q : m.tracks.at(m.balls[b])) {
      const size_t i = std::lower_bound(times[s].begin(), times[s].end(), q.t) - times[s].begin();
      const bool in = i < at.size();
      const double dx = in ? at[i][b].x - q.x : 0.0, dz = in ? at[i][b].z - q.z : 0.0, d2 = dx * dx + dz * dz;
      // Cauchy's robust weight: a sample the path has left far behind (after a kiss the model misses) counts as
      // log(1 + d^2 / c^2), not d^2, so that it does not drown the rest of the shot.
      const double w = robust > 0 && d2 > 0 ? std::sqrt(robust * robust * std::log1p(d2 / (robust * robust)) / d2) : 1.0;
      r[k++] = w * dx;
      r[k++] = w * dz;
    }
  return true;
}

// One shot's residuals: params[0] its cue (u), params[1] the shared values (u) when they are fitted.
struct ShotCost {
  const Context* ctx;
  size_t shot;
  double window;
  bool shared_block;
  bool operator()(double const* const* p, double* r) const {
    const Scene scene = ctx->with(shared_block ? ctx->shared(p[1]) : ctx->fixed);
    return ctx->fill(shot, scene, ctx->cue(shot, p[0]), window, r);
  }
};

// A shot's residuals and their central differences, taken as Ceres's numeric differentiation takes them (step
// h = max(sqrt(eps), |x| kStepSize), (f(x + h) - f(x - h)) (1/h) / 2), each column on its own: on `jobs` threads the
// Jacobian comes out bit for bit as on one. The joint fit's threads are these, not Ceres's: Ceres adds its threads'
// shares in the order they finish (ceres-solver issue 664), so its sums differ in the last bits from run to run, and
// a fit of chaotic paths can take another way from there.
class ShotCostFunction final : public ceres::DynamicCostFunction {
 public:
  ShotCostFunction(ShotCost cost, int jobs) : cost_(cost), jobs_(jobs) {}
  bool Evaluate(double const* const* p, double* r, double** jacobians) const override {
    if (!cost_(p, r)) return false;
    if (!jacobians) return true;
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    std::vector<std::pair<size_t, int>> columns;  // (block, index) of each column asked for
    for (size_t b = 0; b < sizes.size(); ++b)
      for (int j = 0; jacobians[b] && j < sizes[b]; ++j) columns.emplace_back(b, j);
    std::atomic<bool> ok{true};
    parallel_in_order(0, columns.size(), jobs_, [&](size_t c) {
      const auto [b, j] = columns[c];
      std::vector<std::vector<double>> x(sizes.size());
      std::vector<const double*> at(sizes.size());
      for (size_t k = 0; k < sizes.size(); ++k) x[k].assign(p[k], p[k] + sizes[k]), at[k] = x[k].data();
      const double h = std::max(std::sqrt(std::numeric_limits<double>::epsilon()), std::abs(p[b][j]) * kStepSize);
      std::vector<double> plus(static_cast<size_t>(num_residuals())), minus(plus.size());
      x[b][j] = p[b][j] + h;
      const bool up = cost_(at.data(), plus.data());
      x[b][j] = p[b][j] - h;
      if (!up || !cost_(at.data(), minus.data())) return void(ok = false);
      const double scale = 1.0 / h / 2;
      for (size_t k = 0; k < plus.size(); ++k) jacobians[b][k * sizes[b] + j] = (plus[k] - minus[k]) * scale;
    });
    return ok;
  }

 private:
  ShotCost cost_;
  int jobs_;
};

ceres::CostFunction* shot_cost(const Context& ctx, size_t s, double window, bool shared_block, int jobs) {
  auto* f = new ShotCostFunction(ShotCost{&ctx, s, window, shared_block}, jobs);
  f->AddParameterBlock(ctx.cue_params);
  if (shared_block) f->AddParameterBlock(static_cast<int>(ctx.paths.size()));
  f->SetNumResiduals(static_cast<int>(ctx.residuals[s]));
  return f;
}

// The earliest strike the cue ball's track allows: the scene starts it where it was first seen, so it was struck after
// the last sample that still shows it there, less the time the slowest strike (0.3 m/s) takes to move it kFirstMove.
double earliest_strike(const MeasuredShot& m) {
  double still = m.tracks.at(m.cue_ball).front().t;
  for (const MeasuredSample& q : m.tracks.at(m.cue_ball))
    if (q.t < m.first_move) still = q.t;
  return still - kFirstMove / 0.3;
}

// Keeps the strike physical: speed 0.3-15 m/s, tip within 0.6 R, elevation 0-60 deg, the strike between the cue
// ball's last still sample and its first moved one.
void bound_cue(ceres::Problem& problem, const Context& ctx, size_t s, double* u) {
  const CueFit& c = ctx.cue_start[s];
  auto bound = [&](int k, double lo, double hi, double v0) {
    problem.SetParameterLowerBound(u, k, 1 + (lo - v0) / kCueScale[k]);
    problem.SetParameterUpperBound(u, k, 1 + (hi - v0) / kCueScale[k]);
  };
  bound(0, 0.3, 15, c.speed);
  bound(2, -0.6, 0.6, c.side);
  bound(3, -0.6, 0.6, c.height);
  bound(4, earliest_strike(ctx.shots[s]), ctx.shots[s].first_move, c.strike_time);
  if (ctx.cue_params > 5) bound(5, 0, 60, c.elevation_deg);
}

// Ends a solve once the caller cancels the fit.
struct CancelCallback : ceres::IterationCallback {
  const std::atomic<bool>* cancel;
  explicit CancelCallback(const std::atomic<bool>* c) : cancel(c) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return cancel && *cancel ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }
};

// One thread (Ceres's default): the threads are the cost functions' (ShotCostFunction).
ceres::Solver::Options solver_options(int iterations, CancelCallback* cancel) {
  ceres::Solver::Options o;
  o.callbacks.push_back(cancel);
  o.linear_solver_type = ceres::DENSE_SCHUR;
  o.max_num_iterations = iterations;
  o.function_tolerance = 1e-7;
  o.logging_type = ceres::SILENT;
  return o;
}

// One shot's cue alone on the first `window` s, parameter `held` (if any) kept; returns the final cost.
double fit_cue(const Context& ctx, size_t s, std::vector<double>& u, double window, int iterations, int held = -1) {
  ceres::Problem problem;
  problem.AddResidualBlock(shot_cost(ctx, s, window, false, 1), nullptr, u.data());
  bound_cue(problem, ctx, s, u.data());
  if (held >= 0) problem.SetManifold(u.data(), new ceres::SubsetManifold(ctx.cue_params, {held}));
  ceres::Solver::Summary summary;
  CancelCallback cancel(ctx.cancel);
  ceres::Solve(solver_options(iterations, &cancel), &problem, &summary);
  return summary.final_cost;
}

// The per-shot fits on windows growing from the first moves to the whole shot, each from the last one's answers. Before
// the first cushion the data cannot tell side from aim (the cue ball's heading is their sum) and a three-cushion path
// has a valley for each sign of side, so the fits carry a beam: at kRestartWindows the best strike is fitted again
// with each tip offset of kSideStarts held (aim and speed take the heading the data shows with it); after the first
// window all of them go on, after later ones up to kBeam distinct strikes within kBeamRatio of the best cost
// (docs/fit.md).
constexpr double kWindows[] = {0.3, 0.6, 1.0, 1.5, 2.0, 3.0, 4.0, 5.5, 7.0, 9.0, 12.0};
constexpr double kRestartWindows[] = {0.3, 1.0, 2.0, 4.0};
constexpr size_t kBeam = std::size(kSideStarts) + 1;
constexpr double kBeamRatio = 2.0;
constexpr int kSide = 2;  // side's place in a strike (kCueScale's order)

using Fitted = std::pair<double, std::vector<double>>;  // a window's final cost, the strike (u)

// The strikes that go on: the best kBeam distinct ones within `ratio` of the best cost, the best always.
std::vector<std::vector<double>> keep_beam(std::vector<Fitted> fitted, double ratio) {
  for (Fitted& f : fitted)
    if (!std::isfinite(f.first)) f.first = INFINITY;  // a strike the scene refused
  std::stable_sort(fitted.begin(), fitted.end(), [](const Fitted& x, const Fitted& y) { return x.first < y.first; });
  std::vector<std::vector<double>> beam;
  for (const auto& [cost, u] : fitted) {
    const bool same = std::any_of(beam.begin(), beam.end(), [&](const std::vector<double>& b) {
      for (size_t k = 0; k < b.size(); ++k)
        if (std::abs(b[k] - u[k]) > 1e-3) return false;
      return true;
    });
    if (beam.empty() || (!same && beam.size() < kBeam && cost <= ratio * fitted.front().first)) beam.push_back(u);
  }
  return beam;
}

std::vector<double> fit_alone(const Context& ctx, size_t s, const std::vector<double>& u0) {
  const double length = ctx.times[s].back() - ctx.times[s].front();
  std::vector<std::vector<double>> beam{u0};
  for (double w : kWindows) {
    const double window = std::min(length, ctx.lead(s) + w);
    std::vector<Fitted> fitted;
    for (std::vector<double> u : beam) {
      const double cost = fit_cue(ctx, s, u, window, 25);
      fitted.emplace_back(cost, u);
    }
    if (std::find(std::begin(kRestartWindows), std::end(kRestartWindows), w) != std::end(kRestartWindows))
      for (double side : kSideStarts) {
        std::vector<double> u = beam.front();
        u[kSide] = 1 + (side - ctx.cue_start[s].side) / kCueScale[kSide];
        const double cost = fit_cue(ctx, s, u, window, 25, kSide);
        fitted.emplace_back(cost, u);
      }
    beam = keep_beam(std::move(fitted), w == kWindows[0] ? INFINITY : kBeamRatio);
    if (ctx.window_done) ctx.window_done();
    if (window >= length || ctx.cancelled()) return beam.front();
  }
  std::vector<double> u = beam.front();
  fit_cue(ctx, s, u, length, 25);
  return u;
}

// Standard deviations of the parameters from the final problem's covariance, scaled by the residuals' variance;
// NaN where the covariance cannot be had (a value the data does not pin down).
void uncertainty(ceres::Problem& problem, const std::vector<double*>& blocks, const std::vector<int>& sizes,
                 double cost, size_t residuals, std::vector<std::vector<double>>& sd) {
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;
  ceres::Covariance cov(co);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (double* b : blocks) pairs.emplace_back(b, b);
  size_t params = 0;
  for (int n : sizes) params += static_cast<size_t>(n);
  const double variance = residuals > params ? 2 * cost / static_cast<double>(residuals - params) : NAN;
  sd.assign(blocks.size(), {});
  const bool ok = cov.Compute(pairs, &problem);
  for (size_t b = 0; b < blocks.size(); ++b) {
    sd[b].assign(static_cast<size_t>(sizes[b]), NAN);
    std::vector<double> m(static_cast<size_t>(sizes[b] * sizes[b]));
    if (ok && cov.GetCovarianceBlock(blocks[b], blocks[b], m.data()))
      for (int k = 0; k < sizes[b]; ++k) sd[b][k] = std::sqrt(std::max(0.0, m[k * sizes[b] + k] * variance));
  }
}

// The part of a shot its fitted path follows: up to the first measured time where some ball is farther than
// kFollowed from its simulated centre. Beyond, a small change of the values flips which side of a ball the path
// passes, and numeric derivatives there say nothing about the values.
double followed(const Context& ctx, size_t s, const Scene& scene, const std::vector<double>& u) {
  const auto at = ctx.simulate(s, scene, ctx.cue(s, u.data()), INFINITY);
  const MeasuredShot& m = ctx.shots[s];
  double until = INFINITY;
  for (size_t b = 0; b < m.balls.size(); ++b)
    for (const MeasuredSample& p : m.tracks.at(m.balls[b])) {
      const size_t i = std::lower_bound(ctx.times[s].begin(), ctx.times[s].end(), p.t) - ctx.times[s].begin();
      if (std::hypot(at[i][b].x - p.x, at[i][b].z - p.z) > kFollowed) {
        until = std::min(until, p.t - ctx.times[s].front());
        break;
      }
    }
  return until;
}

// The plain squared distance, simulated to measured centre, summed over every sample of every shot (m^2).
double squared_error(const Context& ctx, const Scene& scene, const std::vector<std::vector<double>>& cue_u, int threads) {
  std::vector<double> per(ctx.shots.size(), 0.0);
  parallel_in_order(0, ctx.shots.size(), threads, [&](size_t s) {
    std::vector<double> r(ctx.residuals[s]);
    if (!ctx.fill(s, scene, ctx.cue(s, cue_u[s].data()), INFINITY, r.data())) return void(per[s] = INFINITY);
    for (double x : r) per[s] += x * x;
  });
  double sum = 0;
  for (double x : per) sum += x;
  return sum;
}

// Every strike and the shared values together.
// `windows`: per shot, the s of it the joint fit sees (INFINITY: all). A shot followed for less than the first window
// of the fits alone is left out: its few samples would hold neither its strike nor the shared values. `jobs`: threads
// of each shot's differences.
ceres::Problem joint_problem(const Context& ctx, std::vector<std::vector<double>>& cue_u, std::vector<double>& shared_u,
                             const std::vector<double>& windows, int jobs) {
  ceres::Problem problem;
  for (size_t s = 0; s < ctx.shots.size(); ++s) {
    if (windows[s] < ctx.lead(s) + kWindows[0]) continue;
    problem.AddResidualBlock(shot_cost(ctx, s, windows[s], !shared_u.empty(), jobs), nullptr,
                             shared_u.empty() ? std::vector<double*>{cue_u[s].data()}
                                              : std::vector<double*>{cue_u[s].data(), shared_u.data()});
    bound_cue(problem, ctx, s, cue_u[s].data());
  }
  for (size_t k = 0; k < shared_u.size(); ++k) {
    problem.SetParameterLowerBound(shared_u.data(), static_cast<int>(k), ctx.start[k] != 0 ? 0.05 : 1.0);
    problem.SetParameterUpperBound(shared_u.data(), static_cast<int>(k), ctx.start[k] != 0 ? 20.0 : 2.0);
  }
  return problem;
}

// A shot's fitted strike with its deviations, and its simulated centres and errors at the measured times.
ShotFit shot_result(const Context& ctx, size_t s, const Scene& fitted, const std::vector<double>& u,
                    const std::vector<double>& q) {
  const MeasuredShot& m = ctx.shots[s];
  ShotFit f{m.name, m.cue_ball, ctx.cue_start[s], ctx.cue(s, u.data()), {}, {}, {}};
  f.sd = {q[0] * kCueScale[0], q[1] * kCueScale[1], q[2] * kCueScale[2], q[3] * kCueScale[3],
          ctx.cue_params > 5 ? q[5] * kCueScale[5] : NAN, q[4] * kCueScale[4]};
  const auto at = ctx.simulate(s, fitted, f.cue, INFINITY);
  for (size_t b = 0; b < m.balls.size(); ++b) {
    double sum = 0;
    const auto& track = m.tracks.at(m.balls[b]);
    for (const MeasuredSample& p : track) {
      const size_t i = std::lower_bound(ctx.times[s].begin(), ctx.times[s].end(), p.t) - ctx.times[s].begin();
      sum += (at[i][b].x - p.x) * (at[i][b].x - p.x) + (at[i][b].z - p.z) * (at[i][b].z - p.z);
      f.simulated[m.balls[b]].push_back({p.t, at[i][b].x, at[i][b].z});
    }
    f.rms[m.balls[b]] = std::sqrt(sum / static_cast<double>(track.size()));
  }
  return f;
}

}  // namespace

CueFit initial_cue(const Scene& base, const MeasuredShot& m) {
  const std::vector<MeasuredSample>& t = m.tracks.at(m.cue_ball);
  size_t k = 1;
  while (k + 1 < t.size() && std::hypot(t[k].x - t[0].x, t[k].z - t[0].z) <= kFirstMove) ++k;
  const MeasuredSample& a = t[k];
  const MeasuredSample& b = t[std::min(k + 1, t.size() - 1)];
  const double dt = std::max(1e-3, b.t - a.t);
  const double v = std::hypot(b.x - a.x, b.z - a.z) / dt;
  CueFit c;
  c.aim_deg = std::atan2(-(b.z - t[0].z), b.x - t[0].x) / kDeg;  // heading from the start: 0 = +x, 90 = -z
  c.strike_time = std::max(earliest_strike(m), a.t - std::hypot(a.x - t[0].x, a.z - t[0].z) / std::max(v, 0.05));
  const Scene probe = measured_scene(base, m, CueFit{1.0, c.aim_deg, 0, 0, 0, 0});
  const int cue = [&] {
    for (size_t i = 0; i < probe.balls.size(); ++i)
      if (probe.balls[i].spec.id == m.cue_ball) return static_cast<int>(i);
    return 0;
  }();
  const StrikeResult unit = strike(*probe.cue, probe.balls[cue].spec.mass, probe.balls[cue].spec.radius);
  c.speed = std::clamp(v / std::max(1e-6, glm::length(unit.velocity)), 0.3, 15.0);
  return c;
}

Scene measured_scene(const Scene& base, const MeasuredShot& m, const CueFit& c) {
  Scene s = base;
  s.rack.reset();
  s.balls.clear();
  for (const std::string& id : m.balls) {
    InitialBall b;
    b.spec = base.balls.empty() ? BallSpec{id, 0.21, 0.03075} : base.balls.front().spec;
    for (const InitialBall& known : base.balls)
      if (known.spec.id == id) b.spec = known.spec;
    b.spec.id = id;
    const MeasuredSample& first = m.tracks.at(id).front();
    b.position = {first.x, b.spec.radius, first.z};
    s.balls.push_back(b);
  }
  CueStrike cue = base.cue.value_or(CueStrike{});
  cue.ball = m.cue_ball;
  cue.speed = c.speed, cue.aim = c.aim_deg * kDeg, cue.side = c.side, cue.height = c.height;
  cue.elevation = c.elevation_deg * kDeg;
  s.cue = cue;
  s.duration = m.tracks.at(m.cue_ball).back().t - c.strike_time + 1;
  return s;
}

FitResult fit_measured(const Scene& base, const std::vector<MeasuredShot>& shots, const FitSettings& settings) {
  const auto t0 = std::chrono::steady_clock::now();
  Context ctx{base, scene_to_json(base), shots, settings.paths, {}, {}, {}, {}, {}, settings.elevation ? 6 : 5, nullptr, {}};
  for (const std::string& p : settings.paths) ctx.start.push_back(number_at(ctx.doc, p));
  for (const MeasuredShot& m : shots) {
    ctx.cue_start.push_back(initial_cue(base, m));
    std::vector<double> t;
    size_t n = 0;
    for (const auto& [ball, track] : m.tracks)
      for (const MeasuredSample& q : track) t.push_back(q.t), n += 2;
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    ctx.times.push_back(std::move(t));
    ctx.residuals.push_back(n);
  }
  auto say = [&](const std::string& line) { if (settings.log) settings.log(line); };
  std::vector<std::vector<double>> cue_u(shots.size(), std::vector<double>(ctx.cue_params, 1.0));
  std::vector<double> shared_u(settings.paths.size(), 1.0);
  ceres::Solver::Summary summary;
  std::string report = settings.paths.empty() ? "no joint fit: no shared values (each strike fitted alone)"
                                              : "no joint fit: no shot followed far enough to tell the shared values";
  int iterations = 0;
  size_t residuals = 0;
  for (size_t s = 0; s < shots.size(); ++s) residuals += ctx.residuals[s];
  // Rounds: every strike alone on growing windows with the shared values as they are, then all together on what the
  // paths follow; a strike fitted under the old values can sit in another valley, so the strikes are refitted after
  // each joint fit, while a round lowers the whole shots' squared error by 1 %. The best round is kept.
  double best = INFINITY;  // the whole shots' plain squared error after the best round, which is kept
  std::vector<std::vector<double>> best_cue;
  std::vector<double> best_shared;
  ctx.cancel = settings.cancel;
  std::atomic<size_t> windows_done{0};
  const size_t windows_total = shots.size() * std::size(kWindows);
  ctx.window_done = [&] {
    if (settings.progress) settings.progress(std::min(windows_total, ++windows_done), windows_total);
  };
  for (int round = 0; round < kJointRounds && !ctx.cancelled(); ++round) {
    windows_done = 0;
    ctx.fixed = ctx.shared(shared_u.data());
    ctx.robust = 0;
    parallel_in_order(0, shots.size(), settings.threads, [&](size_t s) { cue_u[s] = fit_alone(ctx, s, cue_u[s]); },
                      [&](size_t s) { say(shots[s].name + ": cue strike fitted alone"); });
    const double error = squared_error(ctx, ctx.with(ctx.fixed), cue_u, settings.threads);
    say("round " + std::to_string(round + 1) + ": squared error " + number_text(error) + " m^2");
    const bool gained = error < 0.99 * best;
    if (error < best) best = error, best_cue = cue_u, best_shared = shared_u;
    if (!gained || settings.paths.empty() || round + 1 == kJointRounds) break;  // a joint fit is always judged
    ctx.robust = kJointRobust;
    std::vector<double> windows(shots.size(), INFINITY);
    const Scene now = ctx.with(ctx.fixed);
    parallel_in_order(0, shots.size(), settings.threads, [&](size_t s) { windows[s] = followed(ctx, s, now, cue_u[s]); });
    ceres::Problem problem = joint_problem(ctx, cue_u, shared_u, windows, settings.threads);
    if (problem.NumResidualBlocks() == 0) break;  // no shot is followed far enough to tell the shared values
    CancelCallback cancel(settings.cancel);
    ceres::Solve(solver_options(settings.max_iterations, &cancel), &problem, &summary);
    iterations += std::max(0, static_cast<int>(summary.iterations.size()) - 1);  // Ceres lists its start as 0
    report = summary.BriefReport();
    say("joint fit, round " + std::to_string(round + 1) + ": " + report);
  }
  if (!best_cue.empty()) cue_u = best_cue, shared_u = best_shared;  // empty: cancelled before a round ended
  ctx.robust = 0;  // the uncertainties and errors below are those of plain least squares, on the whole shots
  ceres::Problem problem =
      joint_problem(ctx, cue_u, shared_u, std::vector<double>(shots.size(), INFINITY), settings.threads);

  std::vector<double*> blocks;
  std::vector<int> sizes;
  for (auto& u : cue_u) blocks.push_back(u.data()), sizes.push_back(ctx.cue_params);
  if (!shared_u.empty()) blocks.push_back(shared_u.data()), sizes.push_back(static_cast<int>(shared_u.size()));
  // The residuals' variance from the kept values' own cost: the last joint round's was of its robust loss over the
  // followed windows, and a strike fitted alone has none.
  double cost = NAN;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr);
  std::vector<std::vector<double>> sd;
  uncertainty(problem, blocks, sizes, cost, residuals, sd);

  FitResult r;
  r.paths = settings.paths, r.start = ctx.start, r.values = ctx.shared(shared_u.data());
  for (size_t k = 0; k < r.paths.size(); ++k)
    r.sd.push_back(sd.back()[k] * (ctx.start[k] != 0 ? std::abs(ctx.start[k]) : 1.0));
  const Scene fitted = ctx.with(r.values);
  for (size_t s = 0; s < shots.size(); ++s) r.shots.push_back(shot_result(ctx, s, fitted, cue_u[s], sd[s]));
  r.iterations = iterations;
  r.report = ctx.cancelled() ? "cancelled" : report;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

Scene fitted_scene(const Scene& base, const FitResult& fit) {
  nlohmann::json doc = scene_to_json(base);
  for (size_t k = 0; k < fit.paths.size(); ++k) apply_override(doc, fit.paths[k] + "=" + number_text(fit.values[k]));
  return parse_scene(doc, "the fitted scene");
}

}  // namespace shotlab
