/// \file ocean/sao.hpp
/// Part of ocean.hpp: Scalable Ambient Obscurance (ocean::sao).
/// Include ocean.hpp, not this file; its notes (errors, handles, spans, units) apply here.
#ifndef OCEAN_HPP_SAO
#define OCEAN_HPP_SAO

#ifndef OCEAN_HPP
#error "include ocean.hpp, not its parts"
#endif

namespace ocean {

// ---------------------------------------------------------------------------------------------
// Scalable Ambient Obscurance

#if defined(OCEAN_GPU)
/// The uniform block of the exported `sao_*` shaders and the number of z levels.
struct sao_uniforms_block {
    std::vector<std::uint8_t> bytes; ///< OCEAN_SAO_UNIFORMS_SIZE bytes, std140.
    std::uint32_t levels;            ///< z levels the passes build, 1 to 14.
};
#endif

/// A validated SAO set-up (`OceanSao`), immutable and shareable.
class sao : public detail::handle<OceanSao, ocean_sao_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanSao, ocean_sao_destroy>;
    using base::base;

    /// `ocean_sao_create` for input_width x input_height depth buffers with `guard` pixels of
    /// guard band (`camera`: see make_camera; SAO reads its projection), holding
    /// `depth_source` values (`OCEAN_SAO_DEPTH_WINDOW` or `OCEAN_SAO_DEPTH_NDC`).
    static sao create(std::uint32_t input_width, std::uint32_t input_height, std::uint32_t guard,
                      const OceanCamera &camera, std::uint32_t depth_source,
                      const OceanSaoParams &params)
    {
        OceanSao *s = nullptr;
        check(ocean_sao_create(input_width, input_height, guard, &camera, depth_source, &params,
                               &s));
        return sao(s);
    }
    /// What the set-up was made of (sizes, planes, constants).
    OceanSaoInfo describe() const
    {
        return detail::out<OceanSaoInfo>([&](OceanSaoInfo *o) { return ocean_sao_describe(get(), o); });
    }
    /// `ocean_sao_run` of `depth` (input_width * input_height floats, row 0 at the top) into
    /// `ao` (output_width * output_height floats); either size wrong: std::invalid_argument.
    void run(span<const float> depth, span<float> ao) const
    {
        const OceanSaoInfo info = describe();
        detail::check_size("ocean::sao::run: depth", depth.size(),
                           std::size_t(info.input_width) * info.input_height);
        detail::check_size("ocean::sao::run: ao", ao.size(),
                           std::size_t(info.output_width) * info.output_height);
        check(ocean_sao_run(get(), depth.data(), depth.size(), ao.data(), ao.size()));
    }
    /// `ocean_sao_run` into a new vector.
    std::vector<float> run(span<const float> depth) const
    {
        const OceanSaoInfo info = describe();
        std::vector<float> ao(std::size_t(info.output_width) * info.output_height);
        run(depth, ao);
        return ao;
    }
    /// The view-space z of every depth value, metres (input size, else std::invalid_argument).
    std::vector<float> view_z(span<const float> depth) const
    {
        const OceanSaoInfo info = describe();
        const std::size_t n = std::size_t(info.input_width) * info.input_height;
        detail::check_size("ocean::sao::view_z: depth", depth.size(), n);
        std::vector<float> z(n);
        check(ocean_sao_view_z(get(), depth.data(), depth.size(), z.data(), z.size()));
        return z;
    }
#if defined(OCEAN_GPU)
    /// `ocean_sao_uniforms`: the block of the exported `sao_*` shaders and the level count.
    sao_uniforms_block uniforms() const
    {
        sao_uniforms_block b{std::vector<std::uint8_t>(OCEAN_SAO_UNIFORMS_SIZE), 0};
        check(ocean_sao_uniforms(get(), b.bytes.data(), b.bytes.size(), &b.levels));
        return b;
    }
#endif
};

} // namespace ocean

#endif // OCEAN_HPP_SAO
