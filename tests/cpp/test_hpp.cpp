// C++17 test of include/ocean.hpp, the header-only wrapper over the C ABI, linked against the
// library (the full libocean with -DOCEAN_GPU, or libocean-cpu without).
//
// Built and run by tests/tests/c_abi.rs with
//   c++ -std=c++17 -Wall -Wextra -Werror -pedantic -DOCEAN_GPU -I include tests/cpp/test_hpp.cpp libocean.a ...
//
// What it checks:
// - every CPU handle type created, used and destroyed through its RAII owner: moves leave the
//   source empty, move assignment and scope exit destroy (the raw handle is then refused with
//   OCEAN_STATUS_INVALID_HANDLE), release() hands the handle over;
// - errors: a failing call throws ocean::error with the C status and the last-error message
//   naming the C function, copied at the call; wrong buffer sizes throw std::invalid_argument;
// - every span and vector overload against the raw C call on the same inputs, bit for bit;
// - ocean::defaults<T>() against the C _default functions; the version check;
// - with OCEAN_GPU: the shader export and the draw data of the exported shaders (no adapter
//   needed), and the context, renderer and GPU SAO where an adapter exists (skipped otherwise).
//
// Prints a summary; exits 0 only if every check passed.
#include "ocean.hpp"

#include "../c/check.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Element-wise equality of the bytes of two arrays of a padding-free C struct.
template <typename T>
bool same(const std::vector<T> &a, const T *b, std::size_t n)
{
    return a.size() == n && (n == 0 || std::memcmp(a.data(), b, n * sizeof(T)) == 0);
}
template <typename T>
bool same(const std::vector<T> &a, const std::vector<T> &b)
{
    return same(a, b.data(), b.size());
}
template <typename T>
bool same_value(const T &a, const T &b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// `f` throws ocean::error with `want`, a message naming `function`, kept after later calls.
template <typename F>
void expect_error(F &&f, OceanStatus want, const char *function, const char *what)
{
    try {
        f();
        CHECK(false, "%s: no exception", what);
    } catch (const ocean::error &e) {
        CHECK(e.status() == want, "%s: status %u (%s), expected %u", what, unsigned(e.status()),
              ocean_status_message(e.status()), unsigned(want));
        // A successful call clears the thread's message; the exception keeps its copy.
        (void)ocean::defaults<OceanSeaParams>();
        CHECK(ocean_last_error_message()[0] == '\0', "%s: a success left a message", what);
        CHECK(std::strstr(e.what(), function) != nullptr, "%s: message \"%s\" lacks \"%s\"",
              what, e.what(), function);
        CHECK(dynamic_cast<const std::runtime_error *>(&e) != nullptr, "%s: not a runtime_error",
              what);
    } catch (const std::exception &e) {
        CHECK(false, "%s: another exception: %s", what, e.what());
    }
}

// `f` throws std::invalid_argument (a wrong buffer size or element type).
template <typename F>
void expect_invalid(F &&f, const char *what)
{
    try {
        f();
        CHECK(false, "%s: no exception", what);
    } catch (const std::invalid_argument &) {
        CHECK(true, "%s", what);
    } catch (const std::exception &e) {
        CHECK(false, "%s: another exception: %s", what, e.what());
    }
}

// The RAII contract of owner type H: `make()` creates one, `query(raw)` is a C call on a raw
// handle. Moves transfer, move assignment and scope exit destroy, release() hands over.
template <typename H, typename Make, typename Query>
void raii(const char *name, Make make, Query query)
{
    static_assert(!std::is_copy_constructible<H>::value, "owners are move-only");
    static_assert(!std::is_copy_assignable<H>::value, "owners are move-only");
    static_assert(std::is_nothrow_move_constructible<H>::value, "noexcept moves");
    static_assert(std::is_nothrow_move_assignable<H>::value, "noexcept moves");

    decltype(make().get()) raw = nullptr;
    {
        H a = make();
        raw = a.get();
        CHECK(a && raw != nullptr && query(raw) == OCEAN_STATUS_OK, "%s: created", name);
        H b = std::move(a);
        CHECK(!a && a.get() == nullptr && b.get() == raw, "%s: move construction", name);
        H c = make();
        auto *other = c.get();
        c = std::move(b); // destroys c's own handle
        CHECK(!b && c.get() == raw, "%s: move assignment", name);
        CHECK(query(other) == OCEAN_STATUS_INVALID_HANDLE,
              "%s: move assignment did not destroy the old handle", name);
        CHECK(query(raw) == OCEAN_STATUS_OK, "%s: the moved handle is alive", name);
    }
    CHECK(query(raw) == OCEAN_STATUS_INVALID_HANDLE, "%s: scope exit did not destroy it", name);
    H d = make();
    auto *kept = d.release();
    CHECK(!d && query(kept) == OCEAN_STATUS_OK, "%s: release", name);
    H e(kept); // adopt it again, destroyed by reset()
    e.reset();
    CHECK(!e && query(kept) == OCEAN_STATUS_INVALID_HANDLE, "%s: reset", name);
}

const std::vector<OceanWaveDesc> kWaves = {
    {0.6, 18.0, 0.2, 1.0, 0.1, INFINITY},
    {0.3, 7.0, 1.0, -0.5, 1.9, 1.5},
    {0.15, 4.2, -1.0, -1.0, -2.2, INFINITY},
};

// A camera 4 m above the sea looking along -z, 60 degrees, [0, 1] depth (glm::perspectiveRH_ZO's
// matrix, written out), made with ocean::make_camera.
OceanCamera test_camera()
{
    std::array<double, 16> view{}, projection{};
    for (int i = 0; i < 4; i++)
        view[5 * i] = 1.0;
    view[13] = -4.0; // world-to-view: a translation by (0, -4, 0)
    const double n = 0.1, f = 1000.0, t = std::tan(30.0 * kPi / 180.0);
    projection[0] = 1.0 / (64.0 / 48.0 * t);
    projection[5] = 1.0 / t;
    projection[10] = f / (n - f);
    projection[11] = -1.0;
    projection[14] = -(f * n) / (f - n);
    return ocean::make_camera(view, projection, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE);
}

// make_camera copies the matrices element by element (floats widened exactly) and the
// convention; a null matrix is refused before the library sees it.
void test_make_camera()
{
    const OceanCamera c = test_camera();
    CHECK(c.view[13] == -4.0 && c.projection[11] == -1.0 && c.reserved == 0 &&
              c.depth_convention == OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE,
          "make_camera (arrays)");
    float view[16], projection[16];
    for (int i = 0; i < 16; i++) {
        view[i] = float(c.view[i]);
        projection[i] = float(c.projection[i]);
    }
    const OceanCamera f =
        ocean::make_camera(view, projection, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED);
    bool widened = f.depth_convention == OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED;
    for (int i = 0; i < 16; i++)
        widened = widened && f.view[i] == double(view[i]) &&
                  f.projection[i] == double(projection[i]);
    CHECK(widened, "make_camera (floats)");
    expect_invalid([&] { (void)ocean::make_camera<float>(nullptr, projection,
                                                         OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE); },
                   "make_camera: null view");
    // The library checks the convention against the matrix: this forward-Z matrix declared
    // reversed puts its far plane before its near plane.
    expect_error([&] { (void)ocean::pixel_footprint(f, 64, 48, 32.5, 40.5, 5000.0); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "far plane", "make_camera: wrong convention");
}

void test_version_and_defaults()
{
    CHECK(ocean::version() == ocean_version(), "version %s", ocean::version().c_str());
    char header[64];
    std::snprintf(header, sizeof header, "%d.%d.%d", OCEAN_VERSION_MAJOR, OCEAN_VERSION_MINOR,
                  OCEAN_VERSION_PATCH);
    CHECK(ocean::header_version() == header, "header version %s", header);
    try {
        ocean::check_version();
        CHECK(true, "check_version");
    } catch (const std::exception &e) {
        CHECK(false, "check_version: %s", e.what());
    }
    // A header one minor version ahead is refused, with the status check() throws.
    expect_error([&] { ocean::check(ocean_check_version(OCEAN_VERSION + (1u << 8))); },
                 OCEAN_STATUS_VERSION_MISMATCH, "ocean_check_version", "check_version: a newer header");
    ocean::error e(OCEAN_STATUS_TOO_STEEP, "");
    CHECK(e.status() == OCEAN_STATUS_TOO_STEEP && std::strstr(e.what(), "steep"),
          "an error without a message takes the status text: %s", e.what());

    OceanSkyParams sky{};
    OceanSeaParams sea{};
    OceanSpectrumParams sp{};
    OceanEffects fx{};
    OceanReliefConeParams cp{};
    OceanSaoParams sao{};
    OK(ocean_sky_params_default(&sky));
    OK(ocean_sea_params_default(&sea));
    OK(ocean_spectrum_params_default(&sp));
    OK(ocean_wtb_effects_default(&fx));
    OK(ocean_relief_cone_params_default(&cp));
    OK(ocean_sao_params_default(&sao));
    const auto sky2 = ocean::defaults<OceanSkyParams>();
    CHECK(same_value(sky2.sun_direction, sky.sun_direction) &&
              sky2.sun_angular_radius == sky.sun_angular_radius,
          "defaults<OceanSkyParams>");
    const auto sea2 = ocean::defaults<OceanSeaParams>();
    CHECK(same_value(sea2.albedo, sea.albedo) && sea2.fresnel_r == sea.fresnel_r,
          "defaults<OceanSeaParams>");
    const auto sp2 = ocean::defaults<OceanSpectrumParams>();
    CHECK(sp2.wave_count == sp.wave_count && sp2.wind_speed == sp.wind_speed &&
              sp2.seed == sp.seed,
          "defaults<OceanSpectrumParams>");
    const auto fx2 = ocean::defaults<OceanEffects>();
    CHECK(fx2.refraction == fx.refraction && fx2.shoaling == fx.shoaling &&
              fx2.noise.enabled == fx.noise.enabled,
          "defaults<OceanEffects>");
    const auto cp2 = ocean::defaults<OceanReliefConeParams>();
    CHECK(cp2.kind == cp.kind && cp2.max_ratio == cp.max_ratio, "defaults<OceanReliefConeParams>");
    const auto sao2 = ocean::defaults<OceanSaoParams>();
    CHECK(sao2.radius == sao.radius && sao2.samples == sao.samples &&
              sao2.blur.taps == sao.blur.taps,
          "defaults<OceanSaoParams>");
}

void test_span()
{
    std::vector<float> v{1.0f, 2.0f, 3.0f};
    const std::array<float, 2> a{{4.0f, 5.0f}};
    float c[4] = {6.0f, 7.0f, 8.0f, 9.0f};
    ocean::span<float> sv(v);
    ocean::span<const float> sa(a), sc(c), sv2(sv);
    ocean::span<const float> sp(v.data() + 1, 2);
    CHECK(sv.data() == v.data() && sv.size() == 3 && sa.size() == 2 && sa[1] == 5.0f &&
              sc.size() == 4 && sc.data() == c && sv2.data() == v.data() && sp[0] == 2.0f,
          "span construction");
    float sum = 0.0f;
    for (float x : sc)
        sum += x;
    CHECK(sum == 30.0f && !sc.empty() && ocean::span<const float>().empty(), "span iteration");
    static_assert(!std::is_constructible<ocean::span<float>, const std::vector<float> &>::value,
                  "no mutable span of a const container");
    static_assert(!std::is_constructible<ocean::span<float>, std::vector<double> &>::value,
                  "no span of another element type");
}

void test_waves()
{
    raii<ocean::waves>(
        "waves", [] { return ocean::waves::create(kWaves); },
        [](OceanWaves *w) {
            std::size_t n = 0;
            return ocean_waves_count(w, &n);
        });

    const ocean::waves w = ocean::waves::create(kWaves);
    std::size_t count = 0;
    double steep = 0.0, amp = 0.0;
    OK(ocean_waves_count(w.get(), &count));
    OK(ocean_waves_steepness_sum(w.get(), &steep));
    OK(ocean_waves_max_amplitude(w.get(), &amp));
    CHECK(w.count() == count && count == 3 && w.steepness_sum() == steep &&
              w.max_amplitude() == amp,
          "waves queries");

    std::vector<OceanDVec2> xz;
    for (int i = 0; i < 37; i++)
        xz.push_back(OceanDVec2{double(i) * 1.25 - 20.0, double(i % 7) * 3.5});
    std::vector<OceanDVec3> pos(xz.size());
    std::vector<OceanVec3> nrm(xz.size());
    OK(ocean_waves_evaluate(w.get(), xz.data(), xz.size(), 12.5, pos.data(), nrm.data()));
    const ocean::world_points s = w.evaluate(xz, 12.5);
    CHECK(same(s.positions, pos) && same(s.normals, nrm), "evaluate (vectors) = C");
    std::array<OceanDVec3, 37> p2{};
    std::array<OceanVec3, 37> n2{};
    w.evaluate(xz, 12.5, p2, n2);
    CHECK(std::memcmp(p2.data(), pos.data(), sizeof p2) == 0 &&
              std::memcmp(n2.data(), nrm.data(), sizeof n2) == 0,
          "evaluate (spans) = C");

    const OceanGrid g{-100.5, 40.25, 0.5, 2.0, 13, 5};
    std::vector<OceanVec3> gp(65), gn(65);
    OK(ocean_waves_evaluate_grid(w.get(), &g, 3.0, gp.data(), gn.data()));
    const ocean::surface_points gs = w.evaluate_grid(g, 3.0);
    CHECK(same(gs.positions, gp) && same(gs.normals, gn), "evaluate_grid (vectors) = C");
    std::vector<OceanVec3> gp2(65), gn2(65);
    w.evaluate_grid(g, 3.0, gp2, gn2);
    CHECK(same(gp2, gp) && same(gn2, gn), "evaluate_grid (spans) = C");

    // Sizes: the wrapper refuses before the library is called.
    std::vector<OceanVec3> short_out(36);
    std::vector<OceanDVec3> short_pos(36);
    expect_invalid([&] { w.evaluate(xz, 0.0, short_pos, nrm); }, "evaluate: short positions");
    expect_invalid([&] { w.evaluate(xz, 0.0, pos, short_out); }, "evaluate: short normals");
    expect_invalid([&] { w.evaluate_grid(g, 0.0, short_out, gn); }, "evaluate_grid: short");
    // Errors from the library.
    expect_error([&] { w.evaluate(xz, std::nan(""), pos, nrm); }, OCEAN_STATUS_NON_FINITE,
                 "ocean_waves_evaluate", "evaluate: NaN time");
    expect_error([&] { w.evaluate(std::vector<OceanDVec2>{}, 0.0); }, OCEAN_STATUS_EMPTY,
                 "ocean_waves_evaluate", "evaluate: no points");
    const OceanGrid bad{0.0, 0.0, -1.0, 1.0, 2, 2};
    expect_error([&] { w.evaluate_grid(bad, 0.0); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_waves_evaluate_grid", "evaluate_grid: negative spacing");
    const OceanWaveDesc steep_wave[1] = {{0.9, 5.0, 1.0, 0.0, 0.0, INFINITY}};
    expect_error([&] { ocean::waves::create(steep_wave); }, OCEAN_STATUS_TOO_STEEP,
                 "ocean_waves_create", "create: too steep");
    expect_error([&] { ocean::waves::create({}); }, OCEAN_STATUS_EMPTY, "ocean_waves_create",
                 "create: no waves");
    ocean::waves moved = ocean::waves::create(kWaves);
    ocean::waves into = std::move(moved);
    expect_error([&] { (void)moved.count(); }, OCEAN_STATUS_NULL_POINTER, "ocean_waves_count",
                 "a moved-from owner");
}

OceanBoxDesc test_box()
{
    OceanBoxDesc b{};
    b.wind.speed = 9.0;
    b.wind.direction_x = 1.0;
    b.wind.direction_z = 0.2;
    b.wind.origin_x = -10.0;
    b.wind.origin_z = -5.0;
    b.wind.width = 70.0;
    b.wind.fetch = 80.0;
    b.wind.start = -100.0;
    b.wind.build_up = 10.0;
    b.wind.sustain = INFINITY;
    b.wind.decay = 0.0;
    b.wind.seed = 3;
    b.wind.trains = 4;
    b.smoothing = 5.0;
    b.has_recovery = 0;
    return b;
}

void test_wtb()
{
    const OceanWaterGridDesc grid{0.0, 0.0, 1.0, 48, 40};
    const std::vector<float> terrain(48 * 40, -12.0f);
    raii<ocean::wtb_scene>(
        "wtb_scene", [&] { return ocean::wtb_scene::create(grid); },
        [](OceanWtbScene *s) { return ocean_wtb_scene_reset_coverage(s); });

    ocean::wtb_scene scene = ocean::wtb_scene::create(grid, terrain);
    OceanWtbScene *raw = nullptr; // the same scene through the C API
    OK(ocean_wtb_scene_create(&grid, terrain.data(), terrain.size(), &raw));
    const OceanBoxDesc box = test_box();
    const std::uint32_t id = scene.add_box(box);
    std::uint32_t raw_id = 0;
    OK(ocean_wtb_scene_add_box(raw, &box, nullptr, 0, &raw_id));
    const std::uint32_t id2 = scene.add_box(box, ocean::span<const OceanWaveDesc>(kWaves.data(), 2));
    OK(ocean_wtb_scene_add_box(raw, &box, kWaves.data(), 2, &raw_id));
    CHECK(scene.box_count() == 2, "box_count");
    OceanBoxDesc moved_box = box;
    moved_box.wind.origin_x = -5.0;
    scene.update_box(id, moved_box);
    OK(ocean_wtb_scene_update_box(raw, id, &moved_box, nullptr, 0));
    scene.update_box(id2, box, ocean::span<const OceanWaveDesc>(kWaves.data(), 1));
    OK(ocean_wtb_scene_update_box(raw, id2, &box, kWaves.data(), 1));
    OceanEffects fx = ocean::defaults<OceanEffects>();
    fx.round_waves = 1;
    scene.set_effects(fx);
    OK(ocean_wtb_scene_set_effects(raw, &fx));
    scene.set_train_filter(1.0, 3.0);
    OK(ocean_wtb_scene_set_train_filter(raw, 1.0, 3.0));
    scene.set_budget_seconds(1.0);
    scene.set_budget_explicit(SIZE_MAX, fx);
    scene.set_budget_unlimited();
    scene.set_terrain(terrain);
    const std::vector<OceanDVec2> xz = {{3.5, 4.25}, {20.0, 17.5}, {47.5, 1.0}, {-3.0, 60.0}};
    expect_error([&] { (void)scene.heights_drawn(xz); }, OCEAN_STATUS_NOT_EVALUATED,
                 "ocean_wtb_scene_heights_drawn", "heights_drawn before evaluating");

    const std::size_t n = 48 * 40;
    std::vector<OceanVec3> pos(n), nrm(n), rpos(n), rnrm(n);
    const OceanFrameStats st = scene.evaluate(7.5, nullptr, pos, nrm);
    OceanFrameStats rst{};
    OK(ocean_wtb_scene_evaluate(raw, 7.5, nullptr, rpos.data(), rnrm.data(), n, &rst));
    CHECK(same(pos, rpos) && same(nrm, rnrm), "wtb evaluate = C");
    CHECK(st.alive == rst.alive && st.trains == rst.trains && st.alive == 2 &&
              st.estimated_seconds == rst.estimated_seconds,
          "wtb evaluate stats: %zu boxes, %zu trains", st.alive, st.trains);
    const auto drawn = scene.heights_drawn(xz);
    std::vector<OceanDrawnSample> rdrawn(xz.size());
    OK(ocean_wtb_scene_heights_drawn(raw, xz.data(), xz.size(), rdrawn.data()));
    CHECK(same(drawn, rdrawn) && drawn[1].covered == 1 && drawn[3].covered == 0,
          "heights_drawn (vector) = C");
    std::vector<OceanDrawnSample> drawn2(xz.size());
    scene.heights_drawn(xz, drawn2);
    CHECK(same(drawn2, rdrawn), "heights_drawn (span) = C");
    const auto cont = scene.heights_continuous(9.0, xz);
    std::vector<OceanHeightSample> rcont(xz.size()), cont2(xz.size());
    OK(ocean_wtb_scene_heights_continuous(raw, 9.0, xz.data(), xz.size(), rcont.data()));
    scene.heights_continuous(9.0, xz, cont2);
    CHECK(same(cont, rcont) && same(cont2, rcont), "heights_continuous = C");

    // Incremental evaluation into kept buffers, with culling by a camera at the origin (an
    // infinite [0, 1] perspective, near 0.2 m): equal to the C call on the same state.
    float identity[16] = {}, projection[16] = {};
    identity[0] = identity[5] = identity[10] = identity[15] = 1.0f;
    projection[0] = 1.0f, projection[5] = 1.0f, projection[10] = -1.0f, projection[11] = -1.0f,
    projection[14] = -0.2f;
    const OceanCamera cam =
        ocean::make_camera(identity, projection, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE);
    scene.reset_coverage();
    OK(ocean_wtb_scene_reset_coverage(raw));
    const OceanFrameStats ist = scene.evaluate_incremental(8.0, &cam, pos, nrm);
    OK(ocean_wtb_scene_evaluate_incremental(raw, 8.0, &cam, rpos.data(), rnrm.data(), n, &rst));
    CHECK(same(pos, rpos) && same(nrm, rnrm) && ist.culled == rst.culled,
          "evaluate_incremental = C");

    std::vector<OceanVec3> small(n - 1);
    expect_invalid([&] { scene.evaluate(0.0, nullptr, pos, small); }, "wtb evaluate: sizes");
    expect_error([&] { scene.evaluate(0.0, nullptr, small, small); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "ocean_wtb_scene_evaluate",
                 "wtb evaluate: not nx * nz");
    std::vector<OceanHeightSample> short_out(3);
    expect_invalid([&] { scene.heights_continuous(0.0, xz, short_out); },
                   "heights_continuous: sizes");
    expect_invalid([&] { scene.heights_drawn(xz, ocean::span<OceanDrawnSample>(drawn2.data(), 1)); },
                   "heights_drawn: sizes");
    scene.remove_box(id2);
    expect_error([&] { scene.remove_box(id2); }, OCEAN_STATUS_NOT_FOUND,
                 "ocean_wtb_scene_remove_box", "remove_box twice");
    CHECK(scene.box_count() == 1, "box_count after remove");
    ocean_wtb_scene_destroy(raw);
}

void test_lighting()
{
    raii<ocean::spectrum>(
        "spectrum",
        [] { return ocean::spectrum::create(ocean::defaults<OceanSpectrumParams>()); },
        [](OceanSpectrum *s) {
            std::size_t n = 0;
            return ocean_spectrum_wave_count(s, &n);
        });
    raii<ocean::lighting>(
        "lighting",
        [] {
            return ocean::lighting::create(ocean::defaults<OceanSkyParams>(),
                                           ocean::defaults<OceanSeaParams>());
        },
        [](OceanLighting *l) {
            double x = 0.0;
            return ocean_lighting_sun_solid_angle(l, &x);
        });

    const ocean::spectrum sp = ocean::spectrum::create(ocean::defaults<OceanSpectrumParams>());
    std::size_t wc = 0, clamped = 0;
    OK(ocean_spectrum_wave_count(sp.get(), &wc));
    OK(ocean_spectrum_clamped_count(sp.get(), &clamped));
    std::vector<OceanWaveDesc> rw(wc);
    OK(ocean_spectrum_waves(sp.get(), rw.data(), wc));
    CHECK(sp.wave_count() == wc && same(sp.waves(), rw) && sp.clamped_count() == clamped,
          "spectrum waves");
    double d[4];
    OceanDVec2 wind{};
    OceanSlopeVariance tv{}, sv{};
    OK(ocean_spectrum_max_amplitude(sp.get(), &d[0]));
    OK(ocean_spectrum_steepness_sum(sp.get(), &d[1]));
    OK(ocean_spectrum_mean_height_shift(sp.get(), &d[2]));
    OK(ocean_spectrum_height_variance(sp.get(), &d[3]));
    OK(ocean_spectrum_wind_direction(sp.get(), &wind));
    OK(ocean_spectrum_total_slope_variance(sp.get(), &tv));
    OK(ocean_spectrum_slope_variance(sp.get(), 1.0, 2.5, 0.05, &sv));
    CHECK(sp.max_amplitude() == d[0] && sp.steepness_sum() == d[1] &&
              sp.mean_height_shift() == d[2] && sp.height_variance() == d[3] &&
              same_value(sp.wind_direction(), wind) && same_value(sp.total_slope_variance(), tv) &&
              same_value(sp.slope_variance(1.0, 2.5, 0.05), sv),
          "spectrum queries");
    expect_error([&] { (void)sp.slope_variance(2.0, 1.0, 0.05); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_spectrum_slope_variance", "slope_variance: n_min > n_max");

    const ocean::lighting l = ocean::lighting::create(ocean::defaults<OceanSkyParams>(),
                                                      ocean::defaults<OceanSeaParams>());
    OceanRgb rgb[5];
    OceanIrradiance irr{};
    double omega = 0.0;
    const OceanDVec3 up{0.0, 1.0, 0.0};
    OK(ocean_lighting_sky_irradiance(l.get(), &rgb[0]));
    OK(ocean_lighting_sea_radiance(l.get(), &rgb[1]));
    OK(ocean_lighting_below_horizon_radiance(l.get(), &rgb[2]));
    OK(ocean_lighting_sun_radiance(l.get(), &rgb[3]));
    OK(ocean_lighting_environment_radiance(l.get(), up, &rgb[4]));
    OK(ocean_lighting_irradiance(l.get(), &irr));
    OK(ocean_lighting_sun_solid_angle(l.get(), &omega));
    CHECK(same_value(l.sky_irradiance(), rgb[0]) && same_value(l.sea_radiance(), rgb[1]) &&
              same_value(l.below_horizon_radiance(), rgb[2]) &&
              same_value(l.sun_radiance(), rgb[3]) &&
              same_value(l.environment_radiance(up), rgb[4]) && same_value(l.irradiance(), irr) &&
              l.sun_solid_angle() == omega,
          "lighting queries");
    expect_error([&] { (void)l.environment_radiance(OceanDVec3{0.0, 2.0, 0.0}); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "ocean_lighting_environment_radiance",
                 "environment_radiance: not a unit vector");

    raii<ocean::sky_map>(
        "sky_map", [&] { return l.sky_map(8); },
        [](OceanSkyMap *m) {
            std::uint32_t n = 0;
            return ocean_sky_map_level_count(m, &n);
        });
    const ocean::sky_map map = l.sky_map(16);
    CHECK(map.level_count() == 5 && map.level_size(0) == 16 && map.level_size(4) == 1,
          "sky map levels");
    for (std::uint32_t lv = 0; lv < map.level_count(); lv++) {
        const std::size_t side = map.level_size(lv);
        std::vector<float> raw(4 * side * side), filled(raw.size());
        OK(ocean_sky_map_copy_level(map.get(), lv, raw.data(), raw.size()));
        map.copy_level(lv, filled);
        CHECK(same(map.level(lv), raw) && same(filled, raw), "sky map level %u = C", lv);
    }
    std::vector<float> wrong(15);
    expect_invalid([&] { map.copy_level(0, wrong); }, "copy_level: size");
    expect_error([&] { (void)map.level_size(9); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_sky_map_level_info", "level_size: no such level");

    std::vector<OceanSeaColorInput> in;
    for (int i = 0; i < 9; i++) {
        const double a = 0.15 + 0.1 * i;
        OceanSeaColorInput x{};
        x.v = OceanDVec3{std::cos(a) * 0.6, std::sin(a), std::cos(a) * 0.8};
        const double len = std::sqrt(x.v.x * x.v.x + x.v.y * x.v.y + x.v.z * x.v.z);
        x.v = OceanDVec3{x.v.x / len, x.v.y / len, x.v.z / len};
        x.n = up;
        x.wind = OceanDVec2{1.0, 0.5};
        x.sigma_x2 = 0.004 * i;
        x.sigma_y2 = 0.002 * i;
        in.push_back(x);
    }
    std::vector<OceanSeaLight> rc(in.size()), filled(in.size());
    OK(ocean_sea_color_batch(l.get(), map.get(), in.data(), in.size(), rc.data()));
    l.sea_color(map, in, filled);
    OceanSeaLight one{};
    OK(ocean_sea_color(l.get(), map.get(), in[3].v, in[3].n, in[3].wind, in[3].sigma_x2,
                       in[3].sigma_y2, &one));
    CHECK(same(l.sea_color(map, in), rc) && same(filled, rc) &&
              same_value(l.sea_color(map, in[3].v, in[3].n, in[3].wind, in[3].sigma_x2,
                                     in[3].sigma_y2),
                         one),
          "sea_color = C");
    std::vector<OceanSeaLight> short_out(2);
    expect_invalid([&] { l.sea_color(map, in, short_out); }, "sea_color: sizes");
    in[4].sigma_x2 = -1.0;
    expect_error([&] { (void)l.sea_color(map, in); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_sea_color_batch", "sea_color: negative variance");

    // The BRDF functions and the footprint (camera passed through).
    const OceanDVec3 v{0.3, 0.0, 0.953939}, li{-0.3, 0.1, 0.948683};
    double r[9];
    OceanRgb tm{};
    OK(ocean_ross_brdf(v, li, 0.01, 0.02, 0.02, &r[0]));
    OK(ocean_sun_radiance(v, li, 0.01, 0.02, 1000.0, 6.8e-5, 0.02, &r[1]));
    OK(ocean_schlick(0.7, 0.02, &r[2]));
    OK(ocean_effective_fresnel_fit(0.5, 0.1, 0.02, &r[3]));
    OK(ocean_effective_fresnel_table(0.5, 0.1, 0.02, &r[4]));
    OK(ocean_effective_fresnel_integral(v, 0.01, 0.02, 0.02, &r[5]));
    OK(ocean_linear_to_srgb(0.25, &r[6]));
    OK(ocean_tone_map(OceanRgb{0.1, 0.2, 0.3}, OCEAN_DEFAULT_EXPOSURE, &tm));
    const OceanCamera cam = test_camera();
    OK(ocean_pixel_footprint(&cam, 64, 48, 32.5, 40.5, 5000.0, &r[7]));
    CHECK(ocean::ross_brdf(v, li, 0.01, 0.02, 0.02) == r[0] &&
              ocean::sun_radiance(v, li, 0.01, 0.02, 1000.0, 6.8e-5, 0.02) == r[1] &&
              ocean::schlick(0.7, 0.02) == r[2] && ocean::effective_fresnel_fit(0.5, 0.1, 0.02) == r[3] &&
              ocean::effective_fresnel_table(0.5, 0.1, 0.02) == r[4] &&
              ocean::effective_fresnel_integral(v, 0.01, 0.02, 0.02) == r[5] &&
              ocean::linear_to_srgb(0.25) == r[6] &&
              same_value(ocean::tone_map(OceanRgb{0.1, 0.2, 0.3}), tm) &&
              ocean::pixel_footprint(cam, 64, 48, 32.5, 40.5, 5000.0) == r[7],
          "BRDF functions and footprint = C");
    expect_error([] { (void)ocean::schlick(std::nan(""), 0.02); }, OCEAN_STATUS_NON_FINITE,
                 "ocean_schlick", "schlick: NaN");
}

int progress_calls(void *user, std::size_t done, std::size_t total)
{
    (void)done;
    (void)total;
    ++*static_cast<int *>(user);
    return 0;
}

void test_relief()
{
    const std::uint32_t N = 8;
    std::vector<float> heights(N * N);
    std::vector<std::uint8_t> h8(N * N);
    std::vector<std::uint16_t> h16(N * N);
    for (std::uint32_t j = 0; j < N; j++)
        for (std::uint32_t i = 0; i < N; i++) {
            const bool inside = i >= 2 && i < 6 && j >= 3 && j < 6;
            heights[j * N + i] = inside ? 1.0f : 0.25f + 0.05f * float(i);
            h8[j * N + i] = std::uint8_t(inside ? 255 : 40 + 10 * i);
            h16[j * N + i] = std::uint16_t(inside ? 65535 : 9000 + 1000 * j);
        }
    const auto make_map = [&] {
        return ocean::relief_map::create_f32(heights, N, N, OCEAN_RELIEF_EDGE_WRAP,
                                             OCEAN_RELIEF_RANGE_REFUSE);
    };
    raii<ocean::relief_map>("relief_map", make_map, [](OceanReliefMap *m) {
        std::uint32_t n = 0;
        return ocean_relief_map_size(m, &n);
    });
    const ocean::relief_map map = make_map();
    const ocean::relief_map m8 = ocean::relief_map::create_u8(h8, N, N, OCEAN_RELIEF_EDGE_CLAMP);
    const ocean::relief_map m16 = ocean::relief_map::create_u16(h16, N, N, OCEAN_RELIEF_EDGE_WRAP);
    std::vector<float> depths(N * N), normals(3 * N * N);
    OK(ocean_relief_map_depths(map.get(), depths.data(), depths.size()));
    OK(ocean_relief_normals(map.get(), 2.0f, normals.data(), normals.size()));
    CHECK(map.size() == N && m8.size() == N && m16.size() == N && same(map.depths(), depths) &&
              same(map.normals(2.0f), normals) && m8.depths()[0] == 1.0f - 40.0f / 255.0f,
          "relief map queries");
    const ocean::relief_map half = map.downsample();
    CHECK(half.size() == N / 2, "downsample");
    expect_error([&] { (void)ocean::relief_map::create_f32(heights, N, N - 1, 0, 0); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "ocean_relief_map_create_f32",
                 "create_f32: not square");

    const OceanReliefConeParams params = ocean::defaults<OceanReliefConeParams>();
    raii<ocean::relief_cones>(
        "relief_cones", [&] { return ocean::relief_cones::create(map, params); },
        [](OceanReliefCones *c) {
            std::uint32_t n = 0;
            return ocean_relief_cones_size(c, &n);
        });
    int calls = 0;
    const ocean::relief_cones cones = ocean::relief_cones::create(map, params, progress_calls, &calls);
    CHECK(calls >= 2 && cones.size() == N, "cones: %d progress calls", calls);
    std::vector<float> texels(4 * N * N), filled(texels.size());
    std::vector<std::uint8_t> enc8(3 * N * N);
    std::vector<float> enc32(3 * N * N);
    OK(ocean_relief_cones_texels(cones.get(), texels.data(), texels.size()));
    OK(ocean_relief_cones_encode(cones.get(), OCEAN_RELIEF_ENCODING_UNORM8, enc8.data(), enc8.size()));
    OK(ocean_relief_cones_encode(cones.get(), OCEAN_RELIEF_ENCODING_F32, enc32.data(), enc32.size()));
    cones.texels(filled);
    CHECK(same(cones.texels(), texels) && same(filled, texels) &&
              same(cones.encode<std::uint8_t>(OCEAN_RELIEF_ENCODING_UNORM8), enc8) &&
              same(cones.encode<float>(OCEAN_RELIEF_ENCODING_F32), enc32),
          "cone texels and encodings = C");
    CHECK(same(ocean::relief_generate_texels(map, params), texels) &&
              same(ocean::relief_generate_encoded<std::uint8_t>(map, params,
                                                                OCEAN_RELIEF_ENCODING_UNORM8),
                   enc8),
          "generate = the handle's texels");

    // Progress as a callable: every report in order from 0 to the total (N rows in wrap
    // mode), and the same result as without it.
    std::vector<std::size_t> seen;
    std::size_t reported_total = 0;
    const auto record = [&](std::size_t done, std::size_t total) {
        seen.push_back(done);
        reported_total = total;
        return true;
    };
    const ocean::relief_cones with_lambda = ocean::relief_cones::create(map, params, record);
    bool ordered = seen.size() >= 2 && seen.front() == 0 && seen.back() == reported_total &&
                   reported_total == N;
    for (std::size_t k = 1; k < seen.size(); k++)
        ordered = ordered && seen[k] > seen[k - 1];
    CHECK(ordered && same(with_lambda.texels(), texels), "cones: %zu callable reports, total %zu",
          seen.size(), reported_total);
    CHECK(same(ocean::relief_generate_texels(map, params, record), texels) &&
              same(ocean::relief_generate_encoded<std::uint8_t>(map, params,
                                                                OCEAN_RELIEF_ENCODING_UNORM8, record),
                   enc8),
          "generate with a callable = the handle's texels");
    // false cancels: ocean::error OCEAN_STATUS_CANCELLED, nothing made.
    expect_error([&] { (void)ocean::relief_cones::create(map, params, [](std::size_t, std::size_t) { return false; }); },
                 OCEAN_STATUS_CANCELLED, "ocean_relief_cones_create", "cones: callable cancels");
    // What the callable throws cancels the work and comes back out of the call, unchanged
    // (it never unwinds through the library).
    int thrown_at = -1;
    try {
        (void)ocean::relief_quad_generate_texels(map, params, [&](std::size_t done, std::size_t) {
            if (done > 0) {
                thrown_at = int(done);
                throw std::runtime_error("stop at the first band");
            }
            return true;
        });
        CHECK(false, "quad generate: the callable's exception was swallowed");
    } catch (const std::runtime_error &e) {
        CHECK(std::string(e.what()) == "stop at the first band" && thrown_at > 0,
              "quad generate: rethrown %s", e.what());
    }
    expect_invalid([&] { (void)cones.encode<float>(OCEAN_RELIEF_ENCODING_F16); },
                   "encode: element type");
    expect_invalid([&] { cones.texels(enc32); }, "texels: size");
    expect_error([&] { (void)cones.encode<float>(99); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_relief_cones_encode", "encode: unknown encoding");

    const ocean::relief_cones q8 = cones.quantize(OCEAN_RELIEF_ENCODING_UNORM8);
    CHECK(q8.size() == N, "quantize");

    const OceanReliefMethod method{nullptr, OCEAN_RELIEF_TRACER_RELAXED, 15, 6,
                                   OCEAN_RELIEF_SEARCH_LAST_STEP};
    std::vector<OceanReliefRay> rays;
    for (int k = 0; k < 12; k++) {
        OceanReliefRay ray{};
        OK(ocean_relief_ray_from_view(0.05f + 0.08f * k, 0.4f, 0.3f - 0.05f * k, 0.2f, -1.0f,
                                      0.1f, &ray));
        const OceanReliefRay mine = ocean::relief_ray_from_view(
            0.05f + 0.08f * k, 0.4f, 0.3f - 0.05f * k, 0.2f, -1.0f, 0.1f);
        CHECK(same_value(mine, ray), "ray_from_view %d = C", k);
        rays.push_back(ray);
    }
    std::vector<OceanReliefHit> hits(rays.size()), hits2(rays.size());
    OK(ocean_relief_trace(cones.get(), &method, rays.data(), rays.size(), hits.data()));
    cones.trace(method, rays, hits2);
    CHECK(same(cones.trace(method, rays), hits) && same(hits2, hits), "trace = C");
    std::vector<OceanReliefHit> short_hits(3);
    expect_invalid([&] { cones.trace(method, rays, short_hits); }, "trace: sizes");
    std::vector<OceanReliefPoint> points;
    for (const OceanReliefHit &h : hits)
        points.push_back(h.pos);
    std::vector<std::uint8_t> shadow(points.size());
    OK(ocean_relief_shadow(cones.get(), &method, points.data(), points.size(), 0.6f, 0.2f, 0.5f,
                           0.1f, 0.02f, shadow.data()));
    CHECK(same(cones.shadow(method, points, 0.6f, 0.2f, 0.5f, 0.1f, 0.02f), shadow),
          "shadow = C");
    expect_error([&] { (void)cones.trace(method, std::vector<OceanReliefRay>{}); },
                 OCEAN_STATUS_EMPTY, "ocean_relief_trace", "trace: no rays");

    raii<ocean::relief_mips>(
        "relief_mips", [&] { return ocean::relief_mips::create(cones, OCEAN_RELIEF_MIP_WINDOW); },
        [](OceanReliefMips *m) {
            std::uint32_t n = 0;
            return ocean_relief_mips_level_count(m, &n);
        });
    const ocean::relief_mips mips = ocean::relief_mips::create(cones, OCEAN_RELIEF_MIP_WINDOW);
    std::vector<std::uint16_t> lv1(3 * 4 * 4);
    OK(ocean_relief_mips_copy_level(mips.get(), 1, OCEAN_RELIEF_ENCODING_F16, lv1.data(), lv1.size()));
    CHECK(mips.level_count() == 4 && mips.level_size(1) == 4 &&
              same(mips.level<std::uint16_t>(1, OCEAN_RELIEF_ENCODING_F16), lv1),
          "mips = C");

    raii<ocean::relief_quad_cones>(
        "relief_quad_cones", [&] { return ocean::relief_quad_cones::create(map, params); },
        [](OceanReliefQuadCones *c) {
            std::uint32_t n = 0;
            return ocean_relief_quad_cones_size(c, &n);
        });
    calls = 0;
    const ocean::relief_quad_cones quad =
        ocean::relief_quad_cones::create(map, params, progress_calls, &calls);
    std::vector<float> qtex(16 * N * N);
    OK(ocean_relief_quad_cones_texels(quad.get(), qtex.data(), qtex.size()));
    CHECK(calls >= 2 && quad.size() == N && same(quad.texels(), qtex) &&
              same(ocean::relief_quad_generate_texels(map, params), qtex),
          "quad cones = C");
    std::vector<OceanReliefHit> qhits(rays.size());
    OK(ocean_relief_quad_trace(quad.get(), &method, rays.data(), rays.size(), qhits.data()));
    std::vector<std::uint8_t> qshadow(points.size());
    OK(ocean_relief_quad_shadow(quad.get(), &method, points.data(), points.size(), 0.6f, 0.2f,
                                0.5f, 0.1f, 0.02f, qshadow.data()));
    CHECK(same(quad.trace(method, rays), qhits) &&
              same(quad.shadow(method, points, 0.6f, 0.2f, 0.5f, 0.1f, 0.02f), qshadow),
          "quad trace and shadow = C");

    std::uint32_t w = 0, h = 0, x = 0, y = 0, level = 0;
    OK(ocean_relief_mip_atlas_size(8, 3, &w, &h));
    OK(ocean_relief_mip_atlas_origin(8, 2, &x, &y));
    OK(ocean_relief_mip_level(0.3f, 0.0f, 0.0f, 0.3f, 8, 3, &level));
    const auto ext = ocean::relief_mip_atlas_size(8, 3);
    const auto org = ocean::relief_mip_atlas_origin(8, 2);
    CHECK(ext.width == w && ext.height == h && org.x == x && org.y == y && w == 12 &&
              ocean::relief_mip_level(0.3f, 0.0f, 0.0f, 0.3f, 8, 3) == level,
          "mip atlas = C");
}

// A perspective projection, column-major, OpenGL's [-1, 1] depth (as glm::perspective), and
// the identity view (SAO reads only the projection).
OceanCamera sao_camera()
{
    const float n = 0.5f, f = 100.0f, t = 1.0f / std::tan(0.5f * 1.0f);
    std::array<float, 16> view{}, p{};
    view[0] = view[5] = view[10] = view[15] = 1.0f;
    p[0] = t / (32.0f / 24.0f);
    p[5] = t;
    p[10] = (f + n) / (n - f);
    p[11] = -1.0f;
    p[14] = 2.0f * f * n / (n - f);
    return ocean::make_camera(view, p, OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
}

// Window depth of a floor seen at an angle (a ramp of depths), background in the top rows.
std::vector<float> sao_depth()
{
    std::vector<float> d(32 * 24);
    for (int y = 0; y < 24; y++)
        for (int x = 0; x < 32; x++)
            d[y * 32 + x] = y < 4 ? 1.0f : 0.9f + 0.004f * float(y) + 0.0005f * float(x % 5);
    return d;
}

void test_sao()
{
    const OceanCamera cam = sao_camera();
    const OceanSaoParams params = ocean::defaults<OceanSaoParams>();
    raii<ocean::sao>(
        "sao", [&] { return ocean::sao::create(32, 24, 2, cam, OCEAN_SAO_DEPTH_WINDOW, params); },
        [](OceanSao *s) {
            OceanSaoInfo info{};
            return ocean_sao_describe(s, &info);
        });
    const ocean::sao s = ocean::sao::create(32, 24, 2, cam, OCEAN_SAO_DEPTH_WINDOW, params);
    OceanSaoInfo info{};
    OK(ocean_sao_describe(s.get(), &info));
    const OceanSaoInfo mine = s.describe();
    CHECK(mine.output_width == 28 && mine.output_height == 20 && mine.near == info.near &&
              mine.far == info.far && mine.pixels_per_metre == info.pixels_per_metre,
          "sao describe");
    const std::vector<float> depth = sao_depth();
    std::vector<float> ao(28 * 20), filled(ao.size()), z(depth.size());
    OK(ocean_sao_run(s.get(), depth.data(), depth.size(), ao.data(), ao.size()));
    OK(ocean_sao_view_z(s.get(), depth.data(), depth.size(), z.data(), z.size()));
    s.run(depth, filled);
    CHECK(same(s.run(depth), ao) && same(filled, ao) && same(s.view_z(depth), z),
          "sao run and view_z = C");
    std::vector<float> wrong(27 * 20);
    expect_invalid([&] { s.run(depth, wrong); }, "sao run: ao size");
    expect_invalid([&] { (void)s.run(wrong); }, "sao run: depth size");
    expect_invalid([&] { (void)s.view_z(wrong); }, "sao view_z: depth size");
    std::vector<float> nan_depth = depth;
    nan_depth[40] = std::nan("");
    expect_error([&] { (void)s.run(nan_depth); }, OCEAN_STATUS_NON_FINITE, "ocean_sao_run",
                 "sao run: NaN depth");
    OceanSaoParams bad = params;
    bad.samples = 0;
    expect_error([&] { (void)ocean::sao::create(32, 24, 2, cam, OCEAN_SAO_DEPTH_WINDOW, bad); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "ocean_sao_create", "sao create: no samples");
}

#if defined(OCEAN_GPU)
std::string gpu_note;

void test_gpu()
{
    OceanRendererOptions ro{};
    OceanSurfaceDrawParams dp{};
    OceanReliefScene rs{};
    OK(ocean_renderer_options_default(&ro));
    OK(ocean_surface_draw_params_default(&dp));
    OK(ocean_relief_scene_default(&rs));
    const auto ro2 = ocean::defaults<OceanRendererOptions>();
    const auto dp2 = ocean::defaults<OceanSurfaceDrawParams>();
    const auto rs2 = ocean::defaults<OceanReliefScene>();
    CHECK(ro2.cell_px == ro.cell_px && ro2.sky_map_size == ro.sky_map_size &&
              dp2.n_max == dp.n_max && dp2.srgb_encode == dp.srgb_encode &&
              same_value(rs2.origin, rs.origin) && rs2.depth == rs.depth,
          "GPU defaults");

    // The shader registry and exports.
    CHECK(ocean::shader_count() == ocean_shader_count() && ocean::shader_count() > 0,
          "shader_count");
    bool found = false;
    for (std::size_t i = 0; i < ocean::shader_count(); i++) {
        const char *name = nullptr;
        OK(ocean_shader_name(i, &name));
        CHECK(ocean::shader_name(i) == name, "shader_name %zu", i);
        found = found || std::strcmp(name, "ocean") == 0;
    }
    CHECK(found, "the ocean pass is registered");
    raii<ocean::shader_export>(
        "shader_export",
        [] { return ocean::shader_export::create("sao_z", OCEAN_SHADER_LANGUAGE_GLSL); },
        [](OceanShaderExport *e) {
            std::size_t n = 0;
            return ocean_shader_export_file_count(e, &n);
        });
    const ocean::shader_export ex = ocean::shader_export::create("ocean", OCEAN_SHADER_LANGUAGE_GLSL);
    std::size_t files = 0, nb = 0;
    OK(ocean_shader_export_file_count(ex.get(), &files));
    OK(ocean_shader_export_binding_count(ex.get(), &nb));
    CHECK(ex.file_count() == files && files >= 8 && ex.binding_count() == nb, "export counts");
    for (std::size_t i = 0; i < files; i++) {
        const char *fname = nullptr, *entry = nullptr;
        const std::uint8_t *data = nullptr;
        std::size_t len = 0;
        OceanShaderStage stage = OCEAN_SHADER_STAGE_MODULE;
        OK(ocean_shader_export_file(ex.get(), i, &fname, &data, &len));
        OK(ocean_shader_export_file_stage(ex.get(), i, &stage, &entry));
        const ocean::shader_file f = ex.file(i);
        CHECK(f.name == fname && f.data.data() == data && f.data.size() == len &&
                  f.stage == stage && f.entry_point == entry,
              "export file %zu = C", i);
    }
    const char *table = nullptr;
    OK(ocean_shader_export_bindings(ex.get(), &table));
    const std::vector<OceanShaderBinding> bindings = ex.bindings();
    OceanShaderBinding b0{};
    OK(ocean_shader_export_binding(ex.get(), 0, &b0));
    CHECK(ex.bindings_table() == table && bindings.size() == nb &&
              bindings[0].binding == b0.binding && ex.binding(0).name == b0.name,
          "export bindings = C");
    expect_error([] { (void)ocean::shader_export::create("no such pass", OCEAN_SHADER_LANGUAGE_GLSL); },
                 OCEAN_STATUS_NOT_FOUND, "ocean_shader_export", "export: unknown pass");
    expect_error([&] { (void)ex.file(files); }, OCEAN_STATUS_INVALID_ARGUMENT,
                 "ocean_shader_export_file", "export: file out of range");

    // The draw data of the exported shaders (camera passed through).
    const OceanCamera cam = test_camera();
    const ocean::spectrum sp = ocean::spectrum::create(ocean::defaults<OceanSpectrumParams>());
    const ocean::lighting l = ocean::lighting::create(ocean::defaults<OceanSkyParams>(),
                                                      ocean::defaults<OceanSeaParams>());
    const OceanWaterGridDesc mesh{-10.0, -30.0, 1.0, 20, 20};
    std::vector<std::uint8_t> block(OCEAN_SURFACE_UNIFORMS_SIZE), mine(block.size());
    OK(ocean_surface_uniforms(&cam, sp.get(), l.get(), &dp, &mesh, 2.5, 64, 48, block.data(),
                              block.size()));
    ocean::surface_uniforms(cam, sp, l, dp, &mesh, 2.5, 64, 48, mine);
    CHECK(same(mine, block) && same(ocean::surface_uniforms(cam, sp, l, dp, &mesh, 2.5, 64, 48), block),
          "surface_uniforms = C");
    std::vector<std::uint8_t> long_block(OCEAN_SURFACE_UNIFORMS_SIZE + 1);
    expect_invalid([&] { ocean::surface_uniforms(cam, sp, l, dp, nullptr, 2.5, 64, 48, long_block); },
                   "surface_uniforms: size");
    EXPECT_MSG(ocean_surface_uniforms(&cam, sp.get(), l.get(), &dp, &mesh, 2.5, 64, 48,
                                      long_block.data(), long_block.size()),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 352");
    std::vector<float> waves(12 * sp.wave_count()), waves2(waves.size());
    OK(ocean_surface_wave_texels(&cam, sp.get(), 2.5, waves.data(), waves.size()));
    ocean::surface_wave_texels(cam, sp, 2.5, waves2);
    CHECK(same(ocean::surface_wave_texels(cam, sp, 2.5), waves) && same(waves2, waves),
          "surface_wave_texels = C");
    std::vector<float> five(5);
    expect_invalid([&] { ocean::surface_wave_texels(cam, sp, 2.5, five); },
                   "surface_wave_texels: size");
    std::vector<float> fresnel(OCEAN_FRESNEL_TABLE_SIZE * OCEAN_FRESNEL_TABLE_SIZE);
    OK(ocean_surface_fresnel_texels(fresnel.data(), fresnel.size()));
    CHECK(same(ocean::surface_fresnel_texels(), fresnel), "surface_fresnel_texels = C");
    std::vector<std::uint8_t> relief_block(OCEAN_RELIEF_UNIFORMS_SIZE);
    OK(ocean_relief_uniforms(&cam, &rs, 8, OCEAN_RELIEF_EDGE_WRAP, 1, 1, relief_block.data(),
                             relief_block.size()));
    CHECK(same(ocean::relief_uniforms(cam, rs, 8, OCEAN_RELIEF_EDGE_WRAP, 1, 1), relief_block),
          "relief_uniforms = C");
    const ocean::sao s = ocean::sao::create(32, 24, 2, sao_camera(), OCEAN_SAO_DEPTH_WINDOW,
                                            ocean::defaults<OceanSaoParams>());
    std::vector<std::uint8_t> sao_block(OCEAN_SAO_UNIFORMS_SIZE);
    std::uint32_t levels = 0;
    OK(ocean_sao_uniforms(s.get(), sao_block.data(), sao_block.size(), &levels));
    const ocean::sao_uniforms_block sb = s.uniforms();
    CHECK(same(sb.bytes, sao_block) && sb.levels == levels, "sao uniforms = C");

    // The context, the renderer and the GPU SAO need an adapter.
    ocean::gpu_context ctx;
    try {
        ctx = ocean::gpu_context::create();
    } catch (const ocean::error &e) {
        CHECK(e.status() == OCEAN_STATUS_NO_ADAPTER && std::strlen(e.what()) > 0,
              "gpu_context: %s", e.what());
        gpu_note = "; context, renderer and GPU SAO SKIPPED (no adapter)";
        return;
    }
    raii<ocean::gpu_context>(
        "gpu_context", [] { return ocean::gpu_context::create(); },
        [](OceanGpuContext *c) {
            const char *text = nullptr;
            return ocean_gpu_context_describe(c, &text);
        });
    const std::string adapter = ctx.describe();
    CHECK(!adapter.empty() && adapter.find('\0') == std::string::npos, "describe: %s",
          adapter.c_str());
    raii<ocean::renderer>(
        "renderer", [&] { return ocean::renderer::create(ctx, ro); },
        [&](OceanRenderer *r) { return ocean_renderer_set_lighting(r, ctx.get(), l.get()); });
    ocean::renderer rend = ocean::renderer::create(ctx, ro);
    expect_error([&] { (void)rend.render_rgba8(ctx, cam, 2.5, 64, 48); },
                 OCEAN_STATUS_INVALID_ARGUMENT, "ocean_renderer_render_rgba8",
                 "render before set_spectrum");
    rend.set_spectrum(ctx, sp);
    rend.set_lighting(ctx, l);
    std::vector<std::uint8_t> frame(64 * 48 * 4);
    OK(ocean_renderer_render_rgba8(rend.get(), ctx.get(), &cam, 2.5, 64, 48, frame.data(),
                                   frame.size()));
    CHECK(same(rend.render_rgba8(ctx, cam, 2.5, 64, 48), frame), "render_rgba8 = C");
    raii<ocean::sao_gpu>(
        "sao_gpu", [&] { return ocean::sao_gpu::create(ctx); },
        [&](OceanSaoGpu *g) {
            std::vector<float> out(28 * 20);
            const std::vector<float> d = sao_depth();
            return ocean_sao_gpu_run(g, ctx.get(), s.get(), d.data(), d.size(), out.data(),
                                     out.size());
        });
    const ocean::sao_gpu sg = ocean::sao_gpu::create(ctx);
    const std::vector<float> depth = sao_depth();
    std::vector<float> gao(28 * 20);
    OK(ocean_sao_gpu_run(sg.get(), ctx.get(), s.get(), depth.data(), depth.size(), gao.data(),
                         gao.size()));
    CHECK(same(sg.run(ctx, s, depth), gao), "sao_gpu run = C");
    gpu_note = "; GPU on " + adapter;
}
#endif

} // namespace

int main()
{
    try {
        test_version_and_defaults();
        test_span();
        test_make_camera();
        test_waves();
        test_wtb();
        test_lighting();
        test_relief();
        test_sao();
#if defined(OCEAN_GPU)
        test_gpu();
#endif
    } catch (const std::exception &e) {
        CHECK(false, "unexpected exception: %s", e.what());
    }
#if defined(OCEAN_GPU)
    const std::string variant = "full library (OCEAN_GPU)" + gpu_note;
#else
    const std::string variant = "CPU-only library";
#endif
    std::printf("test_hpp.cpp: library %s, %d checks, %d failures; %s\n", ocean::version().c_str(),
                checks, failures, variant.c_str());
    return failures == 0 ? 0 : 1;
}
