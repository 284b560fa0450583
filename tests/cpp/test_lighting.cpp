// C++17 test of the lighting part of the ocean C ABI with GLM, linked against libocean.a.
//
// Built and run by tests/tests/c_abi.rs like tests/cpp/test_waves.cpp.
//
// What a C++ engine does: RAII handles, GLM matrices handed over as they are (the column-major
// dmat4s of glm::lookAt and glm::infinitePerspective into an OceanCamera), glm::dvec3 in and
// out, one const lighting and sky map shared by several threads. Expected values come from closed forms computed here:
// - the pixel footprint of a camera looking straight down from h: 2 h tan(fov/2) / height;
// - a flat calm sea under a uniform sky of radiance L: sky term F(cos) L with Schlick's F
//   (Eq. 14), refracted term L_sea (1 - F), L_sea = albedo (E_sun sin(elevation) + pi L) / pi;
// - the batch, run from four threads on slices, equals the single-threaded batch bit for bit.
//
// Prints a summary; exits 0 only if every check passed.
#include "ocean.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

int g_checks = 0;
int g_failures = 0;

// printf-style: C varargs with the format attribute, so that the compiler checks each
// message's arguments against its format (clang refuses a non-literal format otherwise).
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void check(bool ok, const char *fmt, ...)
{
    ++g_checks;
    if (!ok) {
        ++g_failures;
        std::fprintf(stderr, "FAIL: ");
        va_list args;
        va_start(args, fmt);
        std::vfprintf(stderr, fmt, args);
        va_end(args);
        std::fputc('\n', stderr);
    }
}

bool ok(OceanStatus s, const char *what)
{
    ++g_checks;
    if (s != OCEAN_STATUS_OK) {
        ++g_failures;
        std::fprintf(stderr, "FAIL: %s: %s (%s)\n", what, ocean_status_message(s),
                     ocean_last_error_message());
        return false;
    }
    return true;
}

struct LightingDeleter {
    void operator()(OceanLighting *p) const { ocean_lighting_destroy(p); }
};
struct SkyMapDeleter {
    void operator()(OceanSkyMap *p) const { ocean_sky_map_destroy(p); }
};
using Lighting = std::unique_ptr<OceanLighting, LightingDeleter>;
using SkyMap = std::unique_ptr<OceanSkyMap, SkyMapDeleter>;

OceanDVec3 to_c(const glm::dvec3 &v) { return OceanDVec3{v.x, v.y, v.z}; }
glm::dvec3 from_c(const OceanRgb &c) { return glm::dvec3(c.r, c.g, c.b); }

double schlick(double c, double r)
{
    double x = 1.0 - c;
    return r + (1.0 - r) * x * x * x * x * x;
}

void footprint_looking_down()
{
    const double h = 25.0, fov = glm::radians(50.0);
    const uint32_t width = 400, height = 300;
    // Looking straight down with -z of the world as the screen's up.
    glm::dmat4 view = glm::lookAt(glm::dvec3(3.0, h, -2.0), glm::dvec3(3.0, 0.0, -2.0),
                                  glm::dvec3(0.0, 0.0, -1.0));
    // GLM's own matrices, as an engine has them: an infinite perspective in GLM's default
    // OpenGL depth range.
    const glm::dmat4 projection =
        glm::infinitePerspective(fov, double(width) / double(height), 0.1);
    OceanCamera cam;
    std::memset(&cam, 0, sizeof cam);
    std::memcpy(cam.view, glm::value_ptr(view), sizeof cam.view);
    std::memcpy(cam.projection, glm::value_ptr(projection), sizeof cam.projection);
    cam.depth_convention = OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE;
    double l = -1.0;
    if (ok(ocean_pixel_footprint(&cam, width, height, width / 2.0, height / 2.0, 1e5, &l),
           "ocean_pixel_footprint")) {
        double want = 2.0 * h * std::tan(fov / 2.0) / height;
        check(std::fabs(l - want) < 1e-9 * want, "footprint %.12g, want %.12g", l, want);
    }
}

void flat_sea_under_a_uniform_sky()
{
    OceanSkyParams sky;
    OceanSeaParams sea;
    ok(ocean_sky_params_default(&sky), "sky defaults");
    ok(ocean_sea_params_default(&sea), "sea defaults");
    const glm::dvec3 radiance(0.125, 0.25, 0.5);
    sky.zenith_radiance = OceanRgb{radiance.x, radiance.y, radiance.z};
    sky.cie = OceanCieSky{0.0, -1.0, 0.0, -1.0, 0.0}; // gradation and indicatrix both 1
    OceanLighting *raw = nullptr;
    if (!ok(ocean_lighting_create(&sky, &sea, &raw), "ocean_lighting_create"))
        return;
    Lighting lighting(raw);
    OceanSkyMap *raw_map = nullptr;
    if (!ok(ocean_lighting_sky_map_create(lighting.get(), 128, &raw_map), "sky map"))
        return;
    SkyMap map(raw_map);

    const glm::dvec3 sun(sky.sun_direction.x, sky.sun_direction.y, sky.sun_direction.z);
    const glm::dvec3 e_sun(sky.sun_irradiance.r, sky.sun_irradiance.g, sky.sun_irradiance.b);
    const glm::dvec3 albedo(sea.albedo.r, sea.albedo.g, sea.albedo.b);
    const glm::dvec3 l_sea = albedo * (e_sun * sun.y + kPi * radiance) / kPi;
    OceanRgb got_sea;
    ok(ocean_lighting_sea_radiance(lighting.get(), &got_sea), "sea radiance");
    check(glm::length(from_c(got_sea) - l_sea) < 1e-12, "L_sea differs");

    for (double elevation : {20.0, 45.0, 80.0}) {
        // Seen from the side (azimuth 90 degrees from the Sun): no glint.
        double e = glm::radians(elevation);
        glm::dvec3 v(std::cos(e), std::sin(e), 0.0);
        OceanSeaLight out;
        if (!ok(ocean_sea_color(lighting.get(), map.get(), to_c(v), OceanDVec3{0.0, 1.0, 0.0},
                                OceanDVec2{1.0, 0.0}, 0.0, 0.0, &out),
                "ocean_sea_color"))
            continue;
        double f = schlick(v.y, sea.fresnel_r);
        check(glm::length(from_c(out.sky) - radiance * f) < 1e-12, "sky term at %g deg",
              elevation);
        check(glm::length(from_c(out.sea) - l_sea * (1.0 - f)) < 1e-12, "sea term at %g deg",
              elevation);
        check(glm::length(from_c(out.sun)) < 1e-30, "no glint at %g deg", elevation);
    }
}

void batch_from_threads()
{
    OceanSkyParams sky;
    OceanSeaParams sea;
    ok(ocean_sky_params_default(&sky), "sky defaults");
    ok(ocean_sea_params_default(&sea), "sea defaults");
    OceanLighting *raw = nullptr;
    if (!ok(ocean_lighting_create(&sky, &sea, &raw), "ocean_lighting_create"))
        return;
    Lighting lighting(raw);
    OceanSkyMap *raw_map = nullptr;
    if (!ok(ocean_lighting_sky_map_create(lighting.get(), 256, &raw_map), "sky map"))
        return;
    SkyMap map(raw_map);

    const size_t n = 4096;
    std::vector<OceanSeaColorInput> inputs(n);
    for (size_t i = 0; i < n; ++i) {
        double e = glm::radians(1.0 + 88.0 * double(i % 97) / 96.0);
        double a = 2.0 * kPi * double(i % 61) / 61.0;
        glm::dvec3 v(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
        double t = glm::radians(15.0 * double(i % 7) / 6.0);
        glm::dvec3 nrm(std::sin(t), std::cos(t), 0.0);
        double s = 0.04 * double(i % 13) / 12.0;
        inputs[i] = OceanSeaColorInput{to_c(v), to_c(nrm), OceanDVec2{0.6, -0.8}, s, 0.5 * s};
    }
    std::vector<OceanSeaLight> single(n), threaded(n);
    ok(ocean_sea_color_batch(lighting.get(), map.get(), inputs.data(), n, single.data()),
       "batch");
    std::vector<std::thread> pool;
    std::vector<OceanStatus> status(4, OCEAN_STATUS_OK);
    for (size_t k = 0; k < 4; ++k) {
        pool.emplace_back([&, k] {
            size_t begin = k * n / 4, end = (k + 1) * n / 4;
            status[k] = ocean_sea_color_batch(lighting.get(), map.get(), inputs.data() + begin,
                                              end - begin, threaded.data() + begin);
        });
    }
    for (auto &t : pool)
        t.join();
    for (size_t k = 0; k < 4; ++k)
        check(status[k] == OCEAN_STATUS_OK, "thread %zu: status %u", k, unsigned(status[k]));
    check(std::memcmp(single.data(), threaded.data(), n * sizeof(OceanSeaLight)) == 0,
          "threaded batch differs from the single-threaded one");
    size_t finite = 0;
    for (const auto &o : single) {
        glm::dvec3 total = from_c(o.sun) + from_c(o.sky) + from_c(o.sea);
        finite += std::isfinite(total.x) && std::isfinite(total.y) && std::isfinite(total.z) &&
                  total.x >= 0.0 && total.y >= 0.0 && total.z >= 0.0;
    }
    check(finite == n, "%zu of %zu outputs finite and non-negative", finite, n);
}

} // namespace

int main()
{
    footprint_looking_down();
    flat_sea_under_a_uniform_sky();
    batch_from_threads();
    std::printf("test_lighting.cpp: library %s, %d checks, %d failures\n", ocean_version(), g_checks,
                g_failures);
    return g_failures == 0 ? 0 : 1;
}
