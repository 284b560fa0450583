// C++17 test of the ocean C ABI (include/ocean.h) with GLM, linked against libocean.a.
//
// Built and run by tests/tests/c_abi.rs with
//   c++ -std=c++17 -Wall -Wextra -Werror -pedantic -I include tests/cpp/test_waves.cpp libocean.a ...
//
// What a C++ engine does with the library: RAII handle, glm vectors, many threads sharing one
// const wave set. The expected surface is computed here with glm::dvec3 from the closed form
// (Yrjola & Larsson Eq. 6-7, dispersion Eq. 4/5) and its analytic derivatives (the C test uses
// finite differences instead, so the two references are independent of each other).
//
// Prints a summary; exits 0 only if every check passed.
#include "ocean.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGravity = 9.81;  // m/s^2, the library's documented value

// Tolerances (see tests/c/test_waves.c for the derivation): positions are float sums of four
// waves plus a rest coordinate of at most ~300 m (half an ulp: 2^-24 * 256 = 1.5e-5 at worst),
// phases rounded to float after a double reduction (1.9e-7 rad): worst case ~2e-5 m, so 1e-4 m
// leaves a 5x margin. Normals: a few float roundings of terms <= 0.25 and a float
// normalisation: ~1e-6, tolerance 1e-5.
constexpr double kPosTol = 1e-4;
constexpr double kNrmTol = 1e-5;

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

std::string last_error() { return ocean_last_error_message(); }

// Layout: OceanVec3 is packed floats, like glm::vec3 (GLM's default, unaligned
// configuration). Checked here so the conversions below are only a convenience, not a claim.
static_assert(std::is_standard_layout<OceanVec3>::value, "OceanVec3 is a C struct");
static_assert(sizeof(OceanVec3) == sizeof(glm::vec3), "OceanVec3 matches glm::vec3");
static_assert(alignof(OceanVec3) == alignof(glm::vec3), "OceanVec3 alignment matches glm");
// World positions cross in double precision: OceanDVec2/OceanDVec3 are glm::dvec2/dvec3.
static_assert(sizeof(OceanDVec2) == sizeof(glm::dvec2), "OceanDVec2 matches glm::dvec2");
static_assert(sizeof(OceanDVec3) == sizeof(glm::dvec3), "OceanDVec3 matches glm::dvec3");
static_assert(std::is_same<std::underlying_type<OceanStatus>::type, uint32_t>::value,
              "OceanStatus is a uint32_t enum in C++");

glm::dvec3 to_glm(const OceanVec3 &v) { return glm::dvec3(v.x, v.y, v.z); }
glm::dvec3 to_glm(const OceanDVec3 &v) { return glm::dvec3(v.x, v.y, v.z); }

struct WavesDeleter {
    void operator()(OceanWaves *w) const { ocean_waves_destroy(w); }
};
using WavesPtr = std::unique_ptr<OceanWaves, WavesDeleter>;

WavesPtr make_waves(const std::vector<OceanWaveDesc> &descs)
{
    OceanWaves *w = nullptr;
    OceanStatus s = ocean_waves_create(descs.data(), descs.size(), &w);
    check(s == OCEAN_STATUS_OK && w != nullptr, "create: status %u: %s", unsigned(s),
          last_error().c_str());
    return WavesPtr(w);
}

// Reference surface point and normal, in double, with analytic derivatives of Eq. 6-7.
struct Expected {
    glm::dvec3 pos;
    glm::dvec3 normal;
};

Expected reference(const std::vector<OceanWaveDesc> &waves, glm::dvec2 p0, double t)
{
    glm::dvec3 pos(p0.x, 0.0, p0.y);
    glm::dvec3 dpdx(1.0, 0.0, 0.0);  // d(position)/d(x0)
    glm::dvec3 dpdz(0.0, 0.0, 1.0);  // d(position)/d(z0)
    for (const OceanWaveDesc &w : waves) {
        const glm::dvec2 khat = glm::normalize(glm::dvec2(w.direction_x, w.direction_z));
        const double k = 2.0 * kPi / w.wavelength;
        const double omega = std::isinf(w.depth) ? std::sqrt(kGravity * k)  // Eq. 5
                                                 : std::sqrt(kGravity * k * std::tanh(k * w.depth));  // Eq. 4
        const double theta = k * glm::dot(khat, p0) - omega * t + w.phase;
        const double s = std::sin(theta), c = std::cos(theta);
        const double a = w.amplitude;
        pos += glm::dvec3(-khat.x * a * s, a * c, -khat.y * a * s);
        // d theta / d x0 = k khat.x, d theta / d z0 = k khat.y
        dpdx += glm::dvec3(-khat.x * a * c, -a * s, -khat.y * a * c) * (k * khat.x);
        dpdz += glm::dvec3(-khat.x * a * c, -a * s, -khat.y * a * c) * (k * khat.y);
    }
    return {pos, glm::normalize(glm::cross(dpdz, dpdx))};
}

const std::vector<OceanWaveDesc> kWaves = {
    // amplitude, wavelength, direction x, z, phase, depth (INFINITY = deep water)
    {0.6, 18.0, 0.2, 1.0, 0.1, INFINITY},
    {0.3, 7.0, 1.0, -0.5, 1.9, 1.5},  // k*D = 1.35: tanh(kD) = 0.87 matters
    {0.15, 4.2, -1.0, -1.0, -2.2, INFINITY},
    {0.4, 55.0, -0.3, 0.8, 0.0, 4.0},  // shallow: k*D = 0.46
};

std::vector<OceanDVec2> make_points(std::size_t n, double extent, glm::dvec2 centre = {})
{
    // Deterministic points on a lattice of 1/64 m up to +-extent around `centre`.
    std::vector<OceanDVec2> pts(n);
    std::uint32_t state = 12345u;
    const int span = int(extent * 128.0), half = int(extent * 64.0);
    for (OceanDVec2 &p : pts) {
        state = state * 1664525u + 1013904223u;
        p.x = centre.x + double(int(state >> 8) % span - half) / 64.0;
        state = state * 1664525u + 1013904223u;
        p.z = centre.y + double(int(state >> 8) % span - half) / 64.0;
    }
    return pts;
}

double max_pos_err = 0.0, max_nrm_err = 0.0;

void compare(const glm::dvec3 &p, const OceanVec3 &n, const Expected &e, const char *what,
             std::size_t i)
{
    const glm::dvec3 dp = glm::abs(p - e.pos);
    const glm::dvec3 dn = glm::abs(to_glm(n) - e.normal);
    const double ep = glm::max(dp.x, glm::max(dp.y, dp.z));
    const double en = glm::max(dn.x, glm::max(dn.y, dn.z));
    max_pos_err = std::fmax(max_pos_err, ep);
    max_nrm_err = std::fmax(max_nrm_err, en);
    check(ep <= kPosTol, "%s[%zu]: position error %g m", what, i, ep);
    check(en <= kNrmTol, "%s[%zu]: normal error %g", what, i, en);
}

void test_version()
{
    char expected[64];
    std::snprintf(expected, sizeof expected, "%d.%d.%d", OCEAN_VERSION_MAJOR,
                  OCEAN_VERSION_MINOR, OCEAN_VERSION_PATCH);
    check(std::strcmp(ocean_version(), expected) == 0, "version %s, header %s", ocean_version(),
          expected);
    check(std::string(ocean_status_message(OCEAN_STATUS_TOO_STEEP)).find("steep") !=
              std::string::npos,
          "TOO_STEEP message: %s", ocean_status_message(OCEAN_STATUS_TOO_STEEP));
}

void test_points_against_reference(const OceanWaves *w)
{
    // Near the origin and 100 km from it: double positions keep the same tolerance there.
    for (const glm::dvec2 centre : {glm::dvec2(0.0), glm::dvec2(1.0e5, -7.3e4)}) {
        const std::vector<OceanDVec2> pts = make_points(300, 300.0, centre);
        std::vector<OceanDVec3> pos(pts.size());
        std::vector<OceanVec3> nrm(pts.size());
        for (double t : {0.0, 12.345, 86400.0 * 30.0}) {  // 30 days: phases ~ 1e6..1e7 rad
            OceanStatus s =
                ocean_waves_evaluate(w, pts.data(), pts.size(), t, pos.data(), nrm.data());
            check(s == OCEAN_STATUS_OK, "evaluate t=%g: %s", t, last_error().c_str());
            for (std::size_t i = 0; i < pts.size(); ++i) {
                compare(to_glm(pos[i]), nrm[i],
                        reference(kWaves, glm::dvec2(pts[i].x, pts[i].z), t), "points", i);
            }
        }
    }
}

void test_grid_against_reference(const OceanWaves *w)
{
    // Negative, far origin; nx = 29 (not a multiple of 8), 3 rows.
    const OceanGrid g{-73000.5, 41000.25, 0.5, 2.0, 29, 3};
    std::vector<OceanVec3> pos(g.nx * g.nz), nrm(g.nx * g.nz);
    const double t = 7.25;
    OceanStatus s = ocean_waves_evaluate_grid(w, &g, t, pos.data(), nrm.data());
    check(s == OCEAN_STATUS_OK, "grid: %s", last_error().c_str());
    for (std::size_t j = 0; j < g.nz; ++j) {
        for (std::size_t i = 0; i < g.nx; ++i) {
            const glm::dvec2 origin(g.origin_x, g.origin_z);
            const glm::dvec2 p0 = origin + glm::dvec2(double(i) * g.spacing_x, double(j) * g.spacing_z);
            Expected e = reference(kWaves, p0, t);
            e.pos -= glm::dvec3(origin.x, 0.0, origin.y);  // grid output is origin-relative
            compare(to_glm(pos[j * g.nx + i]), nrm[j * g.nx + i], e, "grid", j * g.nx + i);
        }
    }
}

template <typename V>
bool bit_equal(const std::vector<V> &a, const std::vector<V> &b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(V)) == 0;
}

// One const handle evaluated from 8 threads at once gives bit-identical results to a single
// thread (the header's thread-safety promise and determinism); 40000 points take the library's
// multi-threaded path, which must equal evaluating the same points 1000 at a time (serial path).
void test_threads(const OceanWaves *w)
{
    const std::vector<OceanDVec2> pts = make_points(40000, 500.0);
    const double t = 3.0;
    std::vector<OceanDVec3> pos(pts.size());
    std::vector<OceanVec3> nrm(pts.size());
    check(ocean_waves_evaluate(w, pts.data(), pts.size(), t, pos.data(), nrm.data()) ==
              OCEAN_STATUS_OK,
          "evaluate 40000: %s", last_error().c_str());

    std::vector<OceanDVec3> cpos(pts.size());
    std::vector<OceanVec3> cnrm(pts.size());
    for (std::size_t i = 0; i < pts.size(); i += 1000) {
        check(ocean_waves_evaluate(w, &pts[i], 1000, t, &cpos[i], &cnrm[i]) == OCEAN_STATUS_OK,
              "evaluate chunk: %s", last_error().c_str());
    }
    check(bit_equal(pos, cpos) && bit_equal(nrm, cnrm),
          "parallel and chunked serial evaluation differ");

    const OceanGrid g{1000.0, -2000.0, 0.25, 0.25, 200, 150};
    std::vector<OceanVec3> gpos(g.nx * g.nz), gnrm(g.nx * g.nz);
    check(ocean_waves_evaluate_grid(w, &g, t, gpos.data(), gnrm.data()) == OCEAN_STATUS_OK,
          "grid: %s", last_error().c_str());

    std::atomic<int> mismatches{0};
    std::vector<std::thread> threads;
    for (int k = 0; k < 8; ++k) {
        threads.emplace_back([&, k] {
            for (int rep = 0; rep < 3; ++rep) {
                std::vector<OceanDVec3> p(pts.size());
                std::vector<OceanVec3> n(pts.size());
                if (ocean_waves_evaluate(w, pts.data(), pts.size(), t, p.data(), n.data()) !=
                        OCEAN_STATUS_OK ||
                    !bit_equal(p, pos) || !bit_equal(n, nrm))
                    ++mismatches;
                std::vector<OceanVec3> gp(gpos.size()), gn(gpos.size());
                if (ocean_waves_evaluate_grid(w, &g, t, gp.data(), gn.data()) != OCEAN_STATUS_OK ||
                    !bit_equal(gp, gpos) || !bit_equal(gn, gnrm))
                    ++mismatches;
                // Errors on this thread stay on this thread (checked below for the others).
                if (k % 2 == 0) {
                    std::size_t c;
                    if (ocean_waves_count(nullptr, &c) != OCEAN_STATUS_NULL_POINTER ||
                        last_error().find("waves") == std::string::npos)
                        ++mismatches;
                } else if (!last_error().empty()) {
                    ++mismatches;
                }
            }
        });
    }
    for (std::thread &th : threads)
        th.join();
    check(mismatches.load() == 0, "%d concurrent evaluations differed or misreported",
          mismatches.load());
}

void test_errors(const OceanWaves *w)
{
    // A sample of the error paths from C++ (the C test drives all of them).
    std::vector<OceanDVec3> pos(4, OceanDVec3{1.0, 2.0, 3.0});
    std::vector<OceanVec3> nrm(4, OceanVec3{1.0f, 2.0f, 3.0f});
    const std::vector<OceanDVec3> before = pos;
    const std::vector<OceanVec3> nrm_before = nrm;
    const OceanDVec2 xz[4] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};

    OceanStatus s = ocean_waves_evaluate(w, xz, 4, std::nan(""), pos.data(), nrm.data());
    check(s == OCEAN_STATUS_NON_FINITE && !last_error().empty(), "NaN time: %u", unsigned(s));
    s = ocean_waves_evaluate(w, xz, SIZE_MAX / 4, 0.0, pos.data(), nrm.data());
    check(s == OCEAN_STATUS_LENGTH_OVERFLOW && !last_error().empty(), "overflow: %u", unsigned(s));
    s = ocean_waves_evaluate(nullptr, xz, 4, 0.0, pos.data(), nrm.data());
    check(s == OCEAN_STATUS_NULL_POINTER && !last_error().empty(), "null: %u", unsigned(s));
    const OceanGrid bad{0.0, 0.0, -1.0, 1.0, 2, 2};
    std::vector<OceanVec3> gpos = nrm_before;
    s = ocean_waves_evaluate_grid(w, &bad, 0.0, gpos.data(), nrm.data());
    check(s == OCEAN_STATUS_INVALID_ARGUMENT && !last_error().empty(), "bad grid: %u",
          unsigned(s));
    check(bit_equal(pos, before) && bit_equal(nrm, nrm_before) && bit_equal(gpos, nrm_before),
          "failed calls wrote outputs");

    // Too steep: k*A = 2*pi/5 * 0.9 = 1.13.
    OceanWaves *out = nullptr;
    const OceanWaveDesc steep{0.9, 5.0, 1.0, 0.0, 0.0, INFINITY};
    s = ocean_waves_create(&steep, 1, &out);
    check(s == OCEAN_STATUS_TOO_STEEP && out == nullptr, "too steep: %u", unsigned(s));
    check(last_error().find("steepness") != std::string::npos, "message: %s",
          last_error().c_str());
}

}  // namespace

int main()
{
    test_version();
    WavesPtr waves = make_waves(kWaves);
    if (!waves) {
        std::fprintf(stderr, "test_waves.cpp: cannot continue without a wave set\n");
        return 1;
    }
    std::size_t count = 0;
    check(ocean_waves_count(waves.get(), &count) == OCEAN_STATUS_OK && count == kWaves.size(),
          "count %zu", count);
    test_points_against_reference(waves.get());
    test_grid_against_reference(waves.get());
    test_threads(waves.get());
    test_errors(waves.get());
    waves.reset();

    std::printf("test_waves.cpp: library %s, %d checks, %d failures; max |position error| %.3g m "
                "(tolerance %g), max |normal error| %.3g (tolerance %g)\n",
                ocean_version(), g_checks, g_failures, max_pos_err, kPosTol, max_nrm_err,
                kNrmTol);
    return g_failures == 0 ? 0 : 1;
}
