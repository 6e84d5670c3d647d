#include "ui/keys.hpp"

#include <GLFW/glfw3.h>

namespace shotlab {

namespace {
std::vector<KeyPress> queue;

void on_key(GLFWwindow*, int key, int, int action, int mods) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT) queue.push_back({key, mods, action == GLFW_REPEAT});
}
}  // namespace

void install_key_queue(GLFWwindow* window) { glfwSetKeyCallback(window, on_key); }

std::vector<KeyPress> take_key_presses() {
  std::vector<KeyPress> out;
  out.swap(queue);
  return out;
}

}  // namespace shotlab
