// Text of the CSV files the engine writes (trajectories, sweep rows): fields and numbers spelled one way.
#pragma once
#include <charconv>
#include <string>

namespace shotlab {

// A field as RFC 4180 writes it: quoted (quotes doubled) when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The shortest text that reads back to the same double.
inline std::string number_text(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

}  // namespace shotlab
