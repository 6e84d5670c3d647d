#include "shotlab/io/measured.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "shotlab/io/json_reader.hpp"

namespace shotlab {
namespace {

constexpr size_t kMaxMeasuredBytes = size_t{64} << 20;

double number(const std::string& field, const std::string& where, const char* name) {
  double v = 0;
  const char* first = field.data();
  const auto [end, ec] = std::from_chars(first, first + field.size(), v);
  if (field.empty() || ec != std::errc() || end != first + field.size() || !std::isfinite(v))
    throw InputError(where + ": " + name + ": not a finite number: " + describe(nlohmann::json(field)));
  return v;
}

// A CSV line's fields as RFC 4180 writes them (and csv_field, for a trajectory's ball ids): a quoted field may hold
// commas, and a doubled quote inside it is one quote.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"') out.back() += c, ++k;
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else if (c != '\r') out.back() += c;
  }
  return out;
}

}  // namespace

MeasuredShot parse_measured(const std::string& text, const std::string& source) {
  MeasuredShot shot;
  shot.name = std::filesystem::path(source).stem().string();
  std::istringstream in(text);
  std::string line;
  // The columns by name: a tracker's time,ball,x,z, or a trajectory `shotlab run` wrote (its other columns unread).
  const std::vector<std::string> header = std::getline(in, line) ? split(line) : std::vector<std::string>{};
  size_t col[4];
  const char* names[] = {"time", "ball", "x", "z"};
  for (int k = 0; k < 4; ++k) {
    col[k] = static_cast<size_t>(std::find(header.begin(), header.end(), names[k]) - header.begin());
    if (col[k] == header.size())
      throw InputError(source + ": line 1: the header names no column '" + names[k] +
                       "' (a measured shot has time,ball,x,z; other columns are left unread)");
  }
  const std::string fields = std::to_string(header.size());
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.empty() || line == "\r") continue;
    const std::string where = source + ": line " + std::to_string(n);
    const std::vector<std::string> f = split(line);
    if (f.size() != header.size())
      throw InputError(where + ": expected " + fields + " fields, as the header has, got " + std::to_string(f.size()));
    const std::string& ball = f[col[1]];
    if (ball.empty()) throw InputError(where + ": ball: empty");
    const MeasuredSample s{number(f[col[0]], where, "time"), number(f[col[2]], where, "x"),
                           number(f[col[3]], where, "z")};
    auto& track = shot.tracks[ball];
    if (track.empty()) shot.balls.push_back(ball);
    else if (s.t < track.back().t)
      throw InputError(where + ": time: " + f[col[0]] + " s comes before the ball's previous sample");
    track.push_back(s);
  }
  if (shot.balls.size() < 2) throw InputError(source + ": fewer than two balls tracked");
  shot.first_move = INFINITY;
  for (const auto& [ball, track] : shot.tracks)
    for (const MeasuredSample& s : track)
      if (std::hypot(s.x - track[0].x, s.z - track[0].z) > kFirstMove) {
        if (s.t < shot.first_move) shot.first_move = s.t, shot.cue_ball = ball;
        break;
      }
  if (shot.cue_ball.empty()) throw InputError(source + ": no ball moves: nothing to fit");
  return shot;
}

MeasuredShot read_measured(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path)) throw InputError(path + ": cannot open the file");
  std::string text(kMaxMeasuredBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxMeasuredBytes) throw InputError(path + ": larger than 64 MiB, not a measured shot");
  return parse_measured(text, path);
}

}  // namespace shotlab
