// run_gui: the window and the frame loop (input, physics on a time budget, layout, 3D view, overlay, panels),
// pictures (screenshots, plot exports, strobe), and the state dump for tests. The loop sleeps while nothing moves.
#include "ui/gui.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>

#include "ui/fonts.hpp"
#include "ui/framing.hpp"
#include "ui/gl.hpp"
#include "ui/keys.hpp"
#include "ui/panels.hpp"
#include "ui/pictures.hpp"
#include "ui/renderer.hpp"
#include "ui/script.hpp"
#include "ui/state_dump.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

// Ctrl+C or a polite kill closes the window like its close button, so the settings are still saved; SIGUSR1 asks
// for a state dump (--dump-state).
std::atomic<bool> interrupted{false}, dump_requested{false};
extern "C" void on_signal(int) { interrupted = true; }
extern "C" void on_dump_signal(int) { dump_requested = true; }

// Presentation mode's fonts and widgets, times the UI scale: 1.7 on a 1920 x 1080 window, less on a smaller one in
// proportion (projected full screen, its pixels are larger), down to 1.25: text keeps its size on the wall. The
// panels do not widen with it past 40 % of the width (kPresentationViewShare): the table keeps its size.
float presentation_scale(int w, int h) {
  return std::clamp(1.7f * std::min(static_cast<float>(w) / 1920, static_cast<float>(h) / 1080), 1.25f, 1.7f);
}

struct Window {
  GLFWwindow* handle;
  Window(int w, int h) {
    if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GL_TRUE);
    handle = glfwCreateWindow(w, h, "shotlab", nullptr, nullptr);
    if (!handle) {
      glfwTerminate();
      throw std::runtime_error("cannot open an OpenGL 3.3 core window");
    }
    glfwMakeContextCurrent(handle);
    glfwFocusWindow(handle);  // as a window manager would: keys go to the new window
  }
  ~Window() {
    glfwDestroyWindow(handle);
    glfwTerminate();
  }
};

// Fonts at a few sizes (crisp text at every UI scale), and the style scaled to match; the atlas is built once.
class Fonts {
 public:
  Fonts() {
    ImGuiIO& io = ImGui::GetIO();
    base_style_ = ImGui::GetStyle();
    if (!std::filesystem::exists(kUiFont)) return;  // ImGui's own font, scaled
    for (float px : {15.0f, 20.0f, 26.0f, 34.0f}) fonts_.push_back({px, io.Fonts->AddFontFromFileTTF(kUiFont, px)});
  }
  // Before NewFrame: the font nearest above the wanted size, scaled down to it.
  void apply(float scale) {
    if (scale == applied_) return;
    applied_ = scale;
    ImGuiIO& io = ImGui::GetIO();
    const float want = kBaseFontPx * scale;
    ImFont* font = nullptr;
    float size = 13;  // ImGui's default font
    for (const auto& [px, f] : fonts_) {
      font = f, size = px;
      if (px >= want) break;
    }
    io.FontDefault = font;
    io.FontGlobalScale = want / size;
    ImGui::GetStyle() = base_style_;
    ImGui::GetStyle().ScaleAllSizes(scale);
  }

 private:
  std::vector<std::pair<float, ImFont*>> fonts_;
  ImGuiStyle base_style_;
  float applied_ = -1;
};

// In replay the camera can follow the cue ball (players watching where it goes); it keeps its distance and angle.
void follow_cue_ball(Camera& camera, const Lab& lab) {
  if (!lab.settings.view.follow_cue || !lab.shot || !lab.scene.cue) return;
  const int c = scene_ball(lab.shot->start(), lab.scene.cue->ball);
  if (c < 0 || c >= lab.frame().state.ball_count() || !lab.frame().state.in_play[c]) return;
  const Vec3 p = position(lab.frame().state.x, c);
  camera.target = {p.x, 0, p.z};
}

std::string initial_scene(const GuiOptions& o, const Settings& s) {
  if (!o.scene.empty()) return o.scene;
  if (!s.last_scene.empty() && std::filesystem::exists(s.last_scene)) return s.last_scene;
  return o.data_root + "/presets/break.json";
}

// A scene that cannot be opened at start is reported on stderr and in the banner, and a preset opens instead; the
// settings' last scene and recent files stay as they were, so the user's file is not forgotten.
void open_first_scene(Lab& lab, const std::string& path, const std::string& fallback) {
  if (lab.load(path)) return;
  const std::string problem = lab.message;
  std::cerr << "shotlab: " << problem << '\n';
  const std::string last = lab.settings.last_scene;
  const std::vector<std::string> recent = lab.settings.recent;
  lab.load(fallback);
  lab.settings.last_scene = last;
  lab.settings.recent = recent;
  lab.say(MessageKind::LoadError, problem + "\n(the " + lab.scene.name + " preset is open instead)");
  lab.scene_kept = false;  // there was none to keep
}

Layout frame_layout(const Settings& s, int w, int h) {
  const float scale = ImGui::GetFontSize() / kBaseFontPx;
  const float bar = ImGui::GetFrameHeight();
  return layout_panels(static_cast<float>(w), static_cast<float>(h),
                       {s.panels.left_open, s.panels.left_width * scale, bar},
                       {s.panels.right_open, s.panels.right_width * scale, bar},
                       view_share(s));
}

// ImGui's GLFW backend (1.86) reads the pointer only once the window has the focus or the pointer has entered it:
// a window opened under the pointer without a window manager gets neither, and its first clicks would be lost.
void pointer_fallback(GLFWwindow* window) {
  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsMousePosValid() || !glfwGetWindowAttrib(window, GLFW_HOVERED)) return;
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  io.MousePos = ImVec2(static_cast<float>(x), static_cast<float>(y));
}

// Sleeps while nothing changes on screen; after input, draws a few frames so that ImGui settles.
class Pacer {
 public:
  // True when it slept: the frame's time is then the wait.
  bool wait(bool busy) {
    if (busy || settle_ > 0) {
      glfwPollEvents();
      settle_ = busy ? kSettle : settle_ - 1;
      return false;
    }
    const double before = glfwGetTime();
    glfwWaitEventsTimeout(kIdleWake);
    if (glfwGetTime() - before < kIdleWake * 0.9) settle_ = kSettle;  // woken by an event, not the timeout
    return true;
  }

 private:
  static constexpr int kSettle = 3;
  static constexpr double kIdleWake = 0.5;  // s: the status line still refreshes at idle
  int settle_ = kSettle;
};

}  // namespace

int run_gui(const GuiOptions& options) {
  try {
    std::unique_ptr<Script> script;
    if (!options.script.empty()) script = std::make_unique<Script>(options.script, options.data_root);
    Window window(options.width, options.height);
    glfwSwapInterval(script ? 0 : 1);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // panel places come from layout.hpp, not from a saved file
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Colors[ImGuiCol_PopupBg].w = 1;  // dialogs and lists opaque: trails showed through a file list
    install_key_queue(window.handle);
    ImGui_ImplGlfw_InitForOpenGL(window.handle, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    Fonts fonts;

    // Scripted runs are hermetic: no settings read or written.
    Settings settings = script ? Settings{} : load_settings();
    int exit_code = 0;
    {
      Lab lab(settings, options.data_root);
      Renderer renderer(options.data_root);
      Tuning tuning;
      MouseDrag drag;
      Pacer pacer;
      lab.on_load = [&settings](const Scene& s) { scene_opened(settings.camera, s); };
      open_first_scene(lab, initial_scene(options, settings), options.data_root + "/presets/sliding_to_rolling.json");
      ScriptHost host{lab, settings.camera, nullptr};
      double last = glfwGetTime(), frame_seconds = 0;
      long frame = 0;
      FrameTimes play_frames;
      bool played = false;   // a shot played in the last frame: at its physics or when it ended
      int played_shot = -1;  // which
      std::signal(SIGINT, on_signal);
      std::signal(SIGTERM, on_signal);
      if (!options.dump_state.empty()) std::signal(SIGUSR1, on_dump_signal);
      while (!glfwWindowShouldClose(window.handle) && !interrupted && !(script && script->done())) {
        bool slept = false;
        if (script) glfwPollEvents();
        else slept = pacer.wait(lab.animating() || tuning.busy() || ImGui::IsAnyMouseDown());
        const double now = glfwGetTime();
        const double dt = script && !host.real_clock ? 1.0 / 60 : std::min(now - last, 0.1);
        frame_seconds = now - last;
        last = now;
        host.fps = frame_seconds > 0 ? 1 / frame_seconds : 0;
        play_frames.add(played, played_shot, frame_seconds);

        int w, h;
        glfwGetFramebufferSize(window.handle, &w, &h);
        fonts.apply(settings.ui_scale * (settings.presentation ? presentation_scale(w, h) : 1.0f));
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        if (script) {  // scripted runs are hermetic: the pointer, wherever it is, plays no part
          ImGuiIO& io = ImGui::GetIO();
          io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
          for (bool& down : io.MouseDown) down = false;
        } else {
          pointer_fallback(window.handle);
        }
        ImGui::NewFrame();
        new_marks_frame();
        readout("font size", ImGui::GetFontSize());
        if (TypingNote n = vet_number_typing(); !n.text.empty())
          lab.say(n.refused ? MessageKind::Refused : MessageKind::Note, std::move(n.text));
        const Layout layout = frame_layout(settings, w, h);
        fit_camera(settings.camera, lab.scene, layout.view);
        follow_cue_ball(settings.camera, lab);
        const Viewport viewport(settings.camera, layout.view.x, layout.view.w, h);
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        handle_input(lab, settings.camera, viewport, drag, layout.view.contains(mouse.x, mouse.y));
        const bool playing = lab.playing;  // the frame a shot ends in counts too
        const int playing_shot = lab.shot_id();
        lab.update(dt);

        settings.panels.left_open = left_panel(lab, settings.camera, layout);
        settings.panels.right_open = inspector_panel(lab, tuning, layout);
        readout("popup open", ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) ? 1.0 : 0.0);  // for the GUI tests
        if (std::string note = take_slider_note(); !note.empty()) lab.say(MessageKind::Refused, std::move(note));
        const float banner_bottom = message_banner(lab, layout.view);
        help_panel(&settings.view.help, banner_bottom > 0 ? banner_bottom + em(4) : 0.0f);
        status_line(lab, layout.view, frame_seconds, slept);
        lab.finish_pocket_aim();  // before the wait: P's new aim gets its paths in this frame too
        lab.await_prediction();
        lab.report_prediction();
        draw_overlay(lab, viewport, ImGui::GetBackgroundDrawList());

        // The side panels' background (they draw none), then the view clears its own part.
        const ImVec4 panel = panel_background();
        glClearColor(panel.x, panel.y, panel.z, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (!lab.strobe_request.empty()) write_strobe(lab, renderer, viewport, h);
        renderer.begin(viewport);
        renderer.draw_scene(lab.scene, lab.shot ? lab.shot->sim().model() : lab.table_model);
        draw_balls(renderer, lab, lab.frame(), 1.0f);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        if (!lab.screenshot_request.empty() && lab.screenshot_delay > 0) --lab.screenshot_delay;
        else if (!lab.screenshot_request.empty()) write_screenshot(lab, w, h);
        lab.plot_capture_drawn = false;  // the next frame's panels say again
        const ScreenInfo screen{w, h, layout.view, &viewport, &marks(), &readouts(), mouse.x, mouse.y, host.fps,
                                frame_seconds * 1e3, ++frame, &play_frames};
        if (dump_requested.exchange(false)) write_state(lab, screen, options.dump_state);
        if (script) {
          host.screen = &screen;
          host.screenshot = [w, h](const std::string& path) { return write_window_png(path, 0, 0, w, h, h); };
          script->run(host);
          host.screen = nullptr;
        }
        glfwSwapBuffers(window.handle);
        played = playing || lab.playing;
        played_shot = playing ? playing_shot : lab.shot_id();
      }
      if (script) {
        exit_code = script->failures() ? 1 : 0;
      } else if (std::string error; !save_settings(settings, &error)) {
        std::cerr << "shotlab: settings not saved: " << error << '\n';
      }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return exit_code;
  } catch (const std::exception& e) {
    std::cerr << "shotlab: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace shotlab
