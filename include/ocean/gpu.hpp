/// \file ocean/gpu.hpp
/// Part of ocean.hpp: the GPU part, declared where OCEAN_GPU is defined (the full library):
/// context, renderer, GPU SAO, shader export, and the draw data of the exported shaders.
/// Include ocean.hpp, not this file; its notes (errors, handles, spans, units) apply here.
#ifndef OCEAN_HPP_GPU
#define OCEAN_HPP_GPU

#ifndef OCEAN_HPP
#error "include ocean.hpp, not its parts"
#endif

#if defined(OCEAN_GPU)

namespace ocean {

/// A headless GPU device and queue (`OceanGpuContext`); shareable between threads.
class gpu_context : public detail::handle<OceanGpuContext, ocean_gpu_context_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanGpuContext, ocean_gpu_context_destroy>;
    using base::base;

    /// `ocean_gpu_context_create` (OCEAN_STATUS_NO_ADAPTER when there is no usable GPU).
    static gpu_context create()
    {
        OceanGpuContext *c = nullptr;
        check(ocean_gpu_context_create(&c));
        return gpu_context(c);
    }
    /// A one-line description of the adapter, owned by the context (valid while it lives).
    const char *describe() const
    {
        const char *text = nullptr;
        check(ocean_gpu_context_describe(get(), &text));
        return text;
    }
};

/// The GPU ocean renderer (`OceanRenderer`); works only with the context it was made on.
class renderer : public detail::handle<OceanRenderer, ocean_renderer_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanRenderer, ocean_renderer_destroy>;
    using base::base;

    /// `ocean_renderer_create` on `ctx` (start from `defaults<OceanRendererOptions>()`).
    static renderer create(const gpu_context &ctx, const OceanRendererOptions &options)
    {
        OceanRenderer *r = nullptr;
        check(ocean_renderer_create(ctx.get(), &options, &r));
        return renderer(r);
    }
    /// Gives the renderer the waves of `s`, filtered by n_min and n_max (the paper's by default).
    void set_spectrum(const gpu_context &ctx, const spectrum &s, double n_min = OCEAN_FILTER_N_MIN,
                      double n_max = OCEAN_FILTER_N_MAX)
    {
        check(ocean_renderer_set_spectrum(get(), ctx.get(), s.get(), n_min, n_max));
    }
    /// Gives the renderer the Sun, the sky and the sea of `l`.
    void set_lighting(const gpu_context &ctx, const lighting &l)
    {
        check(ocean_renderer_set_lighting(get(), ctx.get(), l.get()));
    }
    /// Renders width x height RGBA8 pixels (sRGB, rows from the top) seen by `camera` at
    /// `time` seconds (see make_camera).
    std::vector<std::uint8_t> render_rgba8(const gpu_context &ctx, const OceanCamera &camera,
                                           double time, std::uint32_t width,
                                           std::uint32_t height) const
    {
        std::vector<std::uint8_t> out(4 * detail::mul(width, height));
        check(ocean_renderer_render_rgba8(get(), ctx.get(), &camera, time, width, height,
                                          detail::ptr(span<std::uint8_t>(out)), out.size()));
        return out;
    }
};

/// The composed scene of `ocean render` (`OceanScene`): the sea, the island and its wave train
/// boxes, relief-mapped rocks and pier, ambient obscurance; works only with its context.
class scene : public detail::handle<OceanScene, ocean_scene_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanScene, ocean_scene_destroy>;
    using base::base;

    /// `ocean_scene_builtin_description`: the built-in scene's TOML (the format's reference).
    static std::string builtin_description()
    {
        const char *text = nullptr;
        check(ocean_scene_builtin_description(&text));
        return std::string(text);
    }
    /// `ocean_scene_create` from a TOML description on `ctx` (start the options from
    /// `defaults<OceanSceneOptions>()`).
    static scene create(const gpu_context &ctx, const std::string &description,
                        const OceanSceneOptions &options)
    {
        OceanScene *s = nullptr;
        check(ocean_scene_create(ctx.get(), description.data(), description.size(), &options,
                                 &s));
        return scene(s);
    }
    /// The frames' width and height in pixels.
    std::pair<std::uint32_t, std::uint32_t> size() const
    {
        std::uint32_t w = 0, h = 0;
        check(ocean_scene_size(get(), &w, &h));
        return {w, h};
    }
    /// Renders the frame at `time` seconds: size() RGBA8 pixels (sRGB, rows from the top).
    std::vector<std::uint8_t> render_rgba8(const gpu_context &ctx, double time) const
    {
        const auto [w, h] = size();
        std::vector<std::uint8_t> out(4 * detail::mul(w, h));
        check(ocean_scene_render_rgba8(get(), ctx.get(), time,
                                       detail::ptr(span<std::uint8_t>(out)), out.size()));
        return out;
    }
};

/// The GPU ambient obscurance passes (`OceanSaoGpu`); works only with its context.
class sao_gpu : public detail::handle<OceanSaoGpu, ocean_sao_gpu_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanSaoGpu, ocean_sao_gpu_destroy>;
    using base::base;

    /// `ocean_sao_gpu_create` on `ctx`.
    static sao_gpu create(const gpu_context &ctx)
    {
        OceanSaoGpu *s = nullptr;
        check(ocean_sao_gpu_create(ctx.get(), &s));
        return sao_gpu(s);
    }
    /// `ocean_sao_gpu_run`: sao::run on the GPU of `ctx` (sizes as there).
    std::vector<float> run(const gpu_context &ctx, const ocean::sao &s,
                           span<const float> depth) const
    {
        const OceanSaoInfo info = s.describe();
        detail::check_size("ocean::sao_gpu::run: depth", depth.size(),
                           std::size_t(info.input_width) * info.input_height);
        std::vector<float> ao(std::size_t(info.output_width) * info.output_height);
        check(ocean_sao_gpu_run(get(), ctx.get(), s.get(), depth.data(), depth.size(), ao.data(),
                                ao.size()));
        return ao;
    }
};

/// One file of a shader export; the pointers are owned by the export.
struct shader_file {
    const char *name;              ///< Suggested file name, e.g. "ocean.ocean_vs.vert.glsl".
    span<const std::uint8_t> data; ///< Text (UTF-8, NUL follows) or SPIR-V words.
    OceanShaderStage stage;        ///< What the file holds.
    const char *entry_point;       ///< The entry point ("" for a module).
};

/// The number of registered shaders (passes).
inline std::size_t shader_count() { return ocean_shader_count(); }
/// The name of registered shader `index`, static.
inline const char *shader_name(std::size_t index)
{
    return detail::out<const char *>([&](const char **o) { return ocean_shader_name(index, o); });
}

/// A shader translated to one language (`OceanShaderExport`), immutable and shareable.
class shader_export : public detail::handle<OceanShaderExport, ocean_shader_export_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanShaderExport, ocean_shader_export_destroy>;
    using base::base;

    /// `ocean_shader_export` of pass `name` to `language` (an OceanShaderLanguage value).
    static shader_export create(const char *name, std::uint32_t language)
    {
        OceanShaderExport *e = nullptr;
        check(ocean_shader_export(name, language, &e));
        return shader_export(e);
    }
    /// The number of files (>= 1).
    std::size_t file_count() const
    {
        return detail::out<std::size_t>(
            [&](std::size_t *o) { return ocean_shader_export_file_count(get(), o); });
    }
    /// File `index`: name, bytes, stage and entry point.
    shader_file file(std::size_t index) const
    {
        shader_file f{};
        const std::uint8_t *data = nullptr;
        std::size_t len = 0;
        check(ocean_shader_export_file(get(), index, &f.name, &data, &len));
        check(ocean_shader_export_file_stage(get(), index, &f.stage, &f.entry_point));
        f.data = span<const std::uint8_t>(data, len);
        return f;
    }
    /// The binding layout as text (the `<pass>.bindings.txt` of `ocean shaders`).
    const char *bindings_table() const
    {
        return detail::out<const char *>(
            [&](const char **o) { return ocean_shader_export_bindings(get(), o); });
    }
    /// The number of resource bindings.
    std::size_t binding_count() const
    {
        return detail::out<std::size_t>(
            [&](std::size_t *o) { return ocean_shader_export_binding_count(get(), o); });
    }
    /// Binding `index`, in (group, binding) order.
    OceanShaderBinding binding(std::size_t index) const
    {
        return detail::out<OceanShaderBinding>(
            [&](OceanShaderBinding *o) { return ocean_shader_export_binding(get(), index, o); });
    }
    /// Every binding.
    std::vector<OceanShaderBinding> bindings() const
    {
        std::vector<OceanShaderBinding> out(binding_count());
        for (std::size_t i = 0; i < out.size(); i++)
            out[i] = binding(i);
        return out;
    }
};

/// `ocean_surface_uniforms` into `out`: exactly OCEAN_SURFACE_UNIFORMS_SIZE bytes (else
/// std::invalid_argument). `mesh` may be null. `camera`: see make_camera.
inline void surface_uniforms(const OceanCamera &camera, const spectrum &s, const lighting &l,
                             const OceanSurfaceDrawParams &params, const OceanWaterGridDesc *mesh,
                             double time, std::uint32_t width, std::uint32_t height,
                             span<std::uint8_t> out)
{
    detail::check_size("ocean::surface_uniforms: out", out.size(), OCEAN_SURFACE_UNIFORMS_SIZE);
    check(ocean_surface_uniforms(&camera, s.get(), l.get(), &params, mesh, time, width, height,
                                 out.data(), out.size()));
}
/// `ocean_surface_uniforms` into a new vector.
inline std::vector<std::uint8_t> surface_uniforms(const OceanCamera &camera, const spectrum &s,
                                                  const lighting &l,
                                                  const OceanSurfaceDrawParams &params,
                                                  const OceanWaterGridDesc *mesh, double time,
                                                  std::uint32_t width, std::uint32_t height)
{
    std::vector<std::uint8_t> out(OCEAN_SURFACE_UNIFORMS_SIZE);
    surface_uniforms(camera, s, l, params, mesh, time, width, height, out);
    return out;
}
/// `ocean_surface_wave_texels` into `out`: exactly 12 * wave count floats (else
/// std::invalid_argument).
inline void surface_wave_texels(const OceanCamera &camera, const spectrum &s, double time,
                                span<float> out)
{
    detail::check_size("ocean::surface_wave_texels: out", out.size(),
                       4 * OCEAN_WAVE_TEXTURE_ROWS * s.wave_count());
    check(ocean_surface_wave_texels(&camera, s.get(), time, out.data(), out.size()));
}
/// `ocean_surface_wave_texels` into a new vector.
inline std::vector<float> surface_wave_texels(const OceanCamera &camera, const spectrum &s,
                                              double time)
{
    std::vector<float> out(4 * OCEAN_WAVE_TEXTURE_ROWS * s.wave_count());
    surface_wave_texels(camera, s, time, out);
    return out;
}
/// The effective Fresnel table texture, OCEAN_FRESNEL_TABLE_SIZE^2 floats.
inline std::vector<float> surface_fresnel_texels()
{
    std::vector<float> out(OCEAN_FRESNEL_TABLE_SIZE * OCEAN_FRESNEL_TABLE_SIZE);
    check(ocean_surface_fresnel_texels(out.data(), out.size()));
    return out;
}
/// `ocean_relief_uniforms`: the block of the exported `relief` shader in a new vector (the
/// camera: see make_camera).
inline std::vector<std::uint8_t> relief_uniforms(const OceanCamera &camera,
                                                 const OceanReliefScene &scene,
                                                 std::uint32_t size, std::uint32_t edge,
                                                 std::uint32_t levels, std::uint32_t srgb_encode)
{
    std::vector<std::uint8_t> out(OCEAN_RELIEF_UNIFORMS_SIZE);
    check(ocean_relief_uniforms(&camera, &scene, size, edge, levels, srgb_encode, out.data(),
                                out.size()));
    return out;
}

} // namespace ocean

#endif // OCEAN_GPU

#endif // OCEAN_HPP_GPU
