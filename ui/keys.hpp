// Key presses as GLFW delivers them, queued. Dear ImGui 1.86 keeps only whether a key is down at the start of a
// frame, so a short tap (pressed and released between two frames, as a quick finger or xdotool does) is lost to
// ImGui::IsKeyPressed; the shortcuts read this queue instead, which sees every press and auto-repeat.
#pragma once
#include <vector>

struct GLFWwindow;

namespace shotlab {

struct KeyPress {
  int key;   // GLFW_KEY_*
  int mods;  // GLFW_MOD_* bits
  bool repeat;
};

// Installs the callback; call before ImGui_ImplGlfw_InitForOpenGL, which chains to it.
void install_key_queue(GLFWwindow* window);
// The presses since the last call.
std::vector<KeyPress> take_key_presses();

}  // namespace shotlab
