// Tuning > Measured shot (developers): the measured shot loaded from CSV (Open... in Scene and files lists .csv files),
// the fit of its strike and of chosen materials with progress and Cancel, and how far the fitted paths stay from
// the tracked balls. The tracks are drawn over the table (overlay.cpp).
#include <imgui.h>

#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

void measured_section(Lab& lab) {
  MeasuredView& v = lab.measured;
  lab.apply_fit();
  if (!v.shot) {
    text_wrapped("Open a measured shot (a CSV of time,ball,x,z; docs/fit.md) with Open... in Scene and files: "
                       "its tracked balls are drawn as dots, and its cue strike can be fitted here.");
    return;
  }
  size_t samples = 0;
  for (const auto& [ball, track] : v.shot->tracks) samples += track.size();
  text_wrapped("%s: %zu balls, %zu samples; the cue ball is %s.", v.shot->name.c_str(), v.shot->balls.size(),
                     samples, v.shot->cue_ball.c_str());
  ImGui::TextUnformatted("fit the strike and also:");
  for (int k = 0; k < kLabFitValues; ++k) {
    if (k % 2) same_line_if_fits(kLabFitPaths[k][1]);
    ImGui::Checkbox(kLabFitPaths[k][1], &v.fit_value[k]);
  }
  if (v.fit.busy()) {
    ImGui::ProgressBar(static_cast<float>(v.fit.progress()), ImVec2(-1, 0), "fitting...");
    if (ImGui::Button("Cancel fit")) v.fit.cancel();
    mark("Cancel fit");
  } else {
    ImGui::BeginDisabled(lab.shot != nullptr);
    if (ImGui::Button("Fit the strike")) lab.start_fit();
    mark("Fit the strike");
    ImGui::EndDisabled();
    if (lab.shot) hint("back to aiming (Undo) to fit");
  }
  readout("fit progress", v.fit.busy() ? v.fit.progress() : v.last ? 1.0 : 0.0);
  if (!v.fit.error().empty()) coloured_wrapped(ImVec4(1, 0.5f, 0.4f, 1), "%s", v.fit.error().c_str());
  if (!v.last || v.last->shots.empty()) return;
  const ShotFit& f = v.last->shots[0];
  text_wrapped("fitted: %.3f m/s, aim %.2f deg, side %+.2f R, height %+.2f R", f.cue.speed, f.cue.aim_deg, f.cue.side,
               f.cue.height);
  for (const auto& [ball, rms] : f.rms) {
    ImGui::BulletText("%s: %.0f mm from the tracked centres (rms)", ball.c_str(), rms * 1e3);
    readout("fit rms " + ball, rms);
  }
  for (size_t k = 0; k < v.last->paths.size(); ++k)
    ImGui::BulletText("%s: %.4g -> %.4g", v.last->paths[k].c_str(), v.last->start[k], v.last->values[k]);
}

}  // namespace shotlab
