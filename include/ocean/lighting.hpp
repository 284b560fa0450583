/// \file ocean/lighting.hpp
/// Part of ocean.hpp: the spectrum, lighting, sky map and the BRDF functions.
/// Include ocean.hpp, not this file; its notes (errors, handles, spans, units) apply here.
#ifndef OCEAN_HPP_LIGHTING
#define OCEAN_HPP_LIGHTING

#ifndef OCEAN_HPP
#error "include ocean.hpp, not its parts"
#endif

namespace ocean {

// ---------------------------------------------------------------------------------------------
// Spectrum, lighting, sky map, BRDF

/// A sampled wave spectrum (`OceanSpectrum`), immutable and shareable.
class spectrum : public detail::handle<OceanSpectrum, ocean_spectrum_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanSpectrum, ocean_spectrum_destroy>;
    using base::base;

    /// `ocean_spectrum_create` (start from `defaults<OceanSpectrumParams>()`).
    static spectrum create(const OceanSpectrumParams &params)
    {
        OceanSpectrum *s = nullptr;
        check(ocean_spectrum_create(&params, &s));
        return spectrum(s);
    }
    /// The number of waves.
    std::size_t wave_count() const
    {
        return detail::out<std::size_t>(
            [&](std::size_t *o) { return ocean_spectrum_wave_count(get(), o); });
    }
    /// The waves, shortest first, as descriptions `waves::create` accepts.
    std::vector<OceanWaveDesc> waves() const
    {
        std::vector<OceanWaveDesc> out(wave_count());
        check(ocean_spectrum_waves(get(), out.data(), out.size()));
        return out;
    }
    /// The unit wind direction (x, z).
    OceanDVec2 wind_direction() const
    {
        return detail::out<OceanDVec2>(
            [&](OceanDVec2 *o) { return ocean_spectrum_wind_direction(get(), o); });
    }
    /// How many waves were clamped to the largest steepness.
    std::size_t clamped_count() const
    {
        return detail::out<std::size_t>(
            [&](std::size_t *o) { return ocean_spectrum_clamped_count(get(), o); });
    }
    /// The largest amplitude, metres.
    double max_amplitude() const
    {
        return detail::out<double>([&](double *o) { return ocean_spectrum_max_amplitude(get(), o); });
    }
    /// The sum of the steepnesses k A.
    double steepness_sum() const
    {
        return detail::out<double>([&](double *o) { return ocean_spectrum_steepness_sum(get(), o); });
    }
    /// The mean height of the surface, metres.
    double mean_height_shift() const
    {
        return detail::out<double>(
            [&](double *o) { return ocean_spectrum_mean_height_shift(get(), o); });
    }
    /// The variance of the height about its mean, m^2.
    double height_variance() const
    {
        return detail::out<double>(
            [&](double *o) { return ocean_spectrum_height_variance(get(), o); });
    }
    /// The slope variance of all the waves (Eq. 4 with w_r = 1).
    OceanSlopeVariance total_slope_variance() const
    {
        return detail::out<OceanSlopeVariance>(
            [&](OceanSlopeVariance *o) { return ocean_spectrum_total_slope_variance(get(), o); });
    }
    /// The slope variance of the waves a pixel of `pixel_footprint` metres does not resolve.
    OceanSlopeVariance slope_variance(double n_min, double n_max, double pixel_footprint) const
    {
        return detail::out<OceanSlopeVariance>([&](OceanSlopeVariance *o) {
            return ocean_spectrum_slope_variance(get(), n_min, n_max, pixel_footprint, o);
        });
    }
};

/// A mip-mapped sky map of one lighting (`OceanSkyMap`), immutable and shareable.
class sky_map : public detail::handle<OceanSkyMap, ocean_sky_map_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanSkyMap, ocean_sky_map_destroy>;
    using base::base;

    /// The number of mip levels, log2(size) + 1.
    std::uint32_t level_count() const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_sky_map_level_count(get(), o); });
    }
    /// The side of mip `level`, texels.
    std::uint32_t level_size(std::uint32_t level) const
    {
        return detail::out<std::uint32_t>(
            [&](std::uint32_t *o) { return ocean_sky_map_level_info(get(), level, o); });
    }
    /// Copies mip `level` into `rgba`: side * side RGBA float texels, row-major (exactly
    /// 4 side^2 floats, else std::invalid_argument).
    void copy_level(std::uint32_t level, span<float> rgba) const
    {
        const std::size_t side = level_size(level);
        detail::check_size("ocean::sky_map::copy_level: rgba", rgba.size(), 4 * side * side);
        check(ocean_sky_map_copy_level(get(), level, rgba.data(), rgba.size()));
    }
    /// Mip `level` in a new vector.
    std::vector<float> level(std::uint32_t level) const
    {
        const std::size_t side = level_size(level);
        std::vector<float> rgba(4 * side * side);
        copy_level(level, rgba);
        return rgba;
    }
};

/// The Sun, the sky and the sea (`OceanLighting`), immutable and shareable.
class lighting : public detail::handle<OceanLighting, ocean_lighting_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanLighting, ocean_lighting_destroy>;
    using base::base;

    /// `ocean_lighting_create` (start from `defaults<OceanSkyParams>()` and
    /// `defaults<OceanSeaParams>()`).
    static lighting create(const OceanSkyParams &sky, const OceanSeaParams &sea)
    {
        OceanLighting *l = nullptr;
        check(ocean_lighting_create(&sky, &sea, &l));
        return lighting(l);
    }
    /// The sky's irradiance on the horizontal sea, linear RGB.
    OceanRgb sky_irradiance() const { return rgb(ocean_lighting_sky_irradiance); }
    /// The environment's irradiance on every orientation (order-2 spherical harmonics).
    OceanIrradiance irradiance() const
    {
        return detail::out<OceanIrradiance>(
            [&](OceanIrradiance *o) { return ocean_lighting_irradiance(get(), o); });
    }
    /// L_sea, the diffuse radiance leaving the water body, linear RGB.
    OceanRgb sea_radiance() const { return rgb(ocean_lighting_sea_radiance); }
    /// The radiance shown at and below the horizon, linear RGB.
    OceanRgb below_horizon_radiance() const { return rgb(ocean_lighting_below_horizon_radiance); }
    /// The Sun's radiance over its disc, linear RGB.
    OceanRgb sun_radiance() const { return rgb(ocean_lighting_sun_radiance); }
    /// The Sun's solid angle, steradians.
    double sun_solid_angle() const
    {
        return detail::out<double>([&](double *o) { return ocean_lighting_sun_solid_angle(get(), o); });
    }
    /// The environment's radiance towards the unit direction `dir` (world, y up).
    OceanRgb environment_radiance(OceanDVec3 dir) const
    {
        return detail::out<OceanRgb>(
            [&](OceanRgb *o) { return ocean_lighting_environment_radiance(get(), dir, o); });
    }
    /// `ocean_lighting_sky_map_create`: the sky map, `size` texels square at level 0.
    ocean::sky_map sky_map(std::uint32_t size) const
    {
        OceanSkyMap *m = nullptr;
        check(ocean_lighting_sky_map_create(get(), size, &m));
        return ocean::sky_map(m);
    }
    /// `ocean_sea_color`: the sea's radiance towards the viewer for one pixel.
    OceanSeaLight sea_color(const ocean::sky_map &map, OceanDVec3 v, OceanDVec3 n,
                            OceanDVec2 wind, double sigma_x2, double sigma_y2) const
    {
        return detail::out<OceanSeaLight>([&](OceanSeaLight *o) {
            return ocean_sea_color(get(), map.get(), v, n, wind, sigma_x2, sigma_y2, o);
        });
    }
    /// `ocean_sea_color_batch` into `out` (`inputs.size()` elements, else
    /// std::invalid_argument).
    void sea_color(const ocean::sky_map &map, span<const OceanSeaColorInput> inputs,
                   span<OceanSeaLight> out) const
    {
        detail::check_size("ocean::lighting::sea_color: out", out.size(), inputs.size());
        check(ocean_sea_color_batch(get(), map.get(), detail::ptr(inputs), inputs.size(),
                                    detail::ptr(out)));
    }
    /// `ocean_sea_color_batch` into a new vector.
    std::vector<OceanSeaLight> sea_color(const ocean::sky_map &map,
                                         span<const OceanSeaColorInput> inputs) const
    {
        std::vector<OceanSeaLight> out(inputs.size());
        sea_color(map, inputs, out);
        return out;
    }

private:
    OceanRgb rgb(OceanStatus (*f)(const OceanLighting *, OceanRgb *)) const
    {
        return detail::out<OceanRgb>([&](OceanRgb *o) { return f(get(), o); });
    }
};

/// The Ross BRDF with Schlick's Fresnel factor, 1/steradian (`ocean_ross_brdf`).
inline double ross_brdf(OceanDVec3 v, OceanDVec3 l, double sigma_x2, double sigma_y2, double r)
{
    return detail::out<double>(
        [&](double *o) { return ocean_ross_brdf(v, l, sigma_x2, sigma_y2, r, o); });
}
/// The Sun's reflected radiance (Eq. 15, `ocean_sun_radiance`).
inline double sun_radiance(OceanDVec3 v, OceanDVec3 l, double sigma_x2, double sigma_y2,
                           double l_sun, double omega_sun, double r)
{
    return detail::out<double>([&](double *o) {
        return ocean_sun_radiance(v, l, sigma_x2, sigma_y2, l_sun, omega_sun, r, o);
    });
}
/// Schlick's Fresnel approximation (Eq. 14).
inline double schlick(double cos_theta, double r)
{
    return detail::out<double>([&](double *o) { return ocean_schlick(cos_theta, r, o); });
}
/// The effective Fresnel factor by the paper's fit (Eq. 26).
inline double effective_fresnel_fit(double cos_theta_v, double sigma_v, double r)
{
    return detail::out<double>(
        [&](double *o) { return ocean_effective_fresnel_fit(cos_theta_v, sigma_v, r, o); });
}
/// The effective Fresnel factor from the library's table.
inline double effective_fresnel_table(double cos_theta_v, double sigma_v, double r)
{
    return detail::out<double>(
        [&](double *o) { return ocean_effective_fresnel_table(cos_theta_v, sigma_v, r, o); });
}
/// The effective Fresnel factor by numerical integration (Eq. 24).
inline double effective_fresnel_integral(OceanDVec3 v, double sigma_x2, double sigma_y2, double r)
{
    return detail::out<double>([&](double *o) {
        return ocean_effective_fresnel_integral(v, sigma_x2, sigma_y2, r, o);
    });
}
/// Exponential tone mapping 1 - exp(-exposure L), linear values in [0, 1].
inline OceanRgb tone_map(OceanRgb radiance, double exposure = OCEAN_DEFAULT_EXPOSURE)
{
    return detail::out<OceanRgb>([&](OceanRgb *o) { return ocean_tone_map(radiance, exposure, o); });
}
/// The sRGB transfer function of a linear value in [0, 1].
inline double linear_to_srgb(double linear)
{
    return detail::out<double>([&](double *o) { return ocean_linear_to_srgb(linear, o); });
}
/// The footprint of pixel (px, py) of a width x height viewport on the sea at rest, metres
/// (`ocean_pixel_footprint`; `camera`: see make_camera).
inline double pixel_footprint(const OceanCamera &camera, std::uint32_t width,
                              std::uint32_t height, double px, double py, double max_distance)
{
    return detail::out<double>([&](double *o) {
        return ocean_pixel_footprint(&camera, width, height, px, py, max_distance, o);
    });
}

} // namespace ocean

#endif // OCEAN_HPP_LIGHTING
