// run_gui: the window, the frame loop (input, physics on a time budget, 3D view, overlay, panels) and screenshots.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/paths.hpp"
#include "ui/gl.hpp"
#include "ui/panels.hpp"
#include "ui/renderer.hpp"
#include "ui/script.hpp"

namespace shotlab {

namespace {

// Ctrl+C or a polite kill closes the window like its close button, so the settings are still saved.
std::atomic<bool> interrupted{false};
extern "C" void on_signal(int) { interrupted = true; }

// The back buffer just drawn (3D view and panels) as a PNG.
bool write_png(const std::string& path, int width, int height) {
  std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  stbi_flip_vertically_on_write(1);
  return stbi_write_png(path.c_str(), width, height, 3, pixels.data(), width * 3) != 0;
}

void draw_balls(Renderer& renderer, const Lab& lab) {
  const Frame& f = lab.frame();
  for (int i = 0; i < f.state.ball_count(); ++i) {
    if (!f.state.in_play[i] && position(f.state.x, i).y < -0.1) continue;  // gone down a pocket
    const BallSpec& b = lab.scene.balls[i].spec;
    renderer.draw_ball(position(f.state.x, i), f.orientation[i], b.radius, ball_look(b.id));
  }
}

// Tables have a standard view; a scene without one (Newton's cradle) is framed around its balls and rod anchors.
void frame_scene(Camera& camera, const Scene& scene) {
  camera.reset();
  if (scene.table || scene.balls.empty()) return;
  Vec3 lo{1e9}, hi{-1e9};
  for (const InitialBall& b : scene.balls) lo = glm::min(lo, b.position), hi = glm::max(hi, b.position);
  for (const Rod& r : scene.model.rods) lo = glm::min(lo, r.anchor), hi = glm::max(hi, r.anchor);
  camera.target = (lo + hi) * 0.5;
  camera.yaw = M_PI / 2;
  camera.pitch = 0.25;
  camera.distance = std::max(0.5, 2.5 * glm::length(hi - lo));
}

std::string initial_scene(const GuiOptions& o, const Settings& s) {
  if (!o.scene.empty()) return o.scene;
  if (!s.last_scene.empty() && std::filesystem::exists(s.last_scene)) return s.last_scene;
  return preset_path("break.json");
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
  }
  ~Window() {
    glfwDestroyWindow(handle);
    glfwTerminate();
  }
};

}  // namespace

int run_gui(const GuiOptions& options) {
  try {
    std::unique_ptr<Script> script;
    if (!options.script.empty()) script = std::make_unique<Script>(options.script);
    Window window(options.width, options.height);
    glfwSwapInterval(script ? 0 : 1);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    // Scripted runs are hermetic: no settings or window layout read or written.
    static std::string ini;
    ini = script || config_dir().empty() ? "" : config_dir() + "/imgui.ini";
    ImGui::GetIO().IniFilename = ini.empty() ? nullptr : ini.c_str();
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window.handle, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    Settings settings = script ? Settings{} : load_settings();
    int exit_code = 0;
    {
      Lab lab(settings);
      Renderer renderer;
      ProbeReadouts probes;
      MouseDrag drag;
      if (!lab.load(initial_scene(options, settings))) lab.load(preset_path("stun.json"));
      lab.on_load = [&settings](const Scene& s) { frame_scene(settings.camera, s); };  // the first load keeps the saved view
      ScriptHost host{lab, settings.camera, nullptr};
      float left = 0, right = static_cast<float>(options.width);  // the 3D view's area, from the previous frame
      double last = glfwGetTime(), fps_start = last;
      int fps_frames = 0;
      std::signal(SIGINT, on_signal);
      std::signal(SIGTERM, on_signal);
      while (!glfwWindowShouldClose(window.handle) && !interrupted && !(script && script->done())) {
        glfwPollEvents();
        const double now = glfwGetTime();
        const double dt = script && !host.real_clock ? 1.0 / 60 : std::min(now - last, 0.1);
        last = now;
        if (++fps_frames, now - fps_start >= 1.0) host.fps = fps_frames / (now - fps_start), fps_frames = 0, fps_start = now;

        int w, h;
        glfwGetFramebufferSize(window.handle, &w, &h);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        if (right - left < 200) left = 0, right = static_cast<float>(w);  // panels cover it: use the whole window
        const Viewport viewport(settings.camera, left, right - left, h);
        handle_input(lab, settings.camera, viewport, drag);
        lab.update(dt);

        left = play_panel(lab, settings.camera);
        right = std::min(inspector_panel(lab, probes), static_cast<float>(w));
        help_panel(&settings.view.help);
        message_banner(lab);
        draw_overlay(lab, viewport, ImGui::GetBackgroundDrawList());

        renderer.begin(viewport.view_proj, viewport.eye, static_cast<int>(viewport.x0), static_cast<int>(viewport.width), h);
        renderer.draw_scene(lab.scene, lab.shot ? lab.shot->sim().model() : lab.table_model);
        draw_balls(renderer, lab);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        if (!lab.screenshot_request.empty()) {
          lab.note = write_png(lab.screenshot_request, w, h) ? "wrote " + lab.screenshot_request
                                                             : "cannot write " + lab.screenshot_request;
          lab.screenshot_request.clear();
        }
        if (script) {
          host.screenshot = [w, h](const std::string& path) { return write_png(path, w, h); };
          script->run(host);
        }
        glfwSwapBuffers(window.handle);
      }
      if (script) exit_code = script->failures() ? 1 : 0;
      else save_settings(settings);
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
