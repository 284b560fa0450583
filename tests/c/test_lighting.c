/*
 * C11 test of the ocean lighting C ABI (crate ocean-brdf: ocean_spectrum_*, ocean_pixel_footprint,
 * the BRDF and Fresnel evaluations, ocean_lighting_*, ocean_sky_map_*, ocean_sea_color*),
 * linked against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_lighting.c libocean.a ...
 *
 * Expected values are computed here from the documented formulas (Bruneton, Neyret & Holzschuch
 * 2010): the spectrum's amplitudes from Eq. 1 and the band rule of OceanSpectrumParams, its
 * statistics and the slope variance of Eq. 4 from the copied waves, footprints of cameras looking
 * straight down from their frusta, Schlick (Eq. 14), the fit of Eq. 26, the Ross BRDF (Eq. 13,
 * with erfc from <math.h>), the Sun's glint on a calm sea (Eq. 15 with the solar-disc variance),
 * the sky map's texels from the environment radiance and its mips from 2x2 means, a uniform sky's
 * irradiance (pi L), and the three terms of the sea colour on a calm sea (the sky term from a
 * bilinear lookup of the copied map, the sea term L_sea (1 - F)). Then every error path, with the
 * outputs untouched.
 *
 * Prints a summary; exits 0 only if every check passed.
 */
#include "ocean.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;
static const double G = 9.81; /* m/s^2, the library's documented gravity */
/* The Sun's mean angular radius (radians) and the solar-disc slope variance rho^2 / 16. */
static const double SUN_RHO = 4.653e-3;

#include "check.h"

/* |got - want| <= rel |want| + abs_tol (NaN fails); the rest is the failure's printf format. */
#define NEAR(got, want, rel, abs_tol, ...)                                                 \
    do {                                                                                   \
        double g_ = (got), w_ = (want);                                                    \
        int ok_ = fabs(g_ - w_) <= (rel) * fabs(w_) + (abs_tol);                           \
        CHECK(ok_, __VA_ARGS__);                                                           \
        if (!ok_)                                                                          \
            fprintf(stderr, "    got %.17g, expected %.17g\n", g_, w_);                    \
    } while (0)

static const double SENTINEL = -12345.0;

static OceanDVec3 dvec3(double x, double y, double z)
{
    double n = sqrt(x * x + y * y + z * z);
    OceanDVec3 v;
    v.x = x / n;
    v.y = y / n;
    v.z = z / n;
    return v;
}

static double dot3(OceanDVec3 a, OceanDVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

static double schlick_ref(double c, double r) { return r + (1.0 - r) * pow(1.0 - c, 5.0); }

/* ------------------------------------------------------------------------------------------ */
/* Spectrum.                                                                                  */

/* Eq. 1: the Pierson-Moskowitz spectrum. */
static double pierson_moskowitz(double omega, double wind)
{
    double r = (G / wind) / omega;
    return 8.1e-3 * G * G / pow(omega, 5.0) * exp(-0.74 * r * r * r * r);
}

/* Appendix A, in the cancellation-free form: 1 - sqrt(1 - s^2) = s^2 / (1 + sqrt(1 - s^2)). */
static double trochoid_slope_variance(double ka)
{
    double s = ka * ka;
    return s / (1.0 + sqrt(1.0 - s));
}

static double smooth_weight(double a, double b, double x)
{
    double t = (x - a) / (b - a);
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return t * t * (3.0 - 2.0 * t);
}

/* Eq. 4 summed over every wave, as printed, in the wind frame (wx, wz). */
static void unresolved_ref(const OceanWaveDesc *w, size_t n, double wx, double wz, double n_min,
                           double n_max, double footprint, double out[2])
{
    size_t i;
    out[0] = out[1] = 0.0;
    for (i = 0; i < n; i++) {
        double k = 2.0 * PI / w[i].wavelength;
        double wr = footprint > 0.0
                        ? 1.0 - smooth_weight(n_min, n_max, w[i].wavelength / footprint)
                        : 0.0;
        double v = trochoid_slope_variance(k * w[i].amplitude * wr);
        double c = w[i].direction_x * wx + w[i].direction_z * wz;
        out[0] += v * c * c;
        out[1] += v * (1.0 - c * c);
    }
}

static void test_spectrum(void)
{
    OceanSpectrumParams p;
    OceanSpectrum *s = NULL, *untouched = (OceanSpectrum *)&p;
    OceanWaveDesc *waves;
    size_t n = 0, i, clamped = 0, got_clamped = 0;
    double ratio, half, sum_a = 0, sum_ka = 0, shift = 0, hvar = 0, var[2] = {0, 0};
    double got, mean_cos = 0, ref[2];
    OceanDVec2 wind;
    OceanSlopeVariance sv, total;
    OceanWaves *ow = NULL;

    OK(ocean_spectrum_params_default(&p));
    CHECK(p.wind_speed == 10.0 && p.wind_direction_x == 1.0 && p.wind_direction_z == 0.0 &&
              p.wave_count == 60 && p.min_wavelength == 0.02 && p.max_wavelength == 30.0 &&
              p.max_steepness == 0.5 && p.seed == 0,
          "default spectrum parameters");

    /* A non-unit wind direction (normalised to (0.6, 0.8)), 40 waves, a steepness cap that
     * clamps some of them. */
    p.wind_direction_x = 3.0;
    p.wind_direction_z = 4.0;
    p.wave_count = 40;
    p.min_wavelength = 0.05;
    p.max_wavelength = 60.0;
    p.wind_speed = 14.0;
    /* Eq. 1's tail gives every short wave the same k A (about 0.0384 at 14 m/s); the waves
     * near the peak are gentler. A cap of 0.0375 clamps the short ones only. */
    p.max_steepness = 0.0375;
    p.seed = 42;
    if (!OK(ocean_spectrum_create(&p, &s)))
        return;
    OK(ocean_spectrum_wave_count(s, &n));
    CHECK(n == 40, "wave count %zu", n);
    OK(ocean_spectrum_wind_direction(s, &wind));
    NEAR(wind.x, 0.6, 1e-15, 0.0, "wind x");
    NEAR(wind.z, 0.8, 1e-15, 0.0, "wind z");

    waves = (OceanWaveDesc *)malloc(40 * sizeof *waves);
    if (!waves)
        abort();
    OK(ocean_spectrum_waves(s, waves, 40));

    /* Amplitudes from Eq. 1 and the band rule of OceanSpectrumParams. */
    ratio = pow(p.max_wavelength / p.min_wavelength, 1.0 / 39.0);
    half = pow(ratio, 0.25);
    for (i = 0; i < 40; i++) {
        double lambda = p.min_wavelength * pow(ratio, (double)i);
        double k = 2.0 * PI / lambda, omega = sqrt(G * k);
        double a = sqrt(2.0 * pierson_moskowitz(omega, p.wind_speed) * omega * (half - 1.0 / half));
        double dlen = hypot(waves[i].direction_x, waves[i].direction_z);
        if (k * a > p.max_steepness) {
            a = p.max_steepness / k;
            clamped++;
        }
        NEAR(waves[i].wavelength, lambda, 1e-12, 0.0, "wave %zu wavelength", i);
        NEAR(waves[i].amplitude, a, 1e-12, 0.0, "wave %zu amplitude (Eq. 1)", i);
        NEAR(dlen, 1.0, 1e-14, 0.0, "wave %zu direction length", i);
        CHECK(waves[i].phase >= 0.0 && waves[i].phase < 2.0 * PI, "wave %zu phase %g", i,
              waves[i].phase);
        CHECK(isinf(waves[i].depth) && waves[i].depth > 0, "wave %zu depth %g", i,
              waves[i].depth);
        mean_cos += (waves[i].direction_x * 0.6 + waves[i].direction_z * 0.8) / 40.0;
        k = 2.0 * PI / waves[i].wavelength;
        a = waves[i].amplitude;
        sum_a += a;
        sum_ka += k * a;
        shift -= 0.5 * k * a * a;
        hvar += 0.5 * a * a - (0.5 * k * a * a) * (0.5 * k * a * a);
    }
    CHECK(clamped > 0 && clamped < 40, "the steepness cap should clamp some waves: %zu", clamped);
    OK(ocean_spectrum_clamped_count(s, &got_clamped));
    CHECK(got_clamped == clamped, "clamped %zu, expected %zu", got_clamped, clamped);
    /* Hasselmann spreading with s >= 2 around the wind: E[cos] >= 2/3; 40 draws. */
    CHECK(mean_cos > 0.4, "waves do not travel with the wind: mean cos %g", mean_cos);

    OK(ocean_spectrum_max_amplitude(s, &got));
    NEAR(got, sum_a, 1e-13, 0.0, "max amplitude = sum A");
    OK(ocean_spectrum_steepness_sum(s, &got));
    NEAR(got, sum_ka, 1e-13, 0.0, "steepness sum");
    OK(ocean_spectrum_mean_height_shift(s, &got));
    NEAR(got, shift, 1e-13, 0.0, "mean height shift = -sum k A^2 / 2");
    OK(ocean_spectrum_height_variance(s, &got));
    NEAR(got, hvar, 1e-13, 0.0, "height variance");

    /* Total slope variance (Eq. 4, w_r = 1). */
    unresolved_ref(waves, 40, 0.6, 0.8, 1.0, 2.5, 1e300, var);
    OK(ocean_spectrum_total_slope_variance(s, &total));
    NEAR(total.sigma_x2, var[0], 1e-12, 0.0, "total sigma_x2");
    NEAR(total.sigma_y2, var[1], 1e-12, 0.0, "total sigma_y2");
    CHECK(total.sigma_x2 > total.sigma_y2, "upwind variance %g <= crosswind %g",
          total.sigma_x2, total.sigma_y2);

    /* Unresolved variance for pixel footprints: 0 resolves everything, a huge one nothing, and
     * in between Eq. 4 as printed, for the paper's filter and another one. */
    OK(ocean_spectrum_slope_variance(s, OCEAN_FILTER_N_MIN, OCEAN_FILTER_N_MAX, 0.0, &sv));
    CHECK(sv.sigma_x2 >= 0 && sv.sigma_x2 <= 1e-15 && sv.sigma_y2 >= 0 && sv.sigma_y2 <= 1e-15,
          "footprint 0: (%g, %g)", sv.sigma_x2, sv.sigma_y2);
    OK(ocean_spectrum_slope_variance(s, OCEAN_FILTER_N_MIN, OCEAN_FILTER_N_MAX, 1e6, &sv));
    NEAR(sv.sigma_x2, total.sigma_x2, 1e-15, 0.0, "footprint 1e6 m: everything unresolved");
    NEAR(sv.sigma_y2, total.sigma_y2, 1e-15, 0.0, "footprint 1e6 m: everything unresolved");
    {
        const double footprints[] = {0.01, 0.05, 0.3, 1.7, 12.0};
        const double filters[][2] = {{1.0, 2.5}, {2.0, 4.0}};
        size_t f, j;
        double prev = -1.0;
        for (f = 0; f < 2; f++) {
            prev = -1.0;
            for (j = 0; j < sizeof footprints / sizeof footprints[0]; j++) {
                unresolved_ref(waves, 40, 0.6, 0.8, filters[f][0], filters[f][1], footprints[j],
                               ref);
                OK(ocean_spectrum_slope_variance(s, filters[f][0], filters[f][1], footprints[j],
                                                 &sv));
                NEAR(sv.sigma_x2, ref[0], 1e-9, 1e-16, "Eq. 4 x, footprint %g", footprints[j]);
                NEAR(sv.sigma_y2, ref[1], 1e-9, 1e-16, "Eq. 4 y, footprint %g", footprints[j]);
                CHECK(sv.sigma_x2 + sv.sigma_y2 > prev,
                      "variance must grow with the footprint (%g m)", footprints[j]);
                prev = sv.sigma_x2 + sv.sigma_y2;
            }
        }
    }

    /* The waves feed ocean_waves_create as they are. */
    if (OK(ocean_waves_create(waves, 40, &ow))) {
        OceanDVec2 x0 = {0.0, 0.0};
        OceanDVec3 pos;
        OceanVec3 nrm;
        double h = 0.0;
        OK(ocean_waves_max_amplitude(ow, &got));
        NEAR(got, sum_a, 1e-13, 0.0, "wave set's max amplitude");
        OK(ocean_waves_steepness_sum(ow, &got));
        NEAR(got, sum_ka, 1e-13, 0.0, "wave set's steepness sum");
        /* At the origin and t = 0 the height is sum A cos(phase) (Eq. 6). */
        for (i = 0; i < 40; i++)
            h += waves[i].amplitude * cos(waves[i].phase);
        OK(ocean_waves_evaluate(ow, &x0, 1, 0.0, &pos, &nrm));
        NEAR(pos.y, h, 0.0, 1e-5, "height at the origin");
        ocean_waves_destroy(ow);
    }

    /* Errors: outputs untouched. */
    {
        OceanSpectrumParams bad = p;
        OceanWaveDesc copy[40];
        size_t cnt = 777;
        OceanDVec2 w2 = {SENTINEL, SENTINEL};
        OceanSlopeVariance v2 = {SENTINEL, SENTINEL};
        double d = SENTINEL;

        EXPECT(ocean_spectrum_params_default(NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_spectrum_create(NULL, &untouched), OCEAN_STATUS_NULL_POINTER, "params");
        EXPECT_MSG(ocean_spectrum_create(&p, NULL), OCEAN_STATUS_NULL_POINTER, "out");
        bad.wave_count = 0;
        EXPECT_MSG(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_EMPTY, "wave_count");
        bad = p;
        bad.wave_count = 2000;
        EXPECT(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_INVALID_ARGUMENT);
        bad = p;
        bad.wind_speed = NAN;
        EXPECT_MSG(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_NON_FINITE,
                   "wind_speed");
        bad = p;
        bad.max_wavelength = INFINITY;
        EXPECT_MSG(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_NON_FINITE,
                   "max_wavelength");
        bad = p;
        bad.wind_direction_x = 0.0;
        bad.wind_direction_z = 0.0;
        EXPECT_MSG(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_INVALID_ARGUMENT,
                   "wind direction");
        bad = p;
        bad.max_wavelength = 0.01;
        EXPECT(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_INVALID_ARGUMENT);
        bad = p;
        bad.max_steepness = 1.5;
        EXPECT(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_INVALID_ARGUMENT);
        bad = p;
        bad.wind_speed = -3.0;
        EXPECT(ocean_spectrum_create(&bad, &untouched), OCEAN_STATUS_INVALID_ARGUMENT);
        CHECK(untouched == (OceanSpectrum *)&p, "a failed create wrote *out");

        memset(copy, 0x5a, sizeof copy);
        EXPECT_MSG(ocean_spectrum_waves(s, copy, 39), OCEAN_STATUS_LENGTH_MISMATCH, "40");
        EXPECT(ocean_spectrum_waves(s, copy, 41), OCEAN_STATUS_LENGTH_MISMATCH);
        EXPECT(ocean_spectrum_waves(s, NULL, 40), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_waves(NULL, copy, 40), OCEAN_STATUS_NULL_POINTER);
        {
            unsigned char pattern[sizeof copy];
            memset(pattern, 0x5a, sizeof pattern);
            CHECK(memcmp(copy, pattern, sizeof copy) == 0, "a failed copy wrote the buffer");
        }

        EXPECT(ocean_spectrum_wave_count(NULL, &cnt), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_wave_count(s, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_clamped_count(NULL, &cnt), OCEAN_STATUS_NULL_POINTER);
        CHECK(cnt == 777, "count written on failure");
        EXPECT(ocean_spectrum_wind_direction(NULL, &w2), OCEAN_STATUS_NULL_POINTER);
        CHECK(w2.x == SENTINEL, "wind written on failure");
        EXPECT(ocean_spectrum_max_amplitude(NULL, &d), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_steepness_sum(NULL, &d), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_mean_height_shift(NULL, &d), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_height_variance(NULL, &d), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_height_variance(s, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(d == SENTINEL, "statistic written on failure");
        EXPECT(ocean_spectrum_total_slope_variance(NULL, &v2), OCEAN_STATUS_NULL_POINTER);

        EXPECT_MSG(ocean_spectrum_slope_variance(s, 1.0, 2.5, NAN, &v2), OCEAN_STATUS_NON_FINITE,
                   "pixel_footprint");
        EXPECT_MSG(ocean_spectrum_slope_variance(s, 1.0, 2.5, INFINITY, &v2),
                   OCEAN_STATUS_NON_FINITE, "pixel_footprint");
        EXPECT_MSG(ocean_spectrum_slope_variance(s, 1.0, 2.5, -0.1, &v2),
                   OCEAN_STATUS_INVALID_ARGUMENT, "pixel_footprint");
        EXPECT_MSG(ocean_spectrum_slope_variance(s, NAN, 2.5, 0.1, &v2), OCEAN_STATUS_NON_FINITE,
                   "n_min");
        EXPECT(ocean_spectrum_slope_variance(s, 2.5, 2.5, 0.1, &v2),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_spectrum_slope_variance(s, 3.0, 2.5, 0.1, &v2),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_spectrum_slope_variance(s, 0.0, 2.5, 0.1, &v2),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_spectrum_slope_variance(s, 1.0, 2.5, 0.1, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_spectrum_slope_variance(NULL, 1.0, 2.5, 0.1, &v2),
               OCEAN_STATUS_NULL_POINTER);
        CHECK(v2.sigma_x2 == SENTINEL && v2.sigma_y2 == SENTINEL,
              "variance written on failure");
    }

    free(waves);
    ocean_spectrum_destroy(s);
    ocean_spectrum_destroy(NULL);
}

/* ------------------------------------------------------------------------------------------ */
/* Pixel footprint.                                                                           */

/* A camera at (ex, h, ez) looking straight down: view-space x = world +x, y = world -z,
 * z = world +y (the camera looks down its -z axis, i.e. world -y). Column-major. */
static void look_down(double ex, double h, double ez, double view[16])
{
    /* Rows of the rotation: right (1,0,0), up (0,0,-1), back (0,1,0). */
    const double r[3][3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    const double eye[3] = {ex, h, ez};
    int row, col;
    for (col = 0; col < 3; col++)
        for (row = 0; row < 3; row++)
            view[col * 4 + row] = r[row][col];
    for (row = 0; row < 3; row++) {
        view[12 + row] = -(r[row][0] * eye[0] + r[row][1] * eye[1] + r[row][2] * eye[2]);
        view[row * 4 + 3] = 0.0;
    }
    view[15] = 1.0;
}

static void test_pixel_footprint(void)
{
    OceanCamera cam;
    double l = 0.0, prev = 0.0, d = SENTINEL;
    unsigned conv;
    int j;

    /* Orthographic, 40 m x 20 m over 200 x 100 pixels: every pixel is 0.2 m wide. The matrix
     * is glm::orthoRH_ZO(-20, 20, -10, 10, 0.5, 100). */
    memset(&cam, 0, sizeof cam);
    look_down(5.0, 30.0, -7.0, cam.view);
    cam.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE;
    cam.projection[0] = 2.0 / 40.0;
    cam.projection[5] = 2.0 / 20.0;
    cam.projection[10] = -1.0 / (100.0 - 0.5);
    cam.projection[14] = -0.5 / (100.0 - 0.5);
    cam.projection[15] = 1.0;
    OK(ocean_pixel_footprint(&cam, 200, 100, 0.5, 0.5, 1e4, &l));
    NEAR(l, 0.2, 1e-9, 0.0, "orthographic footprint, corner pixel");
    OK(ocean_pixel_footprint(&cam, 200, 100, 117.5, 63.5, 1e4, &l));
    NEAR(l, 0.2, 1e-9, 0.0, "orthographic footprint, inner pixel");

    /* Perspective from 10 m, fov_y 1 rad: at the centre a pixel spans 2 h tan(fov/2) / height
     * metres, in every depth convention. */
    look_down(0.0, 10.0, 0.0, cam.view);
    for (conv = 0; conv < 3; conv++) {
        cam.depth_convention = conv;
        check_perspective(1.0, 2.0, 0.1, conv == 1 ? INFINITY : 500.0, conv, cam.projection);
        OK(ocean_pixel_footprint(&cam, 200, 100, 100.0, 50.0, 1e4, &l));
        NEAR(l, 2.0 * 10.0 * tan(0.5) / 100.0, 1e-9, 0.0, "perspective footprint, convention %u",
             conv);
    }
    /* Farther from the centre the ground is farther: the footprint grows towards the edges
     * (the rays there are oblique). */
    prev = 0.0;
    for (j = 0; j < 5; j++) {
        OK(ocean_pixel_footprint(&cam, 200, 100, 100.0, 50.0 - 10.0 * j, 1e4, &l));
        CHECK(l > prev * (1.0 - 1e-12), "footprint must not shrink towards the edge: %g < %g", l,
              prev);
        prev = l;
    }

    /* Errors: output untouched. */
    EXPECT_MSG(ocean_pixel_footprint(NULL, 200, 100, 1, 1, 1e4, &d), OCEAN_STATUS_NULL_POINTER,
               "camera");
    EXPECT(ocean_pixel_footprint(&cam, 200, 100, 1, 1, 1e4, NULL), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_pixel_footprint(&cam, 0, 100, 1, 1, 1e4, &d), OCEAN_STATUS_EMPTY);
    EXPECT(ocean_pixel_footprint(&cam, 200, 0, 1, 1, 1e4, &d), OCEAN_STATUS_EMPTY);
    EXPECT_MSG(ocean_pixel_footprint(&cam, 200, 100, NAN, 1, 1e4, &d), OCEAN_STATUS_NON_FINITE,
               "px");
    EXPECT_MSG(ocean_pixel_footprint(&cam, 200, 100, 1, 1, INFINITY, &d),
               OCEAN_STATUS_NON_FINITE, "max_distance");
    EXPECT_MSG(ocean_pixel_footprint(&cam, 200, 100, 1, 1, 0.0, &d),
               OCEAN_STATUS_INVALID_ARGUMENT, "max_distance");
    {
        OceanCamera bad = cam;
        bad.view[13] = NAN;
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d), OCEAN_STATUS_NON_FINITE,
                   "view[13]");
        bad = cam;
        bad.projection[7] = 0.5; /* neither a perspective nor an orthographic bottom row */
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "bottom row");
        bad = cam;
        bad.reserved = 1;
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "reserved");
        bad = cam;
        bad.depth_convention = 7;
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "depth_convention");
        bad = cam;
        bad.projection[5] = -bad.projection[5]; /* y-flipped */
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "y-flipped");
        bad = cam;
        bad.projection[5] = NAN;
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d), OCEAN_STATUS_NON_FINITE,
                   "projection[5]");
        /* A [0, 1] forward matrix declared reversed: its far plane comes before its near one. */
        bad = cam;
        bad.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE;
        check_perspective(1.0, 2.0, 0.1, 500.0, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE, bad.projection);
        OK(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &l));
        bad.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED;
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "far plane");
        bad = cam;
        bad.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE;
        memset(bad.view, 0, sizeof bad.view); /* singular */
        EXPECT(ocean_pixel_footprint(&bad, 200, 100, 1, 1, 1e4, &d),
               OCEAN_STATUS_INVALID_ARGUMENT);
        bad = cam;
        look_down(0.0, -5.0, 0.0, bad.view); /* under water */
        EXPECT_MSG(ocean_pixel_footprint(&bad, 200, 100, 100, 50, 1e4, &d),
                   OCEAN_STATUS_INVALID_ARGUMENT, "above the sea");
    }
    CHECK(d == SENTINEL, "footprint written on failure: %g", d);
}

/* ------------------------------------------------------------------------------------------ */
/* Stateless evaluations.                                                                     */

static double lambda_smith(double a)
{
    if (isinf(a))
        return 0.0;
    return (exp(-a * a) - a * sqrt(PI) * erfc(a)) / (2.0 * a * sqrt(PI));
}

/* Smith's a for a unit tangent-frame direction (Eq. 9 with tan^2). */
static double smith_a(OceanDVec3 d, double sx2, double sy2)
{
    double den = sqrt(2.0 * (sx2 * d.x * d.x + sy2 * d.y * d.y));
    return den > 0.0 ? d.z / den : INFINITY;
}

/* Eq. 13 with Eq. 5 and Schlick's F at v.h. */
static double ross_ref(OceanDVec3 v, OceanDVec3 l, double sx2, double sy2, double r)
{
    OceanDVec3 h;
    double zx, zy, p, f;
    if (v.z <= 0.0 || l.z <= 0.0)
        return 0.0;
    h = dvec3(v.x + l.x, v.y + l.y, v.z + l.z);
    zx = -h.x / h.z;
    zy = -h.y / h.z;
    p = exp(-0.5 * (zx * zx / sx2 + zy * zy / sy2)) / (2.0 * PI * sqrt(sx2) * sqrt(sy2));
    f = schlick_ref(dot3(v, h), r);
    return p * f /
           (4.0 * pow(h.z, 4.0) * v.z * l.z *
            (1.0 + lambda_smith(smith_a(v, sx2, sy2)) + lambda_smith(smith_a(l, sx2, sy2))));
}

static void test_evaluations(void)
{
    const double R = OCEAN_WATER_R;
    double out = SENTINEL, want, a, b;
    int i;

    /* Schlick (Eq. 14): R at normal incidence, 1 at grazing, clamped cosines. */
    CHECK(R == 0.02, "OCEAN_WATER_R = %g", R);
    OK(ocean_schlick(1.0, R, &out));
    CHECK(out == R, "Schlick at normal incidence: %.17g", out);
    OK(ocean_schlick(0.0, R, &out));
    CHECK(out == 1.0, "Schlick at grazing: %.17g", out);
    OK(ocean_schlick(0.5, R, &out));
    NEAR(out, R + (1.0 - R) / 32.0, 1e-15, 0.0, "Schlick at 60 degrees");
    OK(ocean_schlick(-0.3, R, &out));
    CHECK(out == 1.0, "a back-facing cosine gives 1: %.17g", out);
    OK(ocean_schlick(1.5, 0.3, &out));
    CHECK(out == 0.3, "a cosine above 1 is clamped: %.17g", out);

    /* The fit of Eq. 26 equals Schlick bit for bit at sigma_v = 0, and the formula elsewhere. */
    for (i = 0; i <= 10; i++) {
        double c = i / 10.0;
        OK(ocean_effective_fresnel_fit(c, 0.0, R, &a));
        OK(ocean_schlick(c, R, &b));
        CHECK(a == b, "fit(sigma 0) %.17g != Schlick %.17g at cos %g", a, b, c);
    }
    {
        const double sig[] = {0.05, 0.2, 0.45};
        const double cs[] = {0.05, 0.3, 0.9};
        int k, m;
        for (k = 0; k < 3; k++)
            for (m = 0; m < 3; m++) {
                double sv = sig[k], c = cs[m];
                want = R + (1.0 - R) * pow(1.0 - c, 5.0 * exp(-2.69 * sv)) /
                               (1.0 + 22.7 * pow(sv, 1.5));
                OK(ocean_effective_fresnel_fit(c, sv, R, &out));
                NEAR(out, want, 1e-14, 0.0, "Eq. 26 at cos %g, sigma %g", c, sv);
                /* Roughness lowers the reflectance at grazing angles. */
                OK(ocean_schlick(c, R, &b));
                CHECK(c > 0.1 || out < b, "rough %g not below smooth %g at grazing", out, b);
            }
    }

    /* The integral of Eq. 24: Schlick when smooth, close to the fit when rough. */
    for (i = 0; i < 6; i++) {
        double th = i * 0.3; /* up to 1.5 rad */
        OceanDVec3 v = dvec3(sin(th) * 0.6, sin(th) * 0.8, cos(th));
        OK(ocean_effective_fresnel_integral(v, 0.0, 0.0, R, &out));
        NEAR(out, schlick_ref(v.z, R), 1e-12, 1e-15, "Eq. 24 smooth at theta %g", th);
        OK(ocean_effective_fresnel_integral(v, 0.02, 0.01, R, &out));
        {
            double phi = atan2(v.y, v.x);
            double sv = sqrt(0.02 * cos(phi) * cos(phi) + 0.01 * sin(phi) * sin(phi));
            double fit;
            OK(ocean_effective_fresnel_fit(v.z, sv, R, &fit));
            CHECK(out >= R && out <= 1.0, "Eq. 24 out of [R, 1]: %g", out);
            NEAR(out, fit, 0.0, 0.02, "Eq. 24 vs its fit (Eq. 26) at theta %g", th);
        }
    }

    /* The table of Eq. 24 (what the sea colour uses): Schlick when smooth, within 0.03 of the
       integral for an isotropic rough surface, and the fit's argument checks. */
    for (i = 0; i < 6; i++) {
        double th = i * 0.3;
        OceanDVec3 v = dvec3(sin(th), 0.0, cos(th));
        OK(ocean_effective_fresnel_table(v.z, 0.0, R, &out));
        NEAR(out, schlick_ref(v.z, R), 1e-12, 0.0, "table smooth at theta %g", th);
        OK(ocean_effective_fresnel_integral(v, 0.04, 0.04, R, &a));
        OK(ocean_effective_fresnel_table(v.z, 0.2, R, &b));
        NEAR(b, a, 0.0, 0.03, "table vs Eq. 24 at theta %g", th);
    }
    out = 7.0;
    EXPECT(ocean_effective_fresnel_table(1.5, 0.1, R, &out), OCEAN_STATUS_INVALID_ARGUMENT);
    EXPECT(ocean_effective_fresnel_table(NAN, 0.1, R, &out), OCEAN_STATUS_NON_FINITE);
    CHECK(out == 7.0, "table wrote on error: %g", out);

    /* The Ross BRDF (Eq. 13) against the formula, symmetric, zero below the horizon. */
    {
        const OceanDVec3 vs[] = {{0.3, 0.1, 0.9}, {-0.5, 0.4, 0.3}, {0.0, 0.0, 1.0},
                                 {0.9, -0.2, 0.15}};
        const OceanDVec3 ls[] = {{-0.4, 0.2, 0.8}, {0.6, -0.1, 0.5}, {0.2, 0.7, 0.3},
                                 {-0.9, 0.1, 0.2}};
        const double sx[] = {0.02, 0.004, 0.1, 0.3};
        const double sy[] = {0.01, 0.006, 0.05, 0.3};
        int k;
        for (k = 0; k < 4; k++) {
            OceanDVec3 v = dvec3(vs[k].x, vs[k].y, vs[k].z), l = dvec3(ls[k].x, ls[k].y, ls[k].z);
            double back;
            want = ross_ref(v, l, sx[k], sy[k], R);
            OK(ocean_ross_brdf(v, l, sx[k], sy[k], R, &out));
            NEAR(out, want, 1e-10, 1e-300, "Ross BRDF case %d", k);
            CHECK(out > 0.0, "Ross BRDF case %d is zero", k);
            OK(ocean_ross_brdf(l, v, sx[k], sy[k], R, &back));
            CHECK(back == out, "BRDF not symmetric: %.17g vs %.17g", back, out);
            /* Eq. 15: I_sun = L_sun Omega brdf cos(theta_l). */
            OK(ocean_sun_radiance(v, l, sx[k], sy[k], 3.0, 6.8e-5, R, &b));
            NEAR(b, 3.0 * 6.8e-5 * out * l.z, 1e-14, 0.0, "Eq. 15 case %d", k);
        }
        OK(ocean_ross_brdf(dvec3(0.3, 0, 0.9), dvec3(0.2, 0.1, -0.3), 0.02, 0.01, R, &out));
        CHECK(out == 0.0, "light below the horizon: %g", out);
    }

    /* Tone mapping and sRGB. */
    {
        OceanRgb rad = {0.05, 0.0, -1.0}, tm = {SENTINEL, SENTINEL, SENTINEL};
        CHECK(OCEAN_DEFAULT_EXPOSURE == 8.0, "default exposure");
        OK(ocean_tone_map(rad, OCEAN_DEFAULT_EXPOSURE, &tm));
        NEAR(tm.r, 1.0 - exp(-0.4), 1e-15, 0.0, "tone map r");
        CHECK(tm.g == 0.0 && tm.b == 0.0, "tone map of 0 and negative: %g %g", tm.g, tm.b);
        OK(ocean_linear_to_srgb(0.5, &out));
        NEAR(out, 1.055 * pow(0.5, 1.0 / 2.4) - 0.055, 1e-15, 0.0, "sRGB 0.5");
        OK(ocean_linear_to_srgb(0.001, &out));
        NEAR(out, 0.01292, 1e-15, 0.0, "sRGB linear segment");
        tm.r = SENTINEL;
        rad.g = NAN;
        EXPECT_MSG(ocean_tone_map(rad, 8.0, &tm), OCEAN_STATUS_NON_FINITE, "radiance.g");
        rad.g = 0.0;
        EXPECT_MSG(ocean_tone_map(rad, -1.0, &tm), OCEAN_STATUS_INVALID_ARGUMENT, "exposure");
        EXPECT(ocean_tone_map(rad, 8.0, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(tm.r == SENTINEL, "tone map written on failure");
    }

    /* Errors: output untouched. */
    {
        OceanDVec3 v = dvec3(0.3, 0.1, 0.9), l = dvec3(-0.4, 0.2, 0.8);
        OceanDVec3 nan_v = {NAN, 0.0, 1.0}, long_v = {0.0, 0.0, 1.001}, down = {0.0, 0.6, -0.8};
        out = SENTINEL;
        EXPECT_MSG(ocean_schlick(NAN, R, &out), OCEAN_STATUS_NON_FINITE, "cos_theta");
        EXPECT_MSG(ocean_schlick(0.5, 1.5, &out), OCEAN_STATUS_INVALID_ARGUMENT, "r");
        EXPECT(ocean_schlick(0.5, R, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_effective_fresnel_fit(1.5, 0.1, R, &out), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_effective_fresnel_fit(0.5, -0.1, R, &out), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT_MSG(ocean_effective_fresnel_fit(0.5, INFINITY, R, &out), OCEAN_STATUS_NON_FINITE,
                   "sigma_v");
        EXPECT(ocean_effective_fresnel_fit(0.5, 0.1, -0.5, &out), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_effective_fresnel_fit(0.5, 0.1, R, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_effective_fresnel_integral(nan_v, 0.01, 0.01, R, &out),
                   OCEAN_STATUS_NON_FINITE, "v.x");
        EXPECT_MSG(ocean_effective_fresnel_integral(long_v, 0.01, 0.01, R, &out),
                   OCEAN_STATUS_INVALID_ARGUMENT, "unit");
        EXPECT(ocean_effective_fresnel_integral(down, 0.01, 0.01, R, &out),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_effective_fresnel_integral(v, -0.01, 0.01, R, &out),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_effective_fresnel_integral(v, 0.01, 0.01, R, NULL),
               OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_ross_brdf(v, l, 0.0, 0.01, R, &out), OCEAN_STATUS_INVALID_ARGUMENT,
                   "sigma_x2");
        EXPECT_MSG(ocean_ross_brdf(v, l, 0.01, NAN, R, &out), OCEAN_STATUS_NON_FINITE,
                   "sigma_y2");
        EXPECT_MSG(ocean_ross_brdf(nan_v, l, 0.01, 0.01, R, &out), OCEAN_STATUS_NON_FINITE, "v");
        EXPECT_MSG(ocean_ross_brdf(v, long_v, 0.01, 0.01, R, &out),
                   OCEAN_STATUS_INVALID_ARGUMENT, "l");
        EXPECT(ocean_ross_brdf(v, l, 0.01, 0.01, 2.0, &out), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_ross_brdf(v, l, 0.01, 0.01, R, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_sun_radiance(v, l, 0.01, 0.01, 1.0, 7.0, R, &out),
                   OCEAN_STATUS_INVALID_ARGUMENT, "omega_sun");
        EXPECT_MSG(ocean_sun_radiance(v, l, 0.01, 0.01, -1.0, 1e-4, R, &out),
                   OCEAN_STATUS_INVALID_ARGUMENT, "l_sun");
        EXPECT_MSG(ocean_sun_radiance(v, l, 0.01, 0.01, INFINITY, 1e-4, R, &out),
                   OCEAN_STATUS_NON_FINITE, "l_sun");
        EXPECT(ocean_sun_radiance(v, l, 0.01, 0.01, 1.0, 1e-4, R, NULL),
               OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_linear_to_srgb(NAN, &out), OCEAN_STATUS_NON_FINITE);
        EXPECT(ocean_linear_to_srgb(0.5, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(out == SENTINEL, "an evaluation wrote its output on failure: %g", out);
    }
}

/* ------------------------------------------------------------------------------------------ */
/* Lighting, sky map, sea colour.                                                             */

/* The stereographic plane point of texel (i, j) of a level of side n. */
static void texel_u(int i, int j, int n, double u[2])
{
    u[0] = (2.0 * (i + 0.5) / n - 1.0) * OCEAN_SKY_MAP_EXTENT;
    u[1] = (2.0 * (j + 0.5) / n - 1.0) * OCEAN_SKY_MAP_EXTENT;
}

static OceanDVec3 inverse_stereographic(const double u[2])
{
    double q = u[0] * u[0] + u[1] * u[1];
    OceanDVec3 r;
    r.x = 2.0 * u[0] / (1.0 + q);
    r.y = (1.0 - q) / (1.0 + q);
    r.z = 2.0 * u[1] / (1.0 + q);
    return r;
}

/* Bilinear, clamp-to-edge lookup of an n x n RGBA level at texture coordinates t. */
static void bilinear(const float *texels, int n, double tx, double ty, double out[3])
{
    double x = tx * n - 0.5, y = ty * n - 0.5;
    double x0 = floor(x), y0 = floor(y), fx = x - x0, fy = y - y0;
    int c, di, dj;
    double v[2][2][3];
    for (dj = 0; dj < 2; dj++)
        for (di = 0; di < 2; di++) {
            double fi = x0 + di, fj = y0 + dj;
            int i = (int)(fi < 0 ? 0 : (fi > n - 1 ? n - 1 : fi));
            int j = (int)(fj < 0 ? 0 : (fj > n - 1 ? n - 1 : fj));
            for (c = 0; c < 3; c++)
                v[dj][di][c] = texels[((size_t)j * n + i) * 4 + c];
        }
    for (c = 0; c < 3; c++) {
        double top = v[0][0][c] * (1.0 - fx) + v[0][1][c] * fx;
        double bottom = v[1][0][c] * (1.0 - fx) + v[1][1][c] * fx;
        out[c] = top * (1.0 - fy) + bottom * fy;
    }
}

static double rgb_at(OceanRgb c, int k) { return k == 0 ? c.r : (k == 1 ? c.g : c.b); }

/* Binary16 keeps 11 significant bits: rounding is within 2^-11 relative. */
static const double HALF_REL = 1.0 / 2048.0;

/* Level 0 of a map against the environment radiance, and every mip against its 2x2 means.
 * Returns level 0 (malloc'ed), or NULL. */
static float *check_sky_map(const OceanLighting *lt, const OceanSkyMap *m, uint32_t n)
{
    uint32_t count = 0, level, side = 0, i, j;
    float *prev = NULL, *level0 = NULL;
    OceanRgb below;
    OK(ocean_lighting_below_horizon_radiance(lt, &below));
    OK(ocean_sky_map_level_count(m, &count));
    {
        uint32_t want = 1;
        while ((1u << (want - 1)) < n)
            want++;
        CHECK(count == want, "level count %u, expected log2(%u) + 1 = %u", count, n, want);
    }
    for (level = 0; level < count; level++) {
        size_t len, k;
        float *texels;
        int finite_ok = 1, alpha_ok = 1;
        OK(ocean_sky_map_level_info(m, level, &side));
        CHECK(side == (n >> level), "level %u side %u, expected %u", level, side, n >> level);
        len = (size_t)side * side * 4;
        texels = (float *)malloc(len * sizeof *texels);
        if (!texels)
            abort();
        OK(ocean_sky_map_copy_level(m, level, texels, len));
        for (k = 0; k < len; k++) {
            if (k % 4 == 3)
                alpha_ok &= texels[k] == 1.0f;
            else
                finite_ok &= isfinite(texels[k]) && texels[k] >= 0.0f;
        }
        CHECK(finite_ok, "level %u has a negative or non-finite texel", level);
        CHECK(alpha_ok, "level %u has alpha != 1", level);
        if (level == 0) {
            int bad = 0;
            for (j = 0; j < side; j++)
                for (i = 0; i < side; i++) {
                    double u[2], want;
                    OceanRgb rad;
                    int c;
                    texel_u((int)i, (int)j, (int)side, u);
                    if (u[0] * u[0] + u[1] * u[1] < 1.0) {
                        OK(ocean_lighting_environment_radiance(lt, inverse_stereographic(u),
                                                               &rad));
                    } else {
                        rad = below;
                    }
                    for (c = 0; c < 3; c++) {
                        want = rgb_at(rad, c);
                        if (fabs(texels[((size_t)j * side + i) * 4 + c] - want) >
                            HALF_REL * want + 1e-7)
                            bad++;
                    }
                }
            CHECK(bad == 0, "%d level-0 texels differ from the environment radiance", bad);
            level0 = texels;
        } else {
            int bad = 0;
            uint32_t ps = side * 2;
            for (j = 0; j < side; j++)
                for (i = 0; i < side; i++) {
                    int c;
                    for (c = 0; c < 3; c++) {
                        double mean =
                            0.25 * ((double)prev[((size_t)(2 * j) * ps + 2 * i) * 4 + c] +
                                    prev[((size_t)(2 * j) * ps + 2 * i + 1) * 4 + c] +
                                    prev[((size_t)(2 * j + 1) * ps + 2 * i) * 4 + c] +
                                    prev[((size_t)(2 * j + 1) * ps + 2 * i + 1) * 4 + c]);
                        if (fabs(texels[((size_t)j * side + i) * 4 + c] - mean) >
                            HALF_REL * mean + 1e-7)
                            bad++;
                    }
                }
            CHECK(bad == 0, "%d texels of level %u are not the 2x2 means of level %u", bad, level,
                  level - 1);
        }
        if (prev && prev != level0)
            free(prev);
        prev = texels;
    }
    if (prev && prev != level0)
        free(prev);
    CHECK(side == 1, "the chain must end at 1x1, ends at %u", side);
    return level0;
}

static int same_light(const OceanSeaLight *a, const OceanSeaLight *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

static void test_lighting(void)
{
    OceanSkyParams sky;
    OceanSeaParams sea;
    OceanLighting *lt = NULL, *other = NULL, *uniform = NULL;
    OceanLighting *untouched_l = (OceanLighting *)&sky;
    OceanSkyMap *map = NULL, *other_map = NULL, *untouched_m = (OceanSkyMap *)&sky;
    OceanRgb e_sky, l_sea, below, l_sun, rad;
    double omega, el = 25.0 * PI / 180.0, f_hemi;
    float *level0;
    const uint32_t N = 64;
    int c;

    OK(ocean_sky_params_default(&sky));
    OK(ocean_sea_params_default(&sea));
    NEAR(sky.sun_direction.x, 0.0, 0.0, 0.0, "default Sun x");
    NEAR(sky.sun_direction.y, sin(el), 1e-15, 0.0, "default Sun elevation 25 degrees");
    NEAR(sky.sun_direction.z, -cos(el), 1e-15, 0.0, "default Sun towards -z");
    CHECK(sky.sun_irradiance.r == 1.0 && sky.sun_irradiance.g == 0.96 &&
              sky.sun_irradiance.b == 0.90,
          "default Sun irradiance");
    CHECK(sky.zenith_radiance.r == 0.025 && sky.zenith_radiance.g == 0.045 &&
              sky.zenith_radiance.b == 0.09,
          "default zenith radiance");
    CHECK(sky.cie.a == -1.0 && sky.cie.b == -0.32 && sky.cie.c == 10.0 && sky.cie.d == -3.0 &&
              sky.cie.e == 0.45,
          "default CIE type 12");
    NEAR(sea.albedo.r, 10.0 / 255.0 * 0.1, 1e-15, 0.0, "default albedo r");
    NEAR(sea.albedo.g, 40.0 / 255.0 * 0.1, 1e-15, 0.0, "default albedo g");
    NEAR(sea.albedo.b, 120.0 / 255.0 * 0.1, 1e-15, 0.0, "default albedo b");
    CHECK(sea.fresnel_r == OCEAN_WATER_R, "default R");

    if (!OK(ocean_lighting_create(&sky, &sea, &lt)))
        return;

    /* Derived radiances against their documented formulas. */
    OK(ocean_lighting_sky_irradiance(lt, &e_sky));
    OK(ocean_lighting_sea_radiance(lt, &l_sea));
    OK(ocean_lighting_below_horizon_radiance(lt, &below));
    OK(ocean_lighting_sun_radiance(lt, &l_sun));
    OK(ocean_lighting_sun_solid_angle(lt, &omega));
    NEAR(omega, 2.0 * PI * (1.0 - cos(SUN_RHO)), 1e-12, 0.0, "Sun solid angle");
    f_hemi = sea.fresnel_r + (1.0 - sea.fresnel_r) / 21.0;
    for (c = 0; c < 3; c++) {
        double e_sun = rgb_at(sky.sun_irradiance, c), es = rgb_at(e_sky, c);
        double ls = rgb_at(sea.albedo, c) * (e_sun * sin(el) + es) / PI;
        CHECK(isfinite(es) && es > 0.0, "E_sky channel %d = %g", c, es);
        /* A clear sky, brighter towards the horizon and the Sun than at the zenith, gives
         * between 1 and 10 times a uniform sky's pi L_zenith. */
        CHECK(es > PI * rgb_at(sky.zenith_radiance, c) &&
                  es < 10.0 * PI * rgb_at(sky.zenith_radiance, c),
              "E_sky channel %d = %g implausible", c, es);
        NEAR(rgb_at(l_sea, c), ls, 1e-12, 0.0, "L_sea = albedo (E_sun sin(el) + E_sky)/pi, %d",
             c);
        NEAR(rgb_at(below, c), es / PI * f_hemi + ls * (1.0 - f_hemi), 1e-12, 0.0,
             "below-horizon radiance channel %d", c);
        NEAR(rgb_at(l_sun, c), e_sun / omega, 1e-12, 0.0, "L_sun = E_sun / Omega, %d", c);
    }
    /* The CIE model is normalised to the zenith; below the horizon is the below radiance. */
    {
        OceanDVec3 up = {0.0, 1.0, 0.0}, low = dvec3(1.0, -0.2, 0.3), flat = {0.0, 0.0, 1.0};
        OK(ocean_lighting_environment_radiance(lt, up, &rad));
        for (c = 0; c < 3; c++)
            NEAR(rgb_at(rad, c), rgb_at(sky.zenith_radiance, c), 1e-12, 0.0, "zenith %d", c);
        OK(ocean_lighting_environment_radiance(lt, low, &rad));
        CHECK(memcmp(&rad, &below, sizeof rad) == 0, "below the horizon");
        OK(ocean_lighting_environment_radiance(lt, flat, &rad));
        CHECK(memcmp(&rad, &below, sizeof rad) == 0, "on the horizon");
    }

    /* A uniform sky (CIE coefficients all 0: relative radiance 1 everywhere) has
     * E_sky = pi L exactly, and a sky map equal to L inside the horizon circle. */
    {
        OceanSkyParams u = sky;
        OceanRgb eu;
        memset(&u.cie, 0, sizeof u.cie);
        if (OK(ocean_lighting_create(&u, &sea, &uniform))) {
            OceanSkyMap *um = NULL;
            OK(ocean_lighting_sky_irradiance(uniform, &eu));
            for (c = 0; c < 3; c++)
                NEAR(rgb_at(eu, c), PI * rgb_at(u.zenith_radiance, c), 1e-13, 0.0,
                     "uniform sky E = pi L, channel %d", c);
            /* Its environment is L above the horizon and the sea's L_b below: the order-2
             * irradiance coefficients k_i = A_l * integral of L Y_i are
             * k_0 = pi * C0 * 2 pi (L + L_b), k_y = (2 pi / 3) * C1 * pi (L - L_b) (the integral
             * of y over the upper hemisphere is pi), and the x and z ones 0 by symmetry. */
            {
                OceanIrradiance e;
                OceanRgb lb;
                const double c0 = 0.28209479177387814, c1 = 0.4886025119029199;
                OK(ocean_lighting_below_horizon_radiance(uniform, &lb));
                if (OK(ocean_lighting_irradiance(uniform, &e)))
                    for (c = 0; c < 3; c++) {
                        double l = rgb_at(u.zenith_radiance, c), b = rgb_at(lb, c);
                        NEAR(rgb_at(e.k[0], c), PI * c0 * 2.0 * PI * (l + b), 1e-10, 0.0,
                             "uniform sky k_0, channel %d", c);
                        NEAR(rgb_at(e.k[2], c), 2.0 * PI / 3.0 * c1 * PI * (l - b), 1e-10, 0.0,
                             "uniform sky k_y, channel %d", c);
                        NEAR(rgb_at(e.k[1], c), 0.0, 0.0, 1e-12 * l, "k_x %d", c);
                        NEAR(rgb_at(e.k[3], c), 0.0, 0.0, 1e-12 * l, "k_z %d", c);
                    }
                EXPECT(ocean_lighting_irradiance(NULL, &e), OCEAN_STATUS_NULL_POINTER);
                EXPECT(ocean_lighting_irradiance(uniform, NULL), OCEAN_STATUS_NULL_POINTER);
            }
            if (OK(ocean_lighting_sky_map_create(uniform, 8, &um))) {
                float t[8 * 8 * 4];
                int i, j, bad = 0;
                OK(ocean_sky_map_copy_level(um, 0, t, 8 * 8 * 4));
                for (j = 0; j < 8; j++)
                    for (i = 0; i < 8; i++) {
                        double uu[2];
                        texel_u(i, j, 8, uu);
                        if (uu[0] * uu[0] + uu[1] * uu[1] >= 1.0)
                            continue;
                        for (c = 0; c < 3; c++)
                            if (fabs(t[(j * 8 + i) * 4 + c] - rgb_at(u.zenith_radiance, c)) >
                                HALF_REL * rgb_at(u.zenith_radiance, c))
                                bad++;
                    }
                CHECK(bad == 0, "uniform sky map: %d texels differ from L", bad);
                ocean_sky_map_destroy(um);
            }
        }
    }

    /* The sky map. */
    if (!OK(ocean_lighting_sky_map_create(lt, N, &map))) {
        ocean_lighting_destroy(lt);
        return;
    }
    level0 = check_sky_map(lt, map, N);
    {
        OceanSkyMap *small = NULL;
        if (OK(ocean_lighting_sky_map_create(lt, OCEAN_SKY_MAP_MIN_SIZE, &small))) {
            float *l0 = check_sky_map(lt, small, OCEAN_SKY_MAP_MIN_SIZE);
            free(l0);
            ocean_sky_map_destroy(small);
        }
    }

    /* The sea colour. Calm sea (sigma = 0, n = up), seen from 60 degrees elevation with the Sun
     * behind the viewer: no glint, F_bar = Schlick(sin 60deg), the sky term F_bar times the map
     * read bilinearly at the mirror direction, the sea term L_sea (1 - F_bar). */
    {
        const double R = sea.fresnel_r;
        OceanDVec3 up = {0.0, 1.0, 0.0};
        OceanDVec3 v = {0.0, sin(PI / 3.0), -cos(PI / 3.0)};
        OceanDVec2 wind = {1.0, 0.0};
        OceanSeaLight calm, glint, rough, flipped, back;
        double f = schlick_ref(v.y, R), u[2], lb[3];
        OceanDVec3 r = {-v.x, v.y, -v.z}; /* 2 (n.v) n - v */

        if (OK(ocean_sea_color(lt, map, v, up, wind, 0.0, 0.0, &calm))) {
            u[0] = r.x / (1.0 + r.y);
            u[1] = r.z / (1.0 + r.y);
            bilinear(level0, (int)N, u[0] / (2.0 * OCEAN_SKY_MAP_EXTENT) + 0.5,
                     u[1] / (2.0 * OCEAN_SKY_MAP_EXTENT) + 0.5, lb);
            OK(ocean_lighting_environment_radiance(lt, r, &rad));
            for (c = 0; c < 3; c++) {
                double ls = rgb_at(sea.albedo, c) *
                            (rgb_at(sky.sun_irradiance, c) * sin(el) + rgb_at(e_sky, c)) / PI;
                CHECK(rgb_at(calm.sun, c) == 0.0, "calm sea away from the Sun: glint %g",
                      rgb_at(calm.sun, c));
                NEAR(rgb_at(calm.sea, c), ls * (1.0 - f), 1e-12, 0.0,
                     "calm sea term = L_sea (1 - F), channel %d", c);
                NEAR(rgb_at(calm.sky, c), f * lb[c], 1e-12, 0.0,
                     "calm sky term = F x bilinear(map, mirror), channel %d", c);
                /* ... which is the sky's radiance there up to binary16 and interpolation. */
                NEAR(rgb_at(calm.sky, c), f * rgb_at(rad, c), 0.03, 0.0,
                     "calm sky term vs the sky's radiance, channel %d", c);
            }
        }

        /* The Sun's glint: v the Sun's mirror direction over a calm sea. With the variances
         * raised to the solar disc's, rho^2/16, the half vector is n, zeta_h = 0, Lambda = 0:
         * I_sun = L_sun Omega p(0) F(v.h) / (4 cos theta_v) with p(0) = 1 / (2 pi sigma^2). */
        {
            OceanDVec3 mirror = {-sky.sun_direction.x, sky.sun_direction.y,
                                 -sky.sun_direction.z};
            double s2 = SUN_RHO * SUN_RHO / 16.0;
            double fs = schlick_ref(mirror.y, R);
            if (OK(ocean_sea_color(lt, map, mirror, up, wind, 0.0, 0.0, &glint)))
                for (c = 0; c < 3; c++)
                    NEAR(rgb_at(glint.sun, c),
                         rgb_at(l_sun, c) * omega * fs / (2.0 * PI * s2) / (4.0 * mirror.y), 1e-9,
                         0.0, "Sun glint channel %d", c);
        }

        /* A rough, tilted case: every term finite and non-negative. */
        {
            OceanDVec3 vr = dvec3(0.4, 0.5, -0.7), nr = dvec3(0.1, 0.98, 0.15);
            OceanDVec3 nb = dvec3(0.2, -0.3, 0.93); /* faces away from vr */
            OceanDVec2 wr = {1.0, 0.5};
            if (OK(ocean_sea_color(lt, map, vr, nr, wr, 0.02, 0.01, &rough))) {
                for (c = 0; c < 3; c++) {
                    CHECK(isfinite(rgb_at(rough.sun, c)) && rgb_at(rough.sun, c) >= 0,
                          "rough sun %d", c);
                    CHECK(isfinite(rgb_at(rough.sky, c)) && rgb_at(rough.sky, c) > 0,
                          "rough sky %d", c);
                    CHECK(isfinite(rgb_at(rough.sea, c)) && rgb_at(rough.sea, c) > 0,
                          "rough sea %d", c);
                    CHECK(rgb_at(rough.sea, c) <= rgb_at(l_sea, c) * (1.0 - R) * (1 + 1e-12),
                          "sea term above L_sea (1 - R)");
                }
            }
            /* A normal facing away from v is reflected about the plane normal to v
             * (section 3.2): n' = n - 2 (n.v) v gives the same light. */
            {
                double nv = dot3(nb, vr);
                OceanDVec3 nf = {nb.x - 2 * nv * vr.x, nb.y - 2 * nv * vr.y,
                                 nb.z - 2 * nv * vr.z};
                CHECK(nv < 0.0, "test normal must face away");
                OK(ocean_sea_color(lt, map, vr, nb, wr, 0.02, 0.01, &back));
                OK(ocean_sea_color(lt, map, vr, nf, wr, 0.02, 0.01, &flipped));
                for (c = 0; c < 3; c++) {
                    NEAR(rgb_at(back.sky, c), rgb_at(flipped.sky, c), 1e-9, 1e-15,
                         "back-facing normal, sky %d", c);
                    NEAR(rgb_at(back.sea, c), rgb_at(flipped.sea, c), 1e-9, 1e-15,
                         "back-facing normal, sea %d", c);
                }
            }

            /* The batch equals the single calls bit for bit. */
            {
                OceanSeaColorInput in[4];
                OceanSeaLight outs[4];
                memset(in, 0, sizeof in);
                in[0].v = v;
                in[0].n = up;
                in[0].wind = wind;
                in[1].v.x = -sky.sun_direction.x;
                in[1].v.y = sky.sun_direction.y;
                in[1].v.z = -sky.sun_direction.z;
                in[1].n = up;
                in[1].wind = wind;
                in[2].v = vr;
                in[2].n = nr;
                in[2].wind = wr;
                in[2].sigma_x2 = 0.02;
                in[2].sigma_y2 = 0.01;
                in[3] = in[2];
                in[3].n = nb;
                if (OK(ocean_sea_color_batch(lt, map, in, 4, outs))) {
                    CHECK(same_light(&outs[0], &calm), "batch[0] != single");
                    CHECK(same_light(&outs[1], &glint), "batch[1] != single");
                    CHECK(same_light(&outs[2], &rough), "batch[2] != single");
                    CHECK(same_light(&outs[3], &back), "batch[3] != single");
                }

                /* Batch errors: nothing written. */
                {
                    OceanSeaLight keep[4];
                    OceanSeaColorInput bad[4];
                    memset(keep, 0x5a, sizeof keep);
                    memcpy(outs, keep, sizeof outs);
                    memcpy(bad, in, sizeof bad);
                    bad[2].sigma_y2 = NAN;
                    EXPECT_MSG(ocean_sea_color_batch(lt, map, bad, 4, outs),
                               OCEAN_STATUS_NON_FINITE, "inputs[2].sigma_y2");
                    memcpy(bad, in, sizeof bad);
                    bad[3].n.y = 5.0;
                    EXPECT_MSG(ocean_sea_color_batch(lt, map, bad, 4, outs),
                               OCEAN_STATUS_INVALID_ARGUMENT, "inputs[3].n");
                    memcpy(bad, in, sizeof bad);
                    bad[1].wind.x = 0.0;
                    bad[1].wind.z = 0.0;
                    EXPECT_MSG(ocean_sea_color_batch(lt, map, bad, 4, outs),
                               OCEAN_STATUS_INVALID_ARGUMENT, "inputs[1]");
                    memcpy(bad, in, sizeof bad);
                    bad[0].sigma_x2 = -1.0;
                    EXPECT_MSG(ocean_sea_color_batch(lt, map, bad, 4, outs),
                               OCEAN_STATUS_INVALID_ARGUMENT, "inputs[0].sigma_x2");
                    EXPECT(ocean_sea_color_batch(lt, map, in, 0, outs), OCEAN_STATUS_EMPTY);
                    EXPECT(ocean_sea_color_batch(lt, map, NULL, 4, outs),
                           OCEAN_STATUS_NULL_POINTER);
                    EXPECT(ocean_sea_color_batch(lt, map, in, 4, NULL),
                           OCEAN_STATUS_NULL_POINTER);
                    EXPECT(ocean_sea_color_batch(NULL, map, in, 4, outs),
                           OCEAN_STATUS_NULL_POINTER);
                    EXPECT(ocean_sea_color_batch(lt, NULL, in, 4, outs),
                           OCEAN_STATUS_NULL_POINTER);
                    EXPECT(ocean_sea_color_batch(lt, map, in, SIZE_MAX / 8, outs),
                           OCEAN_STATUS_LENGTH_OVERFLOW);
                    CHECK(memcmp(outs, keep, sizeof outs) == 0,
                          "a failed batch wrote its output");
                    /* Overlapping input and output: refused before anything is read. */
                    EXPECT_MSG(ocean_sea_color_batch(lt, map, in, 4, (OceanSeaLight *)(void *)in),
                               OCEAN_STATUS_INVALID_ARGUMENT, "overlap");
                }
            }
        }

        /* Single-call errors: nothing written. */
        {
            OceanSeaLight keep, o;
            OceanDVec3 nan_v = {NAN, 0.5, 0.5}, long_n = {0.0, 1.01, 0.0};
            OceanDVec2 zero = {0.0, 0.0}, nan_w = {NAN, 1.0};
            OceanSeaParams sea2 = sea;
            memset(&keep, 0x5a, sizeof keep);
            o = keep;
            EXPECT_MSG(ocean_sea_color(lt, map, nan_v, up, wind, 0, 0, &o),
                       OCEAN_STATUS_NON_FINITE, "v.x");
            EXPECT_MSG(ocean_sea_color(lt, map, v, long_n, wind, 0, 0, &o),
                       OCEAN_STATUS_INVALID_ARGUMENT, "n");
            EXPECT_MSG(ocean_sea_color(lt, map, v, up, zero, 0, 0, &o),
                       OCEAN_STATUS_INVALID_ARGUMENT, "wind");
            EXPECT_MSG(ocean_sea_color(lt, map, v, up, nan_w, 0, 0, &o), OCEAN_STATUS_NON_FINITE,
                       "wind.x");
            EXPECT_MSG(ocean_sea_color(lt, map, v, up, wind, -0.1, 0, &o),
                       OCEAN_STATUS_INVALID_ARGUMENT, "sigma_x2");
            EXPECT_MSG(ocean_sea_color(lt, map, v, up, wind, 0, INFINITY, &o),
                       OCEAN_STATUS_NON_FINITE, "sigma_y2");
            EXPECT(ocean_sea_color(NULL, map, v, up, wind, 0, 0, &o), OCEAN_STATUS_NULL_POINTER);
            EXPECT(ocean_sea_color(lt, NULL, v, up, wind, 0, 0, &o), OCEAN_STATUS_NULL_POINTER);
            EXPECT(ocean_sea_color(lt, map, v, up, wind, 0, 0, NULL), OCEAN_STATUS_NULL_POINTER);
            /* A map of another lighting is refused. */
            sea2.albedo.g = 0.5;
            if (OK(ocean_lighting_create(&sky, &sea2, &other)) &&
                OK(ocean_lighting_sky_map_create(other, 4, &other_map))) {
                EXPECT_MSG(ocean_sea_color(lt, other_map, v, up, wind, 0, 0, &o),
                           OCEAN_STATUS_INVALID_ARGUMENT, "another lighting");
                OK(ocean_sea_color(other, other_map, v, up, wind, 0, 0, &o));
                o = keep;
            }
            CHECK(same_light(&o, &keep), "a failed ocean_sea_color wrote its output");
        }
    }

    /* Lighting and sky-map errors: outputs untouched. */
    {
        OceanSkyParams bs = sky;
        OceanSeaParams bsea = sea;
        uint32_t u32 = 777;
        float buf[16 * 4 + 1];
        unsigned char pattern[sizeof buf];
        size_t k;
        OceanDVec3 nan_d = {NAN, 1.0, 0.0}, long_d = {0.0, 1.1, 0.0};

        EXPECT(ocean_sky_params_default(NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_sea_params_default(NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_lighting_create(NULL, &sea, &untouched_l), OCEAN_STATUS_NULL_POINTER,
                   "sky");
        EXPECT_MSG(ocean_lighting_create(&sky, NULL, &untouched_l), OCEAN_STATUS_NULL_POINTER,
                   "sea");
        EXPECT(ocean_lighting_create(&sky, &sea, NULL), OCEAN_STATUS_NULL_POINTER);
        bs.sun_direction.y = 2.0;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_INVALID_ARGUMENT,
                   "sun_direction");
        bs = sky;
        bs.sun_direction = dvec3(0.0, -0.3, -1.0);
        EXPECT(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_INVALID_ARGUMENT);
        bs = sky;
        bs.sun_direction.z = NAN;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_NON_FINITE,
                   "sky->sun_direction.z");
        bs = sky;
        bs.sun_irradiance.g = NAN;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_NON_FINITE,
                   "sky->sun_irradiance.g");
        bs = sky;
        bs.zenith_radiance.b = -0.1;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_INVALID_ARGUMENT,
                   "zenith_radiance");
        bs = sky;
        bs.cie.a = 2000.0;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_INVALID_ARGUMENT,
                   "cie.a");
        bs = sky;
        bs.cie.e = INFINITY;
        EXPECT_MSG(ocean_lighting_create(&bs, &sea, &untouched_l), OCEAN_STATUS_NON_FINITE,
                   "sky->cie.e");
        bsea.albedo.r = 1.5;
        EXPECT_MSG(ocean_lighting_create(&sky, &bsea, &untouched_l),
                   OCEAN_STATUS_INVALID_ARGUMENT, "albedo");
        bsea = sea;
        bsea.fresnel_r = -0.1;
        EXPECT_MSG(ocean_lighting_create(&sky, &bsea, &untouched_l),
                   OCEAN_STATUS_INVALID_ARGUMENT, "fresnel_r");
        bsea = sea;
        bsea.fresnel_r = NAN;
        EXPECT_MSG(ocean_lighting_create(&sky, &bsea, &untouched_l), OCEAN_STATUS_NON_FINITE,
                   "sea->fresnel_r");
        CHECK(untouched_l == (OceanLighting *)&sky, "a failed lighting create wrote *out");

        rad.r = SENTINEL;
        EXPECT(ocean_lighting_sky_irradiance(NULL, &rad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_sky_irradiance(lt, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_sea_radiance(NULL, &rad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_below_horizon_radiance(NULL, &rad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_sun_radiance(NULL, &rad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_sun_solid_angle(NULL, &omega), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_lighting_environment_radiance(lt, nan_d, &rad), OCEAN_STATUS_NON_FINITE,
                   "dir.x");
        EXPECT_MSG(ocean_lighting_environment_radiance(lt, long_d, &rad),
                   OCEAN_STATUS_INVALID_ARGUMENT, "unit");
        EXPECT(ocean_lighting_environment_radiance(lt, long_d, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(rad.r == SENTINEL, "a radiance was written on failure");

        EXPECT_MSG(ocean_lighting_sky_map_create(lt, 100, &untouched_m),
                   OCEAN_STATUS_INVALID_ARGUMENT, "power of two");
        EXPECT(ocean_lighting_sky_map_create(lt, 0, &untouched_m), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_lighting_sky_map_create(lt, 2, &untouched_m), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_lighting_sky_map_create(lt, 2 * OCEAN_SKY_MAP_MAX_SIZE, &untouched_m),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_lighting_sky_map_create(NULL, 8, &untouched_m), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_lighting_sky_map_create(lt, 8, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(untouched_m == (OceanSkyMap *)&sky, "a failed sky map create wrote *out");

        EXPECT(ocean_sky_map_level_count(NULL, &u32), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_sky_map_level_count(map, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT_MSG(ocean_sky_map_level_info(map, 7, &u32), OCEAN_STATUS_INVALID_ARGUMENT,
                   "level 7");
        EXPECT(ocean_sky_map_level_info(map, UINT32_MAX, &u32), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_sky_map_level_info(NULL, 0, &u32), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_sky_map_level_info(map, 0, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(u32 == 777, "a level size was written on failure");

        /* Level 4 of the 64^2 map is 4 x 4: exactly 64 floats. */
        for (k = 0; k < sizeof buf / sizeof buf[0]; k++)
            buf[k] = -7.0f;
        memcpy(pattern, buf, sizeof buf);
        EXPECT_MSG(ocean_sky_map_copy_level(map, 4, buf, 65), OCEAN_STATUS_LENGTH_MISMATCH,
                   "64");
        EXPECT(ocean_sky_map_copy_level(map, 4, buf, 63), OCEAN_STATUS_LENGTH_MISMATCH);
        EXPECT(ocean_sky_map_copy_level(map, 4, buf, 16), OCEAN_STATUS_LENGTH_MISMATCH);
        EXPECT(ocean_sky_map_copy_level(map, 4, buf, 0), OCEAN_STATUS_LENGTH_MISMATCH);
        EXPECT(ocean_sky_map_copy_level(map, 99, buf, 64), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_sky_map_copy_level(map, 4, NULL, 64), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_sky_map_copy_level(NULL, 4, buf, 64), OCEAN_STATUS_NULL_POINTER);
        CHECK(memcmp(buf, pattern, sizeof buf) == 0, "a failed level copy wrote the buffer");
        OK(ocean_sky_map_copy_level(map, 4, buf, 64));
        CHECK(buf[64] == -7.0f, "the copy wrote past len");
    }

    free(level0);
    ocean_sky_map_destroy(other_map);
    ocean_sky_map_destroy(map);
    ocean_sky_map_destroy(NULL);
    ocean_lighting_destroy(other);
    ocean_lighting_destroy(uniform);
    ocean_lighting_destroy(lt);
    ocean_lighting_destroy(NULL);
}

int main(void)
{
    test_spectrum();
    test_pixel_footprint();
    test_evaluations();
    test_lighting();
    printf("test_lighting.c: library %s, %d checks, %d failures; spectrum, footprints, Ross BRDF, "
           "Fresnel, sky map and sea colour against their formulas\n",
           ocean_version(), checks, failures);
    return failures == 0 ? 0 : 1;
}
