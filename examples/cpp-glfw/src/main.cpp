// ocean_glfw: the ocean library in a C++ OpenGL 4.3 engine of its own.
//
// Every frame:
// 1. Wave Train Boxes on the CPU (ocean::wtb_scene, ocean_wtb_scene_* in the C ABI): a water grid over a sea floor that rises
//    towards a shallow bank, one wind-driven box of wave trains, evaluated into the vertex
//    buffers (positions relative to the grid origin, unit normals): a steep cross sea shoaling
//    and refracting over the floor.
// 2. The mesh drawn with the library's exported GLSL (ocean_shader_export "ocean", entry points
//    mesh_vs and mesh_fs): the ocean lighting of Bruneton et al. 2010 (Algorithm 5.1) with the
//    open sea's spectrum filtered per pixel on top of the mesh, into two float targets (the
//    Sun's term, and the sky's and the sea's) and a depth texture. Uniform block and textures
//    from ocean_surface_uniforms, ocean_surface_wave_texels, ocean_surface_fresnel_texels and the sky
//    map (ocean_lighting_sky_map_create).
// 3. Scalable Ambient Obscurance over that depth with the exported compute shaders (sao_z,
//    sao_mip, sao_ao, sao_blur) and their uniform block (ocean_sao_uniforms).
// 4. The composition (sky_vs + compose_fs): the Sun's term plus the obscured ambient terms,
//    tone-mapped, the sky where the mesh did not draw, into an RGBA8 image shown in the window.
//
// Options: --frames N (stop after N frames), --screenshot out.png (write the last frame, and fail
// unless it shows water: not black, not uniform, bluish; and unless the obscurance matches the
// library's CPU reference, ocean_sao_run, within 2/255 on 99.9 % of the pixels), --size WxH
// (render size, default 1280x720), --scene (instead of all the above, the library's composed
// scene of `ocean render`, drawn by ocean::scene and shown in the window: scene_view.cpp).
// Exit status 0 on success, 1 on an error, 3 when a check of the screenshot fails.
//
// The library is used through its C++ wrapper, ocean.hpp: owning handles, ocean::error
// exceptions (caught in main), std::vector in and out.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "gl.hpp"
#include "png.hpp"
#include "scene_view.hpp"

// GLM before ocean.hpp, which then offers ocean::make_camera for GLM matrices.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "ocean.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

[[noreturn]] void die(const char *fmt, ...)
{
    std::va_list args;
    va_start(args, fmt);
    std::fputs("ocean_glfw: ", stderr);
    std::vfprintf(stderr, fmt, args);
    std::fputc('\n', stderr);
    va_end(args);
    std::exit(1);
}


void check_gl(const char *where)
{
    GLenum e = gl::GetError();
    if (e != GL_NO_ERROR)
        die("OpenGL error 0x%04x after %s", e, where);
}

struct Options {
    int frames = 0; // 0: until the window is closed
    std::string screenshot;
    int width = 1280;
    int height = 720;
    bool scene = false; // --scene: the library's composed scene instead of this engine's frame
};

Options parse(int argc, char **argv)
{
    Options o;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc)
                die("%s needs a value", a.c_str());
            return argv[++i];
        };
        if (a == "--frames") {
            o.frames = std::atoi(value().c_str());
            if (o.frames < 1)
                die("--frames must be at least 1");
        } else if (a == "--scene") {
            o.scene = true;
        } else if (a == "--screenshot") {
            o.screenshot = value();
        } else if (a == "--size") {
            std::string v = value();
            if (std::sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 16 ||
                o.height < 16 || o.width > 8192 || o.height > 8192)
                die("--size takes WxH, each side in [16, 8192], got %s", v.c_str());
        } else if (a == "--help" || a == "-h") {
            std::printf("usage: %s [--scene] [--frames N] [--screenshot out.png] [--size WxH]\n", argv[0]);
            std::exit(0);
        } else {
            die("unknown argument %s (see --help)", a.c_str());
        }
    }
    if (!o.screenshot.empty() && o.frames == 0)
        o.frames = 1;
    return o;
}

// ---------------------------------------------------------------------------------------------
// Shaders from the library's export.

struct Exported {
    std::map<std::string, std::string> sources; // by entry point
    std::vector<OceanShaderBinding> bindings;
    ocean::shader_export handle; // owns the strings of `bindings`
};

Exported export_glsl(const char *name)
{
    Exported e;
    e.handle = ocean::shader_export::create(name, OCEAN_SHADER_LANGUAGE_GLSL);
    for (size_t i = 0; i < e.handle.file_count(); i++) {
        const ocean::shader_file f = e.handle.file(i);
        e.sources[f.entry_point] =
            std::string(reinterpret_cast<const char *>(f.data.data()), f.data.size());
    }
    e.bindings = e.handle.bindings();
    return e;
}

// GLSL 4.30 exports number every non-sampler binding (`layout(binding = n)`): the number of
// WGSL binding `b` of group 0.
GLuint glsl_binding(const Exported &e, uint32_t b)
{
    for (const OceanShaderBinding &x : e.bindings)
        if (x.group == 0 && x.binding == b && x.glsl_binding != OCEAN_NO_GLSL_BINDING)
            return x.glsl_binding;
    die("the export has no GLSL binding number for binding %u", b);
}

const std::string &source(const Exported &e, const char *entry)
{
    auto it = e.sources.find(entry);
    if (it == e.sources.end())
        die("the export has no entry point %s", entry);
    return it->second;
}

GLuint compile(GLenum stage, const std::string &src, const char *label)
{
    GLuint s = gl::CreateShader(stage);
    const char *text = src.c_str();
    gl::ShaderSource(s, 1, &text, nullptr);
    gl::CompileShader(s);
    GLint ok = 0;
    gl::GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::array<char, 8192> log{};
        gl::GetShaderInfoLog(s, GLsizei(log.size()), nullptr, log.data());
        die("compiling %s:\n%s", label, log.data());
    }
    return s;
}

GLuint link(std::initializer_list<GLuint> shaders, const char *label)
{
    GLuint p = gl::CreateProgram();
    for (GLuint s : shaders)
        gl::AttachShader(p, s);
    gl::LinkProgram(p);
    GLint ok = 0;
    gl::GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::array<char, 8192> log{};
        gl::GetProgramInfoLog(p, GLsizei(log.size()), nullptr, log.data());
        die("linking %s:\n%s", label, log.data());
    }
    for (GLuint s : shaders)
        gl::DeleteShader(s);
    return p;
}

// GLSL 3.30 has no binding qualifiers, so the draw programs get their bindings by name: naga
// names a texture (combined with its sampler) `_group_G_binding_B_vs` / `_fs`, and this
// example puts it on texture unit B; the one uniform block (group 0, binding 0, named
// `Frame_block_0Vertex` / `Frame_block_0Fragment`) goes to uniform buffer binding 0.
void bind_by_names(GLuint program)
{
    GLint blocks = 0, uniforms = 0;
    gl::GetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
    for (GLint i = 0; i < blocks; i++)
        gl::UniformBlockBinding(program, GLuint(i), 0);
    gl::UseProgram(program);
    gl::GetProgramiv(program, GL_ACTIVE_UNIFORMS, &uniforms);
    for (GLint i = 0; i < uniforms; i++) {
        std::array<char, 256> name{};
        GLint size = 0;
        GLenum type = 0;
        gl::GetActiveUniform(program, GLuint(i), GLsizei(name.size()), nullptr, &size, &type,
                             name.data());
        unsigned group = 0, binding = 0;
        if (std::sscanf(name.data(), "_group_%u_binding_%u_", &group, &binding) == 2)
            gl::Uniform1i(gl::GetUniformLocation(program, name.data()), GLint(binding));
    }
}

GLuint draw_program(const Exported &e, const char *vs, const char *fs)
{
    std::string label = std::string(vs) + " + " + fs;
    GLuint p = link({compile(GL_VERTEX_SHADER, source(e, vs), vs),
                     compile(GL_FRAGMENT_SHADER, source(e, fs), fs)},
                    label.c_str());
    bind_by_names(p);
    return p;
}

GLuint compute_program(const Exported &e, const char *entry)
{
    return link({compile(GL_COMPUTE_SHADER, source(e, entry), entry)}, entry);
}

// ---------------------------------------------------------------------------------------------
// Textures.

// A one-level 2D texture read with texelFetch or written as an image: nearest filtering, so it
// is complete without mip levels.
GLuint texture2d(GLenum internal, int w, int h, GLenum format, GLenum type, const void *data)
{
    GLuint t = 0;
    gl::GenTextures(1, &t);
    gl::BindTexture(GL_TEXTURE_2D, t);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, type, data);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void bind_texture(GLuint unit, GLenum target, GLuint t)
{
    gl::ActiveTexture(GL_TEXTURE0 + unit);
    gl::BindTexture(target, t);
}

GLuint framebuffer(std::initializer_list<GLuint> colors, GLuint depth)
{
    GLuint f = 0;
    gl::GenFramebuffers(1, &f);
    gl::BindFramebuffer(GL_FRAMEBUFFER, f);
    std::vector<GLenum> draw;
    for (GLuint c : colors) {
        GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(draw.size());
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, c, 0);
        draw.push_back(attachment);
    }
    if (depth != 0)
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    gl::DrawBuffers(GLsizei(draw.size()), draw.data());
    if (gl::CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        die("framebuffer incomplete");
    return f;
}

// ---------------------------------------------------------------------------------------------
// The scene.

constexpr double kPi = 3.14159265358979323846;

// The water grid: 384 x 256 points 1 m apart, x in [-192, 191], z in [-235, 20]; the camera
// stands at its near edge.
constexpr size_t kNx = 384, kNz = 256;
constexpr double kSpacing = 1.0, kOriginX = -192.0, kOriginZ = -235.0;

// Sea floor height at world (x, z): 20 m deep at the near edge, rising to 1.5 m at the far
// edge, with a shoal off to the right that the waves refract around.
float floor_height(double x, double z)
{
    double t = (20.0 - z) / 255.0; // 0 at the near edge, 1 at the far one
    double shoal = 6.0 * std::exp(-((x - 60.0) * (x - 60.0) + (z + 120.0) * (z + 120.0)) /
                                  (2.0 * 35.0 * 35.0));
    return float(-20.0 + 18.5 * t + shoal);
}

ocean::wtb_scene make_scene()
{
    OceanWaterGridDesc grid{};
    grid.origin_x = kOriginX;
    grid.origin_z = kOriginZ;
    grid.spacing = kSpacing;
    grid.nx = kNx;
    grid.nz = kNz;
    ocean::wtb_scene scene = ocean::wtb_scene::create(grid);

    std::vector<float> terrain(kNx * kNz);
    for (size_t j = 0; j < kNz; j++)
        for (size_t i = 0; i < kNx; i++)
            terrain[j * kNx + i] = floor_height(kOriginX + double(i) * kSpacing,
                                                kOriginZ + double(j) * kSpacing);
    scene.set_terrain(terrain);

    // A box over the whole grid, its wind blowing away from the camera and a little to the
    // right, fully developed since long before t = 0. Its trains are given explicitly: a
    // steep cross sea (steepnesses k A summing to 0.8), whose troughs between crests are
    // deep enough for the obscurance to show; a fully developed 9 m/s wind sea (the trains
    // the wind would raise, k A about 0.1) is so gentle that nothing occludes anything. The
    // terrain still shoals and refracts them.
    OceanBoxDesc box{};
    box.wind.speed = 9.0;
    box.wind.direction_x = 0.25;
    box.wind.direction_z = -1.0;
    // The box's origin is its rear corner on the left looking along the wind; its width runs
    // along v = (-u.z, u.x), to the right.
    box.wind.origin_x = -260.0;
    box.wind.origin_z = 60.0;
    box.wind.width = 520.0;
    box.wind.fetch = 340.0;
    box.wind.start = -1000.0;
    box.wind.build_up = 10.0;
    box.wind.sustain = INFINITY;
    box.wind.decay = 0.0;
    box.wind.seed = 7;
    box.wind.trains = 6;
    box.smoothing = 20.0;
    box.has_recovery = 0;
    // Wavelength (m), steepness k A, direction of travel (x, z).
    const double spec[5][4] = {
        {22.0, 0.25, 0.25, -1.0}, {14.0, 0.20, -0.45, -1.0}, {9.0, 0.15, 0.8, -1.0},
        {6.0, 0.12, -0.2, -1.0}, {4.0, 0.08, 1.0, -0.6}};
    OceanWaveDesc trains[5];
    for (int k = 0; k < 5; k++) {
        trains[k].wavelength = spec[k][0];
        trains[k].amplitude = spec[k][1] * spec[k][0] / (2.0 * kPi);
        trains[k].direction_x = spec[k][2];
        trains[k].direction_z = spec[k][3];
        trains[k].phase = 1.3 * k;
        trains[k].depth = INFINITY;
    }
    scene.add_box(box, trains);
    return scene;
}

// The camera: 14 m above the sea at the grid's near edge, looking away from it 30 degrees
// down, so the view's top edge (22.5 degrees above the axis) meets the sea 7.5 degrees below
// the horizon, about 110 m away, inside the grid.
struct View {
    glm::dvec3 eye{0.0, 14.0, 12.0};
    glm::dvec3 target{0.0, 14.0 - 24.0 * std::tan(30.0 * kPi / 180.0), -12.0};
    double fov_y = 45.0 * kPi / 180.0;
    double z_near = 0.5, z_far = 2000.0;
};

// ---------------------------------------------------------------------------------------------
// The screenshot and its check.

struct ImageStats {
    double mean[3] = {0, 0, 0};
    int lum_min = 255, lum_max = 0;
    size_t colours = 0;
};

ImageStats stats(const std::vector<uint8_t> &rgb)
{
    ImageStats s;
    std::set<uint32_t> colours;
    size_t n = rgb.size() / 3;
    for (size_t i = 0; i < n; i++) {
        const uint8_t *p = &rgb[3 * i];
        for (int c = 0; c < 3; c++)
            s.mean[c] += p[c];
        int lum = (2126 * p[0] + 7152 * p[1] + 722 * p[2]) / 10000;
        s.lum_min = std::min(s.lum_min, lum);
        s.lum_max = std::max(s.lum_max, lum);
        colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
    }
    for (double &m : s.mean)
        m /= double(n);
    s.colours = colours.size();
    return s;
}

int run(int argc, char **argv)
{
    const Options opt = parse(argc, argv);
    const int W = opt.width, H = opt.height;

    glfwSetErrorCallback([](int code, const char *text) {
        std::fprintf(stderr, "ocean_glfw: GLFW error %d: %s\n", code, text);
    });
    if (!glfwInit())
        die("glfwInit failed (no display? run under xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow *window = glfwCreateWindow(W, H, "ocean: wave train boxes, ocean lighting, SAO",
                                          nullptr, nullptr);
    if (window == nullptr)
        die("cannot create a window with an OpenGL 4.3 core context");
    glfwSetKeyCallback(window, [](GLFWwindow *w, int key, int, int action, int) {
        if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS)
            glfwSetWindowShouldClose(w, GLFW_TRUE);
    });
    glfwMakeContextCurrent(window);
    glfwSwapInterval(opt.frames > 0 ? 0 : 1);
    std::string missing;
    if (!gl::load(glfwGetProcAddress, missing))
        die("OpenGL functions missing: %s", missing.c_str());
    std::printf("ocean_glfw: library %s, OpenGL %s (%s), %d x %d\n", ocean_version(),
                reinterpret_cast<const char *>(gl::GetString(GL_VERSION)),
                reinterpret_cast<const char *>(gl::GetString(GL_RENDERER)), W, H);
    if (opt.scene) {
        const int status = run_scene(window, W, H, opt.frames, opt.screenshot);
        glfwDestroyWindow(window);
        glfwTerminate();
        return status;
    }

    // --- The library's objects. --------------------------------------------------------------
    ocean::check_version();
    ocean::wtb_scene scene = make_scene();
    OceanSpectrumParams sp = ocean::defaults<OceanSpectrumParams>();
    // The open sea's spectrum adds what the 1 m mesh cannot carry: waves from 2 cm to 4 m under
    // the same wind, in the normals and the BRDF only.
    sp.wind_speed = 9.0;
    sp.wind_direction_x = 0.25;
    sp.wind_direction_z = -1.0;
    sp.wave_count = 40;
    sp.min_wavelength = 0.02;
    sp.max_wavelength = 4.0;
    const ocean::spectrum spectrum = ocean::spectrum::create(sp);
    const size_t waves = spectrum.wave_count();
    const ocean::lighting lighting = ocean::lighting::create(
        ocean::defaults<OceanSkyParams>(), ocean::defaults<OceanSeaParams>());
    const OceanSurfaceDrawParams draw = ocean::defaults<OceanSurfaceDrawParams>();

    const View view;
    const double aspect = double(W) / double(H);
    // The engine's matrices (GLM, double precision) and the
    // library's one camera made of them: GLM's default [-1, 1] depth.
    const glm::dmat4 dproj = glm::perspective(view.fov_y, aspect, view.z_near, view.z_far);
    const glm::dmat4 dview = glm::lookAt(view.eye, view.target, glm::dvec3(0.0, 1.0, 0.0));
    const OceanCamera camera =
        ocean::make_camera(dview, dproj, OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);

    // SAO over the frame's depth: the camera that made it (window depth in the texture), no
    // guard band, so the obscurance covers the viewport pixel for pixel.
    OceanSaoParams sao_params = ocean::defaults<OceanSaoParams>();
    sao_params.radius = 2.0f;
    const ocean::sao sao = ocean::sao::create(uint32_t(W), uint32_t(H), 0, camera,
                                              OCEAN_SAO_DEPTH_WINDOW, sao_params);
    const ocean::sao_uniforms_block sao_uniforms = sao.uniforms();
    const std::vector<uint8_t> &sao_block = sao_uniforms.bytes;
    const uint32_t z_levels = sao_uniforms.levels;

    // --- Shaders. ----------------------------------------------------------------------------
    Exported ocean_export = export_glsl("ocean");
    Exported z_export = export_glsl("sao_z"), mip_export = export_glsl("sao_mip");
    Exported ao_export = export_glsl("sao_ao"), blur_export = export_glsl("sao_blur");
    GLuint mesh_program = draw_program(ocean_export, "mesh_vs", "mesh_fs");
    GLuint compose_program = draw_program(ocean_export, "sky_vs", "compose_fs");
    GLuint z_program = compute_program(z_export, "z_pass");
    GLuint mip_program = compute_program(mip_export, "downsample");
    GLuint ao_program = compute_program(ao_export, "ao");
    GLuint blur_h_program = compute_program(blur_export, "blur_horizontal");
    GLuint blur_v_program = compute_program(blur_export, "blur_vertical");
    check_gl("compiling the shaders");

    // --- Buffers and textures. ---------------------------------------------------------------
    GLuint frame_ubo = 0, sao_ubo = 0;
    gl::GenBuffers(1, &frame_ubo);
    gl::BindBuffer(GL_UNIFORM_BUFFER, frame_ubo);
    gl::BufferData(GL_UNIFORM_BUFFER, OCEAN_SURFACE_UNIFORMS_SIZE, nullptr, GL_DYNAMIC_DRAW);
    gl::GenBuffers(1, &sao_ubo);
    gl::BindBuffer(GL_UNIFORM_BUFFER, sao_ubo);
    gl::BufferData(GL_UNIFORM_BUFFER, GLsizeiptr(sao_block.size()), sao_block.data(),
                   GL_STATIC_DRAW);

    // Bindings 1, 2, 6, 7, 8 of the ocean shader.
    std::vector<float> wave_texels(4 * OCEAN_WAVE_TEXTURE_ROWS * waves);
    GLuint wave_tex = texture2d(GL_RGBA32F, int(waves), OCEAN_WAVE_TEXTURE_ROWS, GL_RGBA,
                                GL_FLOAT, nullptr);
    const std::vector<float> fresnel = ocean::surface_fresnel_texels();
    GLuint fresnel_tex = texture2d(GL_R32F, OCEAN_FRESNEL_TABLE_SIZE, OCEAN_FRESNEL_TABLE_SIZE,
                                   GL_RED, GL_FLOAT, fresnel.data());
    GLuint sky_tex = 0;
    {
        const ocean::sky_map map = lighting.sky_map(draw.sky_map_size);
        const uint32_t levels = map.level_count();
        gl::GenTextures(1, &sky_tex);
        gl::BindTexture(GL_TEXTURE_2D, sky_tex);
        for (uint32_t l = 0; l < levels; l++) {
            const uint32_t side = map.level_size(l);
            const std::vector<float> texels = map.level(l);
            gl::TexImage2D(GL_TEXTURE_2D, GLint(l), GL_RGBA16F, GLsizei(side), GLsizei(side), 0,
                           GL_RGBA, GL_FLOAT, texels.data());
        }
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(levels - 1));
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    // No local waves: bindings 7 and 8 are never read, but a sampler must name a complete
    // texture of its type.
    GLuint local_fields_tex = 0;
    {
        const float zero[2] = {0.0f, 0.0f};
        gl::GenTextures(1, &local_fields_tex);
        gl::BindTexture(GL_TEXTURE_2D_ARRAY, local_fields_tex);
        gl::TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RG32F, 1, 1, 1, 0, GL_RG, GL_FLOAT, zero);
        gl::TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl::TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl::TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    }
    const float no_trains[12] = {};
    GLuint local_trains_tex = texture2d(GL_RGBA32F, 1, 3, GL_RGBA, GL_FLOAT, no_trains);

    // The mesh: positions and normals rewritten every frame, indices once.
    const size_t points = kNx * kNz;
    std::vector<OceanVec3> positions(points), normals(points);
    std::vector<uint32_t> indices;
    indices.reserve((kNx - 1) * (kNz - 1) * 6);
    for (size_t j = 0; j + 1 < kNz; j++)
        for (size_t i = 0; i + 1 < kNx; i++) {
            uint32_t a = uint32_t(j * kNx + i), c = a + uint32_t(kNx);
            indices.insert(indices.end(), {a, c, a + 1, a + 1, c, c + 1});
        }
    GLuint vao = 0, vbo[2] = {0, 0}, ibo = 0;
    gl::GenVertexArrays(1, &vao);
    gl::BindVertexArray(vao);
    gl::GenBuffers(2, vbo);
    for (GLuint a = 0; a < 2; a++) {
        gl::BindBuffer(GL_ARRAY_BUFFER, vbo[a]);
        gl::BufferData(GL_ARRAY_BUFFER, GLsizeiptr(points * sizeof(OceanVec3)), nullptr,
                       GL_STREAM_DRAW);
        gl::EnableVertexAttribArray(a);
        gl::VertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(OceanVec3), nullptr);
    }
    gl::GenBuffers(1, &ibo);
    gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    gl::BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                   indices.data(), GL_STATIC_DRAW);
    GLuint empty_vao = 0;
    gl::GenVertexArrays(1, &empty_vao);

    // Pass 1's targets: linear radiance (direct, ambient) and depth.
    GLuint direct_tex = texture2d(GL_RGBA32F, W, H, GL_RGBA, GL_FLOAT, nullptr);
    GLuint ambient_tex = texture2d(GL_RGBA32F, W, H, GL_RGBA, GL_FLOAT, nullptr);
    GLuint depth_tex =
        texture2d(GL_DEPTH_COMPONENT32F, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    GLuint mesh_fbo = framebuffer({direct_tex, ambient_tex}, depth_tex);
    // SAO's textures: z levels, packed A and key (ping-pong), the obscurance.
    std::vector<GLuint> z_tex;
    std::vector<std::array<int, 2>> z_size;
    for (uint32_t l = 0; l < z_levels; l++) {
        int w = std::max(W >> l, 1), h = std::max(H >> l, 1);
        z_tex.push_back(texture2d(GL_R32F, w, h, GL_RED, GL_FLOAT, nullptr));
        z_size.push_back({w, h});
    }
    GLuint packed_tex[2] = {texture2d(GL_R32UI, W, H, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr),
                            texture2d(GL_R32UI, W, H, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr)};
    GLuint ao_tex = texture2d(GL_R32F, W, H, GL_RED, GL_FLOAT, nullptr);
    // Pass 2's target: the displayed image.
    GLuint color_tex = texture2d(GL_RGBA8, W, H, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    GLuint color_fbo = framebuffer({color_tex}, 0);
    check_gl("creating buffers and textures");

    auto dispatch = [](GLuint program, int w, int h) {
        gl::UseProgram(program);
        gl::DispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
        gl::MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    };
    auto image = [](GLuint unit, GLuint t, GLenum format) {
        gl::BindImageTexture(unit, t, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
    };

    // --- Frames. -----------------------------------------------------------------------------
    std::vector<uint8_t> block(OCEAN_SURFACE_UNIFORMS_SIZE);
    const auto start = std::chrono::steady_clock::now();
    double evaluate_ms = 0.0;
    int frame = 0;
    while (!glfwWindowShouldClose(window) && (opt.frames == 0 || frame < opt.frames)) {
        // Headless runs step a fixed 1/30 s per frame, so a screenshot does not depend on the
        // machine's speed.
        const double time = opt.frames > 0 ? frame / 30.0 : glfwGetTime();

        // 1. The waves on the CPU, culled by the view.
        const auto t0 = std::chrono::steady_clock::now();
        const OceanFrameStats fs =
            scene.evaluate(time, &camera, positions, normals);
        evaluate_ms +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        gl::BindBuffer(GL_ARRAY_BUFFER, vbo[0]);
        gl::BufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(points * sizeof(OceanVec3)),
                          positions.data());
        gl::BindBuffer(GL_ARRAY_BUFFER, vbo[1]);
        gl::BufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(points * sizeof(OceanVec3)),
                          normals.data());

        // The frame's uniform block and wave phases.
        OceanWaterGridDesc mesh{};
        mesh.origin_x = kOriginX;
        mesh.origin_z = kOriginZ;
        mesh.spacing = kSpacing;
        mesh.nx = kNx;
        mesh.nz = kNz;
        ocean::surface_uniforms(camera, spectrum, lighting, draw, &mesh, time, uint32_t(W),
                                uint32_t(H), block);
        gl::BindBuffer(GL_UNIFORM_BUFFER, frame_ubo);
        gl::BufferSubData(GL_UNIFORM_BUFFER, 0, GLsizeiptr(block.size()), block.data());
        ocean::surface_wave_texels(camera, spectrum, time, wave_texels);
        gl::BindTexture(GL_TEXTURE_2D, wave_tex);
        gl::TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(waves), OCEAN_WAVE_TEXTURE_ROWS,
                          GL_RGBA, GL_FLOAT, wave_texels.data());

        // 2. The mesh, lit, into the float targets and the depth.
        gl::BindFramebuffer(GL_FRAMEBUFFER, mesh_fbo);
        gl::Viewport(0, 0, W, H);
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, far_depth = 1.0f;
        gl::ClearBufferfv(GL_COLOR, 0, zero);
        gl::ClearBufferfv(GL_COLOR, 1, zero);
        gl::ClearBufferfv(GL_DEPTH, 0, &far_depth);
        gl::Enable(GL_DEPTH_TEST);
        gl::DepthFunc(GL_LESS);
        gl::DepthMask(GL_TRUE);
        gl::UseProgram(mesh_program);
        gl::BindBufferBase(GL_UNIFORM_BUFFER, 0, frame_ubo);
        bind_texture(1, GL_TEXTURE_2D, wave_tex);
        bind_texture(2, GL_TEXTURE_2D, sky_tex);
        bind_texture(6, GL_TEXTURE_2D, fresnel_tex);
        bind_texture(7, GL_TEXTURE_2D_ARRAY, local_fields_tex);
        bind_texture(8, GL_TEXTURE_2D, local_trains_tex);
        gl::BindVertexArray(vao);
        gl::DrawElements(GL_TRIANGLES, GLsizei(indices.size()), GL_UNSIGNED_INT, nullptr);
        gl::Disable(GL_DEPTH_TEST);
        gl::MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

        // 3. Ambient obscurance of the depth (SAO passes 1-5).
        gl::BindBufferBase(GL_UNIFORM_BUFFER, 0, sao_ubo);
        bind_texture(glsl_binding(z_export, 1), GL_TEXTURE_2D, depth_tex);
        image(glsl_binding(z_export, 2), z_tex[0], GL_R32F);
        dispatch(z_program, W, H);
        for (uint32_t l = 1; l < z_levels; l++) {
            bind_texture(glsl_binding(mip_export, 1), GL_TEXTURE_2D, z_tex[l - 1]);
            image(glsl_binding(mip_export, 2), z_tex[l], GL_R32F);
            dispatch(mip_program, z_size[l][0], z_size[l][1]);
        }
        // Bindings 1 to 14 are z levels 0 to 13; levels the hierarchy lacks repeat its last.
        for (uint32_t k = 0; k < 14; k++)
            bind_texture(glsl_binding(ao_export, 1 + k), GL_TEXTURE_2D,
                         z_tex[std::min(k, z_levels - 1)]);
        image(glsl_binding(ao_export, 15), packed_tex[0], GL_R32UI);
        dispatch(ao_program, W, H);
        bind_texture(glsl_binding(blur_export, 1), GL_TEXTURE_2D, packed_tex[0]);
        image(glsl_binding(blur_export, 2), packed_tex[1], GL_R32UI);
        dispatch(blur_h_program, W, H);
        bind_texture(glsl_binding(blur_export, 1), GL_TEXTURE_2D, packed_tex[1]);
        image(glsl_binding(blur_export, 2), packed_tex[0], GL_R32UI);
        image(glsl_binding(blur_export, 3), ao_tex, GL_R32F);
        dispatch(blur_v_program, W, H);

        // 4. Composition into the displayed image.
        gl::BindFramebuffer(GL_FRAMEBUFFER, color_fbo);
        gl::Viewport(0, 0, W, H);
        gl::UseProgram(compose_program);
        gl::BindBufferBase(GL_UNIFORM_BUFFER, 0, frame_ubo);
        bind_texture(2, GL_TEXTURE_2D, sky_tex);
        bind_texture(9, GL_TEXTURE_2D, direct_tex);
        bind_texture(10, GL_TEXTURE_2D, ambient_tex);
        bind_texture(11, GL_TEXTURE_2D, ao_tex);
        gl::BindVertexArray(empty_vao);
        gl::DrawArrays(GL_TRIANGLES, 0, 3);
        check_gl("drawing a frame");

        // The exported shaders flip y (naga's convention): row 0 of the image is its top, so
        // the window gets it with its rows reversed.
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, color_fbo);
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        gl::BlitFramebuffer(0, 0, W, H, 0, fh, fw, 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glfwSwapBuffers(window);
        glfwPollEvents();
        frame++;
        if (opt.frames > 0) {
            float lo = positions[0].y, hi = lo;
            for (const OceanVec3 &p : positions) {
                lo = std::min(lo, p.y);
                hi = std::max(hi, p.y);
            }
            std::printf("frame %d: t = %.3f s, %zu trains in %zu boxes, heights %.2f to %.2f m\n",
                        frame, time, fs.trains, fs.alive - fs.culled, double(lo), double(hi));
        }
    }
    gl::Finish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d frames in %.2f s (%.1f ms per frame, of which %.1f ms wave train boxes on "
                "the CPU)\n",
                frame, seconds, 1000.0 * seconds / std::max(frame, 1),
                evaluate_ms / std::max(frame, 1));

    int status = 0;
    if (!opt.screenshot.empty()) {
        std::vector<uint8_t> rgba(size_t(W) * size_t(H) * 4), rgb(size_t(W) * size_t(H) * 3);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, color_fbo);
        gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
        gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl::ReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        check_gl("reading the image back");
        for (size_t i = 0; i < size_t(W) * size_t(H); i++)
            std::memcpy(&rgb[3 * i], &rgba[4 * i], 3);
        std::string error;
        if (!png::write_rgb(opt.screenshot, uint32_t(W), uint32_t(H), rgb, error))
            die("%s", error.c_str());
        // The obscurance of the last frame, and the same passes on the CPU (ocean_sao_run) over
        // the same depth buffer: the exported shaders in this pipeline must agree with the
        // library's reference within 2/255 on at least 99.9 % of the pixels (its parity bound).
        std::vector<float> ao(size_t(W) * size_t(H)), depth(ao.size());
        gl::BindTexture(GL_TEXTURE_2D, ao_tex);
        gl::GetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, ao.data());
        gl::BindTexture(GL_TEXTURE_2D, depth_tex);
        gl::GetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        check_gl("reading the obscurance and the depth back");
        const std::vector<float> cpu = sao.run(depth);
        double ao_sum = 0.0;
        float ao_min = 1.0f;
        size_t agree = 0;
        for (size_t i = 0; i < ao.size(); i++) {
            ao_sum += ao[i];
            ao_min = std::min(ao_min, ao[i]);
            agree += std::fabs(ao[i] - cpu[i]) <= 2.0f / 255.0f;
        }
        std::printf("obscurance: mean %.4f, min %.4f; %zu of %zu pixels within 2/255 of "
                    "ocean_sao_run\n",
                    ao_sum / double(ao.size()), double(ao_min), agree, ao.size());
        if (double(agree) < 0.999 * double(ao.size())) {
            std::fprintf(stderr, "ocean_glfw: the GL obscurance differs from the library's\n");
            status = 3;
        }
        const ImageStats s = stats(rgb);
        std::printf("wrote %s: mean RGB (%.1f, %.1f, %.1f), luminance %d to %d, %zu colours\n",
                    opt.screenshot.c_str(), s.mean[0], s.mean[1], s.mean[2], s.lum_min,
                    s.lum_max, s.colours);
        // Water: lit (not black), waves (not uniform: a spread of brightness and many colours),
        // and sea-coloured (blue above red on average).
        if (s.mean[0] + s.mean[1] + s.mean[2] < 30.0 || s.lum_max - s.lum_min < 20 ||
            s.colours < 1000 || s.mean[2] <= s.mean[0]) {
            std::fprintf(stderr, "ocean_glfw: the image does not look like water\n");
            status = 3;
        }
    }

    gl::DeleteFramebuffers(1, &mesh_fbo);
    gl::DeleteFramebuffers(1, &color_fbo);
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

} // namespace

int main(int argc, char **argv)
{
    // A failing library call throws ocean::error: its status, and the library's message naming
    // the function and the argument.
    try {
        return run(argc, argv);
    } catch (const ocean::error &e) {
        die("%s (%s)", e.what(), ocean_status_message(e.status()));
    } catch (const std::exception &e) {
        die("%s", e.what());
    }
}
