/// \file ocean/relief.hpp
/// Part of ocean.hpp: relief mapping: height maps, cone maps, mip chains, tracers.
/// Include ocean.hpp, not this file; its notes (errors, handles, spans, units) apply here.
#ifndef OCEAN_HPP_RELIEF
#define OCEAN_HPP_RELIEF

#ifndef OCEAN_HPP
#error "include ocean.hpp, not its parts"
#endif

namespace ocean {

// ---------------------------------------------------------------------------------------------
// Relief mapping

namespace detail {
// T is the element type of `encoding` (OCEAN_RELIEF_ENCODING_*), or std::invalid_argument;
// an unknown encoding is left to the library.
template <typename T>
void check_encoding(const char *what, std::uint32_t encoding)
{
    bool ok = true;
    if (encoding == OCEAN_RELIEF_ENCODING_UNORM8 || encoding == OCEAN_RELIEF_ENCODING_UNORM8_SQRT)
        ok = std::is_same<T, std::uint8_t>::value;
    else if (encoding == OCEAN_RELIEF_ENCODING_F16)
        ok = std::is_same<T, std::uint16_t>::value;
    else if (encoding == OCEAN_RELIEF_ENCODING_F32)
        ok = std::is_same<T, float>::value;
    if (!ok)
        throw std::invalid_argument(std::string(what) + ": element type does not match encoding " +
                                    std::to_string(encoding));
}

// A progress callable: `bool f(std::size_t done, std::size_t total)`, true to go on.
template <typename F>
using if_progress = std::enable_if_t<std::is_invocable_r<bool, F &, std::size_t, std::size_t>::value>;

// Runs `call(progress, user)`, a generating function of the C API, with `f` as its
// OceanReliefProgress. An exception `f` throws must not unwind through the library: the
// trampoline catches it, cancels the work (nothing is written), and it is rethrown here once
// the call has returned. `f` returning false cancels too: ocean::error OCEAN_STATUS_CANCELLED.
template <typename F, typename Call>
void with_progress(F &f, Call &&call)
{
    struct state {
        F &f;
        std::exception_ptr thrown;
        static int trampoline(void *user, std::size_t done, std::size_t total) noexcept
        {
            state &s = *static_cast<state *>(user);
            try {
                return s.f(done, total) ? 0 : 1;
            } catch (...) {
                s.thrown = std::current_exception();
                return 1;
            }
        }
    } s{f, nullptr};
    const OceanStatus status = call(&state::trampoline, static_cast<void *>(&s));
    if (s.thrown)
        std::rethrow_exception(s.thrown);
    check(status);
}
} // namespace detail

/// A square height map with its edge mode (`OceanReliefMap`), immutable and shareable.
class relief_map : public detail::handle<OceanReliefMap, ocean_relief_map_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanReliefMap, ocean_relief_map_destroy>;
    using base::base;

    /// From width * height float heights in [0, 1] (1: the polygon), row-major; `edge`
    /// OCEAN_RELIEF_EDGE_*, `range` OCEAN_RELIEF_RANGE_*.
    static relief_map create_f32(span<const float> heights, std::uint32_t width,
                                 std::uint32_t height, std::uint32_t edge, std::uint32_t range)
    {
        OceanReliefMap *m = nullptr;
        check(ocean_relief_map_create_f32(heights.data(), heights.size(), width, height, edge,
                                          range, &m));
        return relief_map(m);
    }
    /// From 8-bit heights (v / 255).
    static relief_map create_u8(span<const std::uint8_t> heights, std::uint32_t width,
                                std::uint32_t height, std::uint32_t edge)
    {
        OceanReliefMap *m = nullptr;
        check(ocean_relief_map_create_u8(heights.data(), heights.size(), width, height, edge, &m));
        return relief_map(m);
    }
    /// From 16-bit heights (v / 65535).
    static relief_map create_u16(span<const std::uint16_t> heights, std::uint32_t width,
                                 std::uint32_t height, std::uint32_t edge)
    {
        OceanReliefMap *m = nullptr;
        check(ocean_relief_map_create_u16(heights.data(), heights.size(), width, height, edge, &m));
        return relief_map(m);
    }
    /// The side N, texels.
    std::uint32_t size() const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_relief_map_size(get(), o); });
    }
    /// The depths (1 - height), N * N floats, row-major.
    std::vector<float> depths() const
    {
        std::vector<float> out(detail::mul(size(), size()));
        check(ocean_relief_map_depths(get(), out.data(), out.size()));
        return out;
    }
    /// The tangent-space normals for a relief `depth` texel widths deep, 3 N * N floats.
    std::vector<float> normals(float depth) const
    {
        std::vector<float> out(3 * detail::mul(size(), size()));
        check(ocean_relief_normals(get(), depth, out.data(), out.size()));
        return out;
    }
    /// The next mip level of the map (side N / 2, 2x2 means).
    relief_map downsample() const
    {
        OceanReliefMap *m = nullptr;
        check(ocean_relief_map_downsample(get(), &m));
        return relief_map(m);
    }
};

/// A cone map with its height map (`OceanReliefCones`), immutable and shareable.
class relief_cones : public detail::handle<OceanReliefCones, ocean_relief_cones_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanReliefCones, ocean_relief_cones_destroy>;
    using base::base;

    /// `ocean_relief_cones_create`; `progress` (may be null) is called with `user` and must
    /// not throw.
    static relief_cones create(const relief_map &map, const OceanReliefConeParams &params,
                               OceanReliefProgress progress = nullptr, void *user = nullptr)
    {
        OceanReliefCones *c = nullptr;
        check(ocean_relief_cones_create(map.get(), &params, progress, user, &c));
        return relief_cones(c);
    }
    /// `ocean_relief_cones_create` reporting to a callable `bool progress(done, total)` (true
    /// to go on; false cancels: ocean::error OCEAN_STATUS_CANCELLED). What it throws cancels
    /// the work and is rethrown from here.
    template <typename F, typename = detail::if_progress<F>>
    static relief_cones create(const relief_map &map, const OceanReliefConeParams &params,
                               F &&progress)
    {
        OceanReliefCones *c = nullptr;
        detail::with_progress(progress, [&](OceanReliefProgress p, void *user) {
            return ocean_relief_cones_create(map.get(), &params, p, user, &c);
        });
        return relief_cones(c);
    }
    /// The side N, texels.
    std::uint32_t size() const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_relief_cones_size(get(), o); });
    }
    /// The relief texture into `rgba`: [depth, c, D, E] per texel, exactly 4 N * N floats
    /// (else std::invalid_argument).
    void texels(span<float> rgba) const
    {
        detail::check_size("ocean::relief_cones::texels: rgba", rgba.size(),
                           4 * detail::mul(size(), size()));
        check(ocean_relief_cones_texels(get(), rgba.data(), rgba.size()));
    }
    /// The relief texture in a new vector.
    std::vector<float> texels() const
    {
        std::vector<float> out(4 * detail::mul(size(), size()));
        texels(out);
        return out;
    }
    /// The cone channels [c, D, E] encoded: T is std::uint8_t (UNORM8, UNORM8_SQRT),
    /// std::uint16_t (F16) or float (F32), else std::invalid_argument.
    template <typename T>
    std::vector<T> encode(std::uint32_t encoding) const
    {
        detail::check_encoding<T>("ocean::relief_cones::encode", encoding);
        std::vector<T> out(3 * detail::mul(size(), size()));
        check(ocean_relief_cones_encode(get(), encoding, out.data(), out.size()));
        return out;
    }
    /// The cones after a round trip through `encoding`.
    relief_cones quantize(std::uint32_t encoding) const
    {
        OceanReliefCones *c = nullptr;
        check(ocean_relief_cones_quantize(get(), encoding, &c));
        return relief_cones(c);
    }
    /// `ocean_relief_trace` of `rays` into `hits` (`rays.size()` elements, else
    /// std::invalid_argument).
    void trace(const OceanReliefMethod &method, span<const OceanReliefRay> rays,
               span<OceanReliefHit> hits) const
    {
        detail::check_size("ocean::relief_cones::trace: hits", hits.size(), rays.size());
        check(ocean_relief_trace(get(), &method, detail::ptr(rays), rays.size(), detail::ptr(hits)));
    }
    /// `ocean_relief_trace` into a new vector.
    std::vector<OceanReliefHit> trace(const OceanReliefMethod &method,
                                      span<const OceanReliefRay> rays) const
    {
        std::vector<OceanReliefHit> hits(rays.size());
        trace(method, rays, hits);
        return hits;
    }
    /// `ocean_relief_shadow`: 1 where `points[i]` is in shadow of the tangent-space light.
    std::vector<std::uint8_t> shadow(const OceanReliefMethod &method,
                                     span<const OceanReliefPoint> points, float light_x,
                                     float light_y, float light_z, float depth_scale,
                                     float bias) const
    {
        std::vector<std::uint8_t> out(points.size());
        check(ocean_relief_shadow(get(), &method, detail::ptr(points), points.size(), light_x,
                                  light_y, light_z, depth_scale, bias,
                                  detail::ptr(span<std::uint8_t>(out))));
        return out;
    }
};

/// The mip chain of a cone map (`OceanReliefMips`), immutable and shareable.
class relief_mips : public detail::handle<OceanReliefMips, ocean_relief_mips_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanReliefMips, ocean_relief_mips_destroy>;
    using base::base;

    /// `ocean_relief_mips_create`; `rule` OCEAN_RELIEF_MIP_WINDOW or _GROUP.
    static relief_mips create(const relief_cones &cones, std::uint32_t rule)
    {
        OceanReliefMips *m = nullptr;
        check(ocean_relief_mips_create(cones.get(), rule, &m));
        return relief_mips(m);
    }
    /// The number of levels, log2(N) + 1.
    std::uint32_t level_count() const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_relief_mips_level_count(get(), o); });
    }
    /// The side of `level`, texels.
    std::uint32_t level_size(std::uint32_t level) const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_relief_mips_level_size(get(), level, o); });
    }
    /// `level` encoded, [c, D, E] per texel (T as for relief_cones::encode).
    template <typename T>
    std::vector<T> level(std::uint32_t level, std::uint32_t encoding) const
    {
        detail::check_encoding<T>("ocean::relief_mips::level", encoding);
        const std::size_t side = level_size(level);
        std::vector<T> out(3 * side * side);
        check(ocean_relief_mips_copy_level(get(), level, encoding, out.data(), out.size()));
        return out;
    }
};

/// A quad-directional cone map with its height map (`OceanReliefQuadCones`).
class relief_quad_cones
    : public detail::handle<OceanReliefQuadCones, ocean_relief_quad_cones_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanReliefQuadCones, ocean_relief_quad_cones_destroy>;
    using base::base;

    /// `ocean_relief_quad_cones_create` (progress as for relief_cones::create).
    static relief_quad_cones create(const relief_map &map, const OceanReliefConeParams &params,
                                    OceanReliefProgress progress = nullptr, void *user = nullptr)
    {
        OceanReliefQuadCones *c = nullptr;
        check(ocean_relief_quad_cones_create(map.get(), &params, progress, user, &c));
        return relief_quad_cones(c);
    }
    /// `ocean_relief_quad_cones_create` with a progress callable, as relief_cones::create.
    template <typename F, typename = detail::if_progress<F>>
    static relief_quad_cones create(const relief_map &map, const OceanReliefConeParams &params,
                                    F &&progress)
    {
        OceanReliefQuadCones *c = nullptr;
        detail::with_progress(progress, [&](OceanReliefProgress p, void *user) {
            return ocean_relief_quad_cones_create(map.get(), &params, p, user, &c);
        });
        return relief_quad_cones(c);
    }
    /// The side N, texels.
    std::uint32_t size() const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_relief_quad_cones_size(get(), o); });
    }
    /// The 4 layers of the texture, 16 N * N floats.
    std::vector<float> texels() const
    {
        std::vector<float> out(16 * detail::mul(size(), size()));
        check(ocean_relief_quad_cones_texels(get(), out.data(), out.size()));
        return out;
    }
    /// `ocean_relief_quad_trace` into a new vector.
    std::vector<OceanReliefHit> trace(const OceanReliefMethod &method,
                                      span<const OceanReliefRay> rays) const
    {
        std::vector<OceanReliefHit> hits(rays.size());
        check(ocean_relief_quad_trace(get(), &method, detail::ptr(rays), rays.size(),
                                      detail::ptr(span<OceanReliefHit>(hits))));
        return hits;
    }
    /// `ocean_relief_quad_shadow` (as relief_cones::shadow).
    std::vector<std::uint8_t> shadow(const OceanReliefMethod &method,
                                     span<const OceanReliefPoint> points, float light_x,
                                     float light_y, float light_z, float depth_scale,
                                     float bias) const
    {
        std::vector<std::uint8_t> out(points.size());
        check(ocean_relief_quad_shadow(get(), &method, detail::ptr(points), points.size(),
                                       light_x, light_y, light_z, depth_scale, bias,
                                       detail::ptr(span<std::uint8_t>(out))));
        return out;
    }
};

/// The cone map of `map` generated straight into a vector: 4 N * N floats [depth, c, D, E].
inline std::vector<float> relief_generate_texels(const relief_map &map,
                                                 const OceanReliefConeParams &params,
                                                 OceanReliefProgress progress = nullptr,
                                                 void *user = nullptr)
{
    std::vector<float> out(4 * detail::mul(map.size(), map.size()));
    check(ocean_relief_generate_texels(map.get(), &params, progress, user, out.data(), out.size()));
    return out;
}
/// relief_generate_texels with a progress callable, as relief_cones::create.
template <typename F, typename = detail::if_progress<F>>
std::vector<float> relief_generate_texels(const relief_map &map,
                                          const OceanReliefConeParams &params, F &&progress)
{
    std::vector<float> out(4 * detail::mul(map.size(), map.size()));
    detail::with_progress(progress, [&](OceanReliefProgress p, void *user) {
        return ocean_relief_generate_texels(map.get(), &params, p, user, out.data(), out.size());
    });
    return out;
}
/// The cone map of `map` generated and encoded: 3 N * N elements (T as for
/// relief_cones::encode).
template <typename T>
std::vector<T> relief_generate_encoded(const relief_map &map, const OceanReliefConeParams &params,
                                       std::uint32_t encoding,
                                       OceanReliefProgress progress = nullptr,
                                       void *user = nullptr)
{
    detail::check_encoding<T>("ocean::relief_generate_encoded", encoding);
    std::vector<T> out(3 * detail::mul(map.size(), map.size()));
    check(ocean_relief_generate_encoded(map.get(), &params, progress, user, encoding, out.data(),
                                        out.size()));
    return out;
}
/// relief_generate_encoded with a progress callable, as relief_cones::create.
template <typename T, typename F, typename = detail::if_progress<F>>
std::vector<T> relief_generate_encoded(const relief_map &map, const OceanReliefConeParams &params,
                                       std::uint32_t encoding, F &&progress)
{
    detail::check_encoding<T>("ocean::relief_generate_encoded", encoding);
    std::vector<T> out(3 * detail::mul(map.size(), map.size()));
    detail::with_progress(progress, [&](OceanReliefProgress p, void *user) {
        return ocean_relief_generate_encoded(map.get(), &params, p, user, encoding, out.data(),
                                             out.size());
    });
    return out;
}
/// The quad-directional cone map of `map` generated straight into a vector: 16 N * N floats.
inline std::vector<float> relief_quad_generate_texels(const relief_map &map,
                                                      const OceanReliefConeParams &params,
                                                      OceanReliefProgress progress = nullptr,
                                                      void *user = nullptr)
{
    std::vector<float> out(16 * detail::mul(map.size(), map.size()));
    check(ocean_relief_quad_generate_texels(map.get(), &params, progress, user, out.data(),
                                            out.size()));
    return out;
}
/// relief_quad_generate_texels with a progress callable, as relief_cones::create.
template <typename F, typename = detail::if_progress<F>>
std::vector<float> relief_quad_generate_texels(const relief_map &map,
                                               const OceanReliefConeParams &params, F &&progress)
{
    std::vector<float> out(16 * detail::mul(map.size(), map.size()));
    detail::with_progress(progress, [&](OceanReliefProgress p, void *user) {
        return ocean_relief_quad_generate_texels(map.get(), &params, p, user, out.data(),
                                                 out.size());
    });
    return out;
}
/// The ray of a tangent-space view vector entering at (start_u, start_v), `depth` deep.
inline OceanReliefRay relief_ray_from_view(float start_u, float start_v, float view_x,
                                           float view_y, float view_z, float depth)
{
    return detail::out<OceanReliefRay>([&](OceanReliefRay *o) {
        return ocean_relief_ray_from_view(start_u, start_v, view_x, view_y, view_z, depth, o);
    });
}
/// Width and height, texels, of a mip atlas.
struct relief_atlas_extent {
    std::uint32_t width;  ///< Texels.
    std::uint32_t height; ///< Texels.
};
/// The size of the relief texture holding `levels` levels of side `size`.
inline relief_atlas_extent relief_mip_atlas_size(std::uint32_t size, std::uint32_t levels)
{
    relief_atlas_extent e{};
    check(ocean_relief_mip_atlas_size(size, levels, &e.width, &e.height));
    return e;
}
/// A texel position in a mip atlas.
struct relief_atlas_point {
    std::uint32_t x; ///< Texels from the first column.
    std::uint32_t y; ///< Texels from the first row.
};
/// Where `level` starts in the atlas.
inline relief_atlas_point relief_mip_atlas_origin(std::uint32_t size, std::uint32_t level)
{
    relief_atlas_point p{};
    check(ocean_relief_mip_atlas_origin(size, level, &p.x, &p.y));
    return p;
}
/// The mip level the `relief` shader reads for these texture-coordinate derivatives.
inline std::uint32_t relief_mip_level(float du_x, float du_y, float dv_x, float dv_y,
                                      std::uint32_t size, std::uint32_t levels)
{
    return detail::out<std::uint32_t>([&](std::uint32_t *o) {
        return ocean_relief_mip_level(du_x, du_y, dv_x, dv_y, size, levels, o);
    });
}

} // namespace ocean

#endif // OCEAN_HPP_RELIEF
