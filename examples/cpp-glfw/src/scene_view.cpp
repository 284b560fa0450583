// ocean_glfw --scene: see scene_view.hpp. The library draws the whole frame on its own device
// (the sea, the island and the wave train boxes reaching its shore, relief-mapped rocks and
// pier, ambient obscurance, composition); the engine only displays the bytes it gets back.

#include "scene_view.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "gl.hpp"
#include "png.hpp"

#include "ocean.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

int run_scene(GLFWwindow *window, int W, int H, int frames, const std::string &screenshot)
{
    const ocean::gpu_context ctx = ocean::gpu_context::create();
    OceanSceneOptions options = ocean::defaults<OceanSceneOptions>();
    options.width = std::uint32_t(W);
    options.height = std::uint32_t(H);
    const auto built = std::chrono::steady_clock::now();
    const ocean::scene scene =
        ocean::scene::create(ctx, ocean::scene::builtin_description(), options);
    std::printf("ocean_glfw --scene: the built-in scene on %s, built in %.0f ms\n",
                ctx.describe(),
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - built)
                    .count());

    // The frame's bytes are already sRGB-encoded: a plain RGBA8 texture keeps them unchanged
    // through the blit to a window that is not sRGB.
    GLuint tex = 0, fbo = 0;
    gl::GenTextures(1, &tex);
    gl::BindTexture(GL_TEXTURE_2D, tex);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::GenFramebuffers(1, &fbo);
    gl::BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    if (gl::CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the scene's framebuffer is incomplete");

    std::vector<std::uint8_t> rgba;
    int frame = 0;
    double render_ms = 0.0;
    while (!glfwWindowShouldClose(window) && (frames == 0 || frame < frames)) {
        const double time = frame / 30.0;
        const auto t = std::chrono::steady_clock::now();
        rgba = scene.render_rgba8(ctx, time);
        render_ms +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
        gl::BindTexture(GL_TEXTURE_2D, tex);
        gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl::TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        // Row 0 of the frame is its top; the window's row 0 is its bottom: blit upside down.
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        gl::BlitFramebuffer(0, 0, W, H, 0, fh, fw, 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glfwSwapBuffers(window);
        glfwPollEvents();
        frame++;
        if (frames > 0)
            std::printf("frame %d: t = %.4f s\n", frame, time);
    }
    std::printf("%d frames, %.1f ms per frame rendered by the library\n", frame,
                render_ms / (frame > 0 ? frame : 1));

    int status = 0;
    if (!screenshot.empty() && !rgba.empty()) {
        // What the window was given: the texture read back, which must hold the library's
        // bytes exactly.
        std::vector<std::uint8_t> shown(rgba.size()), rgb(std::size_t(W) * std::size_t(H) * 3);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl::ReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, shown.data());
        if (gl::GetError() != GL_NO_ERROR)
            throw std::runtime_error("reading the scene's texture back failed");
        if (std::memcmp(shown.data(), rgba.data(), rgba.size()) != 0) {
            std::fprintf(stderr, "ocean_glfw: the texture shown differs from the library's frame\n");
            status = 3;
        }
        for (std::size_t i = 0; i < std::size_t(W) * std::size_t(H); i++)
            std::memcpy(&rgb[3 * i], &shown[4 * i], 3);
        std::string error;
        if (!png::write_rgb(screenshot, std::uint32_t(W), std::uint32_t(H), rgb, error))
            throw std::runtime_error(error);
        std::printf("wrote %s (frame %d, t = %.4f s)\n", screenshot.c_str(), frame,
                    (frame - 1) / 30.0);
    }
    gl::DeleteFramebuffers(1, &fbo);
    gl::DeleteTextures(1, &tex);
    return status;
}
