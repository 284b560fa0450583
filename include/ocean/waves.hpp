/// \file ocean/waves.hpp
/// Part of ocean.hpp: trochoid waves (ocean::waves) and Wave Train Boxes (ocean::wtb_scene).
/// Include ocean.hpp, not this file; its notes (errors, handles, spans, units) apply here.
#ifndef OCEAN_HPP_WAVES
#define OCEAN_HPP_WAVES

#ifndef OCEAN_HPP
#error "include ocean.hpp, not its parts"
#endif

namespace ocean {

// ---------------------------------------------------------------------------------------------
// Trochoid waves

/// Displaced positions and unit normals of a batch of surface points, in the order of the input.
struct surface_points {
    /// Positions, metres, relative to the grid's origin.
    std::vector<OceanVec3> positions;
    /// Unit normals, y up.
    std::vector<OceanVec3> normals;
};

/// Displaced world positions (double precision) and unit normals of `waves::evaluate`.
struct world_points {
    /// World positions, metres.
    std::vector<OceanDVec3> positions;
    /// Unit normals, y up.
    std::vector<OceanVec3> normals;
};

/// An immutable set of trochoid (Gerstner) waves (`OceanWaves`); shareable between threads.
class waves : public detail::handle<OceanWaves, ocean_waves_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanWaves, ocean_waves_destroy>;
    using base::base;

    /// `ocean_waves_create` from the descriptions (copied).
    static waves create(span<const OceanWaveDesc> descs)
    {
        OceanWaves *w = nullptr;
        check(ocean_waves_create(detail::ptr(descs), descs.size(), &w));
        return waves(w);
    }
    /// The number of waves.
    std::size_t count() const
    {
        return detail::out<std::size_t>([&](std::size_t *o) { return ocean_waves_count(get(), o); });
    }
    /// The sum of the steepnesses k A (dimensionless).
    double steepness_sum() const
    {
        return detail::out<double>([&](double *o) { return ocean_waves_steepness_sum(get(), o); });
    }
    /// The sum of the amplitudes, metres: the largest displacement any point can reach.
    double max_amplitude() const
    {
        return detail::out<double>([&](double *o) { return ocean_waves_max_amplitude(get(), o); });
    }
    /// `ocean_waves_evaluate` of the world rest points `xz` (x, z in double precision) at
    /// `time` seconds into world `positions` and `normals`, each of `xz.size()` elements (else
    /// std::invalid_argument).
    void evaluate(span<const OceanDVec2> xz, double time, span<OceanDVec3> positions,
                  span<OceanVec3> normals) const
    {
        detail::check_size("ocean::waves::evaluate: positions", positions.size(), xz.size());
        detail::check_size("ocean::waves::evaluate: normals", normals.size(), xz.size());
        check(ocean_waves_evaluate(get(), detail::ptr(xz), xz.size(), time,
                                   detail::ptr(positions), detail::ptr(normals)));
    }
    /// `ocean_waves_evaluate` into new vectors.
    world_points evaluate(span<const OceanDVec2> xz, double time) const
    {
        world_points s{std::vector<OceanDVec3>(xz.size()), std::vector<OceanVec3>(xz.size())};
        evaluate(xz, time, s.positions, s.normals);
        return s;
    }
    /// `ocean_waves_evaluate_grid` at `time` seconds into `positions` and `normals`, each of
    /// nx * nz elements (else std::invalid_argument), row-major, relative to the grid's origin.
    void evaluate_grid(const OceanGrid &grid, double time, span<OceanVec3> positions,
                       span<OceanVec3> normals) const
    {
        const std::size_t n = detail::mul(grid.nx, grid.nz);
        detail::check_size("ocean::waves::evaluate_grid: positions", positions.size(), n);
        detail::check_size("ocean::waves::evaluate_grid: normals", normals.size(), n);
        check(ocean_waves_evaluate_grid(get(), &grid, time, detail::ptr(positions),
                                        detail::ptr(normals)));
    }
    /// `ocean_waves_evaluate_grid` into new vectors.
    surface_points evaluate_grid(const OceanGrid &grid, double time) const
    {
        const std::size_t n = detail::mul(grid.nx, grid.nz);
        surface_points s{std::vector<OceanVec3>(n), std::vector<OceanVec3>(n)};
        evaluate_grid(grid, time, s.positions, s.normals);
        return s;
    }
};

// ---------------------------------------------------------------------------------------------
// Wave Train Boxes

/// A Wave Train Boxes scene (`OceanWtbScene`): water grid, terrain, boxes, effects, budget.
/// The C functions take a non-const scene even to query it, and so do these methods.
class wtb_scene : public detail::handle<OceanWtbScene, ocean_wtb_scene_destroy> {
public:
    /// The owner: get(), release(), reset(), moves; constructible from a raw handle it adopts.
    using base = detail::handle<OceanWtbScene, ocean_wtb_scene_destroy>;
    using base::base;

    /// `ocean_wtb_scene_create`: `terrain` holds nx * nz heights above the sea at rest (metres,
    /// row-major), or is empty for an open sea of infinite depth.
    static wtb_scene create(const OceanWaterGridDesc &grid, span<const float> terrain = {})
    {
        OceanWtbScene *s = nullptr;
        check(ocean_wtb_scene_create(&grid, terrain.data(), terrain.size(), &s));
        return wtb_scene(s);
    }
    /// Replaces the terrain (empty: a deep sea).
    void set_terrain(span<const float> terrain)
    {
        check(ocean_wtb_scene_set_terrain(get(), terrain.data(), terrain.size()));
    }
    /// Adds a box; `trains` empty: the wind raises `desc.wind.trains` trains. Returns its id.
    std::uint32_t add_box(const OceanBoxDesc &desc, span<const OceanWaveDesc> trains = {})
    {
        return detail::out<std::uint32_t>([&](std::uint32_t *id) {
            return ocean_wtb_scene_add_box(get(), &desc, trains.data(), trains.size(), id);
        });
    }
    /// Replaces box `id`'s description (as add_box).
    void update_box(std::uint32_t id, const OceanBoxDesc &desc,
                    span<const OceanWaveDesc> trains = {})
    {
        check(ocean_wtb_scene_update_box(get(), id, &desc, trains.data(), trains.size()));
    }
    /// Removes box `id` (`OCEAN_STATUS_NOT_FOUND` if it is not in the scene).
    void remove_box(std::uint32_t id) { check(ocean_wtb_scene_remove_box(get(), id)); }
    /// The number of boxes, alive or not.
    std::size_t box_count() const
    {
        return detail::out<std::size_t>(
            [&](std::size_t *o) { return ocean_wtb_scene_box_count(get(), o); });
    }
    /// Enables and parameterises the effects.
    void set_effects(const OceanEffects &effects)
    {
        check(ocean_wtb_scene_set_effects(get(), &effects));
    }
    /// Removes any budget limit (the default).
    void set_budget_unlimited() { check(ocean_wtb_scene_set_budget_unlimited(get())); }
    /// Limits each evaluation to about `seconds` of estimated work on one core.
    void set_budget_seconds(double seconds)
    {
        check(ocean_wtb_scene_set_budget_seconds(get(), seconds));
    }
    /// At most `max_trains` trains per box (SIZE_MAX: all) and exactly `effects`.
    void set_budget_explicit(std::size_t max_trains, const OceanEffects &effects)
    {
        check(ocean_wtb_scene_set_budget_explicit(get(), max_trains, &effects));
    }
    /// Weights the trains by grid cells per wavelength (0 and 0: keep every train whole).
    void set_train_filter(double min_cells, double max_cells)
    {
        check(ocean_wtb_scene_set_train_filter(get(), min_cells, max_cells));
    }
    /// `ocean_wtb_scene_evaluate` at `time` seconds into `positions` and `normals` (nx * nz
    /// each, row-major, relative to the grid origin; the two sizes must agree, else
    /// std::invalid_argument, and equal nx * nz, else ocean::error). `camera`: null for no
    /// culling, or the camera the frame is drawn with (see make_camera). Returns what ran.
    OceanFrameStats evaluate(double time, const OceanCamera *camera, span<OceanVec3> positions,
                             span<OceanVec3> normals)
    {
        detail::check_size("ocean::wtb_scene::evaluate: normals", normals.size(),
                           positions.size());
        return detail::out<OceanFrameStats>([&](OceanFrameStats *stats) {
            return ocean_wtb_scene_evaluate(get(), time, camera, detail::ptr(positions),
                                            detail::ptr(normals), positions.size(), stats);
        });
    }
    /// `ocean_wtb_scene_evaluate_incremental`: as evaluate, writing only what changed since
    /// the last call into the same buffers.
    OceanFrameStats evaluate_incremental(double time, const OceanCamera *camera,
                                         span<OceanVec3> positions, span<OceanVec3> normals)
    {
        detail::check_size("ocean::wtb_scene::evaluate_incremental: normals", normals.size(),
                           positions.size());
        return detail::out<OceanFrameStats>([&](OceanFrameStats *stats) {
            return ocean_wtb_scene_evaluate_incremental(
                get(), time, camera, detail::ptr(positions), detail::ptr(normals),
                positions.size(), stats);
        });
    }
    /// Makes the next evaluate_incremental write the whole grid.
    void reset_coverage() { check(ocean_wtb_scene_reset_coverage(get())); }
    /// Height queries at world (x, z) on the drawn mesh of the last evaluation into `out`
    /// (`xz.size()` elements, else std::invalid_argument).
    void heights_drawn(span<const OceanDVec2> xz, span<OceanDrawnSample> out) const
    {
        detail::check_size("ocean::wtb_scene::heights_drawn: out", out.size(), xz.size());
        check(ocean_wtb_scene_heights_drawn(get(), detail::ptr(xz), xz.size(), detail::ptr(out)));
    }
    /// heights_drawn into a new vector.
    std::vector<OceanDrawnSample> heights_drawn(span<const OceanDVec2> xz) const
    {
        std::vector<OceanDrawnSample> out(xz.size());
        heights_drawn(xz, out);
        return out;
    }
    /// Height queries at world (x, z) and `time` seconds on the continuous surface into `out`
    /// (`xz.size()` elements, else std::invalid_argument).
    void heights_continuous(double time, span<const OceanDVec2> xz,
                            span<OceanHeightSample> out) const
    {
        detail::check_size("ocean::wtb_scene::heights_continuous: out", out.size(), xz.size());
        check(ocean_wtb_scene_heights_continuous(get(), time, detail::ptr(xz), xz.size(),
                                                 detail::ptr(out)));
    }
    /// heights_continuous into a new vector.
    std::vector<OceanHeightSample> heights_continuous(double time,
                                                      span<const OceanDVec2> xz) const
    {
        std::vector<OceanHeightSample> out(xz.size());
        heights_continuous(time, xz, out);
        return out;
    }
};

} // namespace ocean

#endif // OCEAN_HPP_WAVES
