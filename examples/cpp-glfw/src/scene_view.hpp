// ocean_glfw --scene: the composed scene of `ocean render` drawn by the library (ocean::scene,
// ocean_scene_* in the C ABI) and shown in the window.
#pragma once

#include <string>

struct GLFWwindow;

// Builds the built-in scene at width x height on the library's own GPU context, renders
// `frames` frames (0: until the window closes) at t = k / 30 s into RGBA8 buffers, uploads each
// to a texture and blits it to `window`, whose OpenGL context must be current. With a
// `screenshot` path, writes the last frame as shown (read back from the texture) to it and
// fails unless it equals the library's bytes. Returns the exit status: 0, or 3 when the
// screenshot's check fails. Library errors throw ocean::error; others std::runtime_error.
int run_scene(GLFWwindow *window, int width, int height, int frames,
              const std::string &screenshot);
