// Where text_wrapped (widgets.hpp) breaks a paragraph into lines: plain logic over a measure of width, so that it
// is tested without a window.
#pragma once
#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace shotlab {

// A unit that stays on the line of the number before it ("1.23 s" never ends one line and starts the next).
inline bool is_unit(std::string_view w) {
  static constexpr std::string_view kUnits[] = {"s", "ms", "\xc2\xb5s", "\xc2\xb5m", "m",   "mm",  "cm", "m/s", "rad/s",
                                                "deg", "N", "J", "kg", "g", "Hz", "fps", "%", "x", "N/m", "1/s", "rad"};
  if (!w.empty() && std::ispunct(static_cast<unsigned char>(w.back())) && w.back() != '%') w.remove_suffix(1);
  for (std::string_view u : kUnits)
    if (w == u) return true;
  return false;
}

// The lines of `paragraph` for a line `width` wide, `wide` measuring a piece: broken at spaces (which go), never
// between a number and its unit; a word wider than the line is a line of its own.
template <class Wide>
std::vector<std::string_view> wrap_paragraph(std::string_view paragraph, float width, Wide&& wide) {
  std::vector<std::string_view> lines;
  size_t line = 0, end = 0, before = 0;  // the line so far: paragraph[line, end); its end before the last word
  for (size_t word = 0; word <= paragraph.size();) {
    const size_t word_end = std::min(paragraph.find(' ', word), paragraph.size());
    const bool unit = word >= 2 && std::isdigit(static_cast<unsigned char>(paragraph[word - 2])) &&
                      is_unit(paragraph.substr(word, word_end - word));
    if (end > line && wide(paragraph.substr(line, word_end - line)) > width) {
      const size_t cut = unit && before > line ? before : end;  // a unit goes to the next line with its number
      lines.push_back(paragraph.substr(line, cut - line));
      line = paragraph.find_first_not_of(' ', cut);
      line = line == std::string_view::npos ? paragraph.size() : line;
    }
    before = end;
    end = word_end;
    word = word_end + 1;
  }
  lines.push_back(paragraph.substr(line, end - line));
  return lines;
}

}  // namespace shotlab
