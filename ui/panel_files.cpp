// Scenes and files: the presets (with what each shows), recent files, a file browser, Save and Save as (a shipped
// preset is never overwritten: Save offers Save as), the trajectory export, and the export naming shared by the
// plots and pictures.
#include <imgui.h>
#include <imgui_internal.h>  // BringWindowToDisplayFront: the plot drawn for its picture goes over the panels
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "shotlab/io/result_json.hpp"
#include "shotlab/io/scene_json.hpp"
#include "ui/files.hpp"
#include "ui/panels.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace fs = std::filesystem;

namespace {

struct PresetEntry {
  std::string path, name, description;
};

// The presets folder, read once: each preset's name and its "what to look for" text, by name.
const std::vector<PresetEntry>& presets(const std::string& data_root) {
  static const std::vector<PresetEntry> list = [&] {
    std::vector<PresetEntry> out;
    for (const DirEntry& e : list_scene_dir(data_root + "/presets")) {
      if (e.folder) continue;
      // Absolute, as Lab::load keeps the scene's path: the preset shown is found by comparing the two.
      std::error_code ec;
      const fs::path file = fs::path(data_root) / "presets" / e.name, abs = fs::absolute(file, ec);
      PresetEntry p{(ec ? file : abs).lexically_normal().string(), fs::path(e.name).stem().string(), ""};
      try {
        const Scene s = load_scene(p.path);
        p.name = s.name.empty() ? p.name : s.name;
        p.description = s.description;
      } catch (const std::exception& err) {
        p.description = err.what();
      }
      out.push_back(p);
    }
    // In the order of the names shown (a file's name may differ: cradle.json is "Newton's cradle").
    auto lower = [](std::string t) {
      for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return t;
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](const PresetEntry& a, const PresetEntry& b) { return lower(a.name) < lower(b.name); });
    return out;
  }();
  return list;
}

// A folder listing with .json scenes and .csv measured shots: click a folder to enter it, a file to open it, or type
// a path. It starts in the folder of the scene shown (or the user's, for a preset), and each folder opens at its top.
void browser_popup(Lab& lab, std::string& dir) {
  ImGui::SetNextWindowSize(ImVec2(em(460), em(400)), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal("Open scene file", nullptr)) return;
  static std::string typed;
  if (ImGui::IsWindowAppearing()) typed.clear(), ImGui::SetKeyboardFocusHere();  // a path can be typed at once
  ImGui::SetNextItemWidth(-em(150));
  const bool enter = ImGui::InputTextWithHint("##path", "type a path, or pick below", &typed,
                                              ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  mark("open path");
  ImGui::SameLine();
  if ((ImGui::Button("Open") || enter) && !typed.empty()) {
    std::error_code ec;
    const std::string path = typed_path(typed, dir);
    if (fs::is_directory(path, ec)) dir = path, typed.clear();
    else if (lab.load(path)) typed.clear(), ImGui::CloseCurrentPopup();  // a bad file: its message, popup stays
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  text_wrapped("%s", dir.c_str());
  if (ImGui::Button("Up")) dir = fs::path(dir).parent_path().string();
  ImGui::SameLine();
  if (ImGui::Button("Presets")) dir = lab.data_root + "/presets";
  ImGui::SameLine();
  if (ImGui::Button("Home")) dir = user_folder({}, "");
  // Under the list, in room kept for it: above, a load error pushed every entry down a row under the pointer, and the
  // next click opened the file below the one that failed.
  const bool failed = lab.message_kind == MessageKind::LoadError;
  const float below = failed ? -3.2f * ImGui::GetTextLineHeightWithSpacing() : 0.0f;
  ImGui::BeginChild(("entries " + dir).c_str(), ImVec2(0, below), true);  // one child a folder: each its own scroll
  for (const DirEntry& e : list_scene_dir(dir)) {
    const std::string label = e.folder ? "[" + e.name + "]" : e.name;
    const bool picked = ImGui::Selectable(label.c_str());
    mark("browse " + e.name);
    if (picked) {
      const std::string path = (fs::path(dir) / e.name).string();
      if (e.folder) dir = path;
      else if (lab.load(path)) ImGui::CloseCurrentPopup();
    }
  }
  ImGui::EndChild();
  if (failed) coloured_wrapped(ImVec4(1, 0.6f, 0.4f, 1), "%s", lab.message.c_str());  // wrapped: it names the path
  ImGui::EndPopup();
}

bool save_to(Lab& lab, const std::string& path) {
  try {
    save_scene(path, lab.scene);
    lab.scene_path = path;
    lab.loaded = lab.scene;  // the file now holds these values: the list of changes starts again from them
    remember_file(lab.settings, path);
    lab.say(MessageKind::Note, "saved " + path);
    return true;
  } catch (const std::exception& e) {
    lab.say(MessageKind::Refused, e.what());
    return false;
  }
}

// Save as: a path box (a relative path is taken inside `folder`, the one it proposes). Replacing a file that exists
// takes the Replace button or a second Return (a habitual Return wrote over a coach's drill); a folder that does not
// exist yet is made. A failed save keeps the dialog and the name typed, the error under the box.
void save_as_popup(Lab& lab, std::string& typed, const std::string& folder) {
  static std::string armed;  // the path a first Return over an existing file armed for replacing
  static std::string failed;  // why the last save from here failed
  if (!ImGui::BeginPopupModal("Save scene as", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    armed.clear();
    return;
  }
  // The folder a relative name is taken in, up front: after a save there it is the scene's, and "drills/mine" typed
  // again went into drills/drills.
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + em(420));
  ImGui::Text("File (a .json scene; a relative name is taken in %s):", folder.c_str());
  ImGui::PopTextWrapPos();
  ImGui::SetNextItemWidth(em(420));
  const bool enter = ImGui::InputText("##saveas", &typed, ImGuiInputTextFlags_EnterReturnsTrue);
  mark("save path");
  if (ImGui::IsItemEdited()) failed.clear(), armed.clear();
  const std::string path = scene_file_path(typed, folder);
  const fs::path parent = fs::path(path).parent_path();
  std::error_code ec;
  const bool folder_typed = !path.empty() && fs::is_directory(path, ec);
  const bool exists = !path.empty() && fs::exists(path, ec);
  const bool new_folder = !path.empty() && !parent.empty() && !fs::exists(parent, ec);
  const bool preset = inside(path, lab.data_root + "/presets");
  const bool blocked = path.empty() || preset || folder_typed;
  const bool arm = enter && !blocked && exists && armed != path;
  if (arm) {
    armed = path;
    ImGui::SetKeyboardFocusHere(-1);  // Return ended the entry: the box takes the second Return
  }
  const ImVec4 warn(1, 0.7f, 0.3f, 1);
  if (folder_typed) coloured_wrapped(warn, "that is a folder: add a file name");
  else if (preset) coloured_wrapped(warn, "that is a shipped preset: choose another name");
  else if (exists && armed == path)
    coloured_wrapped(warn, "Return again, or Replace, writes over the file that exists");
  else if (exists) coloured_wrapped(ImVec4(1, 0.8f, 0.4f, 1), "a file of that name exists: Replace writes over it");
  else if (new_folder) coloured_wrapped(ImVec4(1, 0.8f, 0.4f, 1), "the folder %s does not exist yet: Save makes it",
                                        parent.string().c_str());
  if (!path.empty() && !folder_typed) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + em(420));  // a long path wraps under the box, not past the window
    ImGui::TextDisabled("saves %s", path.c_str());
    ImGui::PopTextWrapPos();
  }
  if (!failed.empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + em(420));
    ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", failed.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::BeginDisabled(blocked);
  const bool clicked = ImGui::Button(exists ? "Replace" : "Save");
  mark("save button");
  if (clicked || (enter && !blocked && !arm && (!exists || armed == path))) {
    if (new_folder) fs::create_directories(parent, ec);
    if (ec) lab.say(MessageKind::Refused, failed = "cannot make the folder " + parent.string() + ": " + ec.message());
    else if (!save_to(lab, path)) failed = lab.message;
    else failed.clear(), armed.clear(), ImGui::CloseCurrentPopup();
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    failed.clear(), armed.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

// The name a first save suggests: the file's, or the scene's where it became another there (Set up break on the cut
// preset: "break", not "cut"), in letters, digits, '-' and '_'.
std::string save_stem(const Lab& lab) {
  if (lab.scene.name.empty() || lab.scene.name == lab.loaded.name)
    return lab.scene_path.empty() ? "scene" : fs::path(lab.scene_path).stem().string();
  std::string stem;
  for (char c : lab.scene.name)
    stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? static_cast<char>(std::tolower(c)) : '_';
  return stem;
}

void preset_combo(Lab& lab) {
  const Fields f({"preset", "recent"});
  f.label("preset");
  // The preset the scene came from, or what it became there (Set up break on the cut preset shows "break").
  std::string current = "choose...";
  for (const PresetEntry& p : presets(lab.data_root))
    if (lab.scene_path == p.path) current = lab.scene.name.empty() ? p.name : lab.scene.name;
  if (ImGui::BeginCombo("##preset", current.c_str(), ImGuiComboFlags_HeightLarge)) {
    for (const PresetEntry& p : presets(lab.data_root)) {
      if (ImGui::Selectable(p.name.c_str(), lab.scene_path == p.path)) lab.load(p.path);
      if (ImGui::IsItemHovered() && !p.description.empty()) ImGui::SetTooltip("%s", p.description.c_str());
    }
    ImGui::EndCombo();
  }
  mark("preset combo");
  f.label("recent");
  if (ImGui::BeginCombo("##recent", lab.settings.recent.empty() ? "none yet" : "open again...")) {
    const std::vector<std::string> recent = lab.settings.recent;  // load() reorders the list
    for (const std::string& r : recent)
      if (ImGui::Selectable(r.c_str())) lab.load(r);
    ImGui::EndCombo();
  }
}

}  // namespace

void scene_section(Lab& lab) {
  preset_combo(lab);
  static std::string browse_dir;
  const std::string presets_dir = lab.data_root + "/presets";
  const bool shipped = lab.scene_path.empty() || inside(lab.scene_path, presets_dir);
  const std::string folder =
      shipped ? user_folder(lab.settings.recent, presets_dir) : fs::path(lab.scene_path).parent_path().string();
  if (ImGui::Button("Open...")) {
    browse_dir = folder;
    if (lab.message_kind == MessageKind::LoadError) lab.say(MessageKind::None, "");  // the popup shows the next one
    ImGui::OpenPopup("Open scene file");
  }
  mark("Open...");
  browser_popup(lab, browse_dir);
  same_line_if_fits("Save");
  static std::string save_path;
  const std::string stem = save_stem(lab);
  const std::string mine = (fs::path(folder) / (stem + "-mine.json")).string();
  if (ImGui::Button("Save")) {
    if (shipped) {
      save_path = mine;
      ImGui::OpenPopup("Save scene as");
    } else {
      save_to(lab, lab.scene_path);
    }
  }
  mark("Save");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(shipped ? "a shipped preset is not overwritten: choose a file" : "save to %s",
                      lab.scene_path.c_str());
  same_line_if_fits("Save as...");
  if (ImGui::Button("Save as...")) {
    save_path = shipped ? mine : lab.scene_path;
    ImGui::OpenPopup("Save scene as");
  }
  mark("Save as...");
  save_as_popup(lab, save_path, folder);
  same_line_if_fits("Set up break");
  if (ImGui::Button("Set up break")) lab.setup_break();
  mark("Set up break");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("rack 15 balls, cue ball in hand behind the head string, a cue strike");
}

std::string export_path(const Lab& lab, const std::string& what, const std::string& ext) {
  // Absolute, so that the banner that names the file says where it is.
  std::error_code ec;
  const fs::path folder = lab.settings.export_dir.empty() ? fs::path(".") : fs::path(lab.settings.export_dir);
  const std::string dir = fs::absolute(folder, ec).lexically_normal().string();
  fs::create_directories(dir, ec);
  return unique_path(dir, (lab.scene.name.empty() ? "shotlab" : lab.scene.name) + "-" + what, ext);
}

namespace {

// The plot asked for as a PNG, drawn again over the middle of the window at most of its size (a side panel's plot
// is a few hundred pixels wide: too small for a slide), and the picture cropped to it and its margin.
void draw_plot_capture(Lab& lab, const char* id, PlotSpec spec, const std::vector<PlotSeries>& series) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float w = 0.9f * vp->Size.x, h = std::min(0.5f * w, 0.9f * vp->Size.y);
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + 0.5f * vp->Size.x, vp->Pos.y + 0.5f * vp->Size.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::SetNextWindowBgAlpha(1.0f);  // nothing of the panels under it shows through in the picture
  // It takes the clicks of its few frames (none reaches a panel out of sight under it), but not the keyboard.
  constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                     ImGuiWindowFlags_NoFocusOnAppearing;
  // On paper, as a handout or a slide wants it: white, dark text, no cursor at the time on screen.
  constexpr ImU32 kInk = IM_COL32(20, 20, 20, 255);
  spec.paper = true, spec.cursor = -1;
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(255, 255, 255, 255));
  ImGui::PushStyleColor(ImGuiCol_Text, kInk);
  const bool open = ImGui::Begin("##plot capture", nullptr, flags);
  ImGui::PopStyleColor(2);
  if (open) {
    ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
    ImGui::PushStyleColor(ImGuiCol_Text, kInk);
    plot(id, spec, series, ImGui::GetContentRegionAvail().y);
    ImGui::PopStyleColor();
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    lab.screenshot_crop = Rect{at.x, at.y, size.x, size.y};  // the plot and a margin round it
    lab.plot_capture_drawn = true;
  }
  ImGui::End();
}

}  // namespace

std::optional<double> lab_plot(Lab& lab, const char* id, PlotSpec spec, const std::vector<PlotSeries>& series,
                               float height) {
  spec.hover = lab.screenshot_request.empty();  // no readout in a picture of it
  const PlotAction a = plot(id, spec, series, height);
  try {
    if (a.export_csv) {
      const std::string path = export_path(lab, spec.title, "csv");
      write_plot_csv(path, spec, series);
      lab.say(MessageKind::Note, "wrote " + path);
    }
    if (a.export_png) {
      lab.screenshot_request = export_path(lab, spec.title, "png");
      lab.screenshot_crop = a.rect;  // until the large copy below is drawn
      lab.plot_capture = id;
      lab.screenshot_delay = 2;  // the menu that asked for it is still drawn in this frame
    }
  } catch (const std::exception& e) {
    lab.say(MessageKind::Refused, e.what());
  }
  if (!lab.screenshot_request.empty() && lab.plot_capture == id) draw_plot_capture(lab, id, spec, series);
  return a.picked;
}

void export_trajectory(const Lab& lab, const std::string& path) {
  // Re-simulates the shot from its start, a row set every 1/240 s up to the time reached (the result does not
  // depend on how time is sliced, so it is the shot that was watched).
  std::ostringstream out;
  write_trajectory_header(out);
  Prepared p = prepare(lab.shot->start());
  Simulation sim(std::move(p.model), std::move(p.state));
  write_trajectory_rows(out, sim);
  while (sim.time() < lab.shot->sim().time() - 1e-12 && sim.status() == Status::Ok) {
    sim.advance(std::min(1.0 / 240, lab.shot->sim().time() - sim.time()));
    write_trajectory_rows(out, sim);
  }
  write_file_atomic(path, out.str());
}

}  // namespace shotlab
