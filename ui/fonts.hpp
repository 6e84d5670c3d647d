// The fonts the shot lab draws with (Debian's fonts-dejavu-core): the interface, and the numerals on the balls.
#pragma once

namespace shotlab {

inline constexpr const char* kUiFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr const char* kNumeralFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

}  // namespace shotlab
