/*
 * C11 test of the ocean C ABI (include/ocean.h), linked against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_waves.c libocean.a ...
 *
 * It computes the expected surface itself, in double precision, from the closed form of the
 * trochoid sum (Yrjola & Larsson Eq. 6-7) with its own dispersion relation (Eq. 4 and 5), and
 * takes normals from central differences of that closed form, so neither the library's analytic
 * derivatives nor its f32 kernel are trusted. Then it drives every error path.
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

/*
 * Tolerances, from f32 rounding. The library forms each phase in double, reduces it to
 * [-pi, pi] and rounds it to float (error <= 2^-24 * pi = 1.9e-7 rad), evaluates sin/cos and the
 * sums in float (each of the N = 4 waves adds a few float roundings of terms <= A = 0.8 m, i.e.
 * ~1e-7 m each) and finally adds the rest position (|x| <= 256 m: half an ulp is 2^-24 * 256 / 2
 * = 7.6e-6 m). The worst case is therefore ~1e-5 m; 1e-4 m leaves a 10x margin and is still
 * 1/8000 of the smallest amplitude's displacement scale (a wrong phase, sign, axis or dispersion
 * gives errors of centimetres to metres).
 */
static const double POS_TOL = 1e-4; /* metres */
/*
 * Normals come from float sums of N terms A k cos/sin (each <= 0.23, float rounding ~3e-8 each)
 * in a Jacobian with entries near 1, then a float normalisation (a few ulps, 2^-24 = 6e-8 each):
 * worst case ~1e-6 per component. 1e-5 leaves a 10x margin; the central-difference reference
 * (h = 1e-3 m) is exact to ~1e-8 here.
 */
static const double NRM_TOL = 1e-5;

#include "check.h"

/* ------------------------------------------------------------------------------------------ */
/* Reference: the closed form, in double.                                                     */

static double angular_frequency(const OceanWaveDesc *w)
{
    double k = 2.0 * PI / w->wavelength;
    /* Eq. 5 (deep water, depth = INFINITY) or Eq. 4 (finite depth). */
    return isinf(w->depth) ? sqrt(G * k) : sqrt(G * k * tanh(k * w->depth));
}

/* Displaced point of rest position (x0, 0, z0) at time t (Eq. 6-7). */
static void surface(const OceanWaveDesc *waves, size_t nw, double x0, double z0, double t,
                    double p[3])
{
    size_t i;
    p[0] = x0;
    p[1] = 0.0;
    p[2] = z0;
    for (i = 0; i < nw; i++) {
        const OceanWaveDesc *w = &waves[i];
        double len = sqrt(w->direction_x * w->direction_x + w->direction_z * w->direction_z);
        double hx = w->direction_x / len, hz = w->direction_z / len;
        double k = 2.0 * PI / w->wavelength;
        double theta = k * (hx * x0 + hz * z0) - angular_frequency(w) * t + w->phase;
        p[0] -= hx * w->amplitude * sin(theta);
        p[1] += w->amplitude * cos(theta);
        p[2] -= hz * w->amplitude * sin(theta);
    }
}

/* Unit normal: normalize(dp/dz x dp/dx) (y up), by central differences of surface(). */
static void normal(const OceanWaveDesc *waves, size_t nw, double x0, double z0, double t,
                   double n[3])
{
    const double h = 1e-3;
    double a[3], b[3], dx[3], dz[3], len;
    int i;
    surface(waves, nw, x0 + h, z0, t, a);
    surface(waves, nw, x0 - h, z0, t, b);
    for (i = 0; i < 3; i++)
        dx[i] = (a[i] - b[i]) / (2.0 * h);
    surface(waves, nw, x0, z0 + h, t, a);
    surface(waves, nw, x0, z0 - h, t, b);
    for (i = 0; i < 3; i++)
        dz[i] = (a[i] - b[i]) / (2.0 * h);
    n[0] = dz[1] * dx[2] - dz[2] * dx[1];
    n[1] = dz[2] * dx[0] - dz[0] * dx[2];
    n[2] = dz[0] * dx[1] - dz[1] * dx[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (i = 0; i < 3; i++)
        n[i] /= len;
}

/* ------------------------------------------------------------------------------------------ */

/* Four waves: deep and finite depth (kD from 0.47 to 1.3, where tanh matters), every quadrant of
 * direction, unnormalised directions, non-zero phases. Steepness sum 0.652 < 1. */
static const OceanWaveDesc WAVES[4] = {
    {0.8, 24.0, 1.0, 0.3, 0.4, INFINITY},
    {0.35, 9.5, -0.2, 1.0, -1.1, 2.0},
    {0.12, 3.7, 0.7, -0.7, 2.5, INFINITY},
    {0.05, 40.0, -1.0, -0.4, 0.0, 3.0},
};
#define NWAVES (sizeof WAVES / sizeof WAVES[0])

static double max_pos_err = 0.0, max_nrm_err = 0.0;

static void compare(const double p[3], const OceanVec3 *nrm, const double ep[3],
                    const double en[3], const char *what, size_t index)
{
    double dp = fmax(fabs(p[0] - ep[0]), fmax(fabs(p[1] - ep[1]), fabs(p[2] - ep[2])));
    double dn = fmax(fabs(nrm->x - en[0]), fmax(fabs(nrm->y - en[1]), fabs(nrm->z - en[2])));
    double len = sqrt((double)nrm->x * nrm->x + (double)nrm->y * nrm->y +
                      (double)nrm->z * nrm->z);
    max_pos_err = fmax(max_pos_err, dp);
    max_nrm_err = fmax(max_nrm_err, dn);
    CHECK(dp <= POS_TOL, "%s[%zu]: position (%.7f, %.7f, %.7f), expected (%.7f, %.7f, %.7f)",
          what, index, p[0], p[1], p[2], ep[0], ep[1], ep[2]);
    CHECK(dn <= NRM_TOL, "%s[%zu]: normal (%.7f, %.7f, %.7f), expected (%.7f, %.7f, %.7f)", what,
          index, nrm->x, nrm->y, nrm->z, en[0], en[1], en[2]);
    /* A float unit vector normalised in float is within a few ulps of length 1. */
    CHECK(fabs(len - 1.0) <= 1e-6, "%s[%zu]: |normal| = %.9f", what, index, len);
}


static void test_version_and_messages(void)
{
    char expected[64];
    uint32_t s;
    snprintf(expected, sizeof expected, "%d.%d.%d", OCEAN_VERSION_MAJOR, OCEAN_VERSION_MINOR,
             OCEAN_VERSION_PATCH);
    CHECK(ocean_version() != NULL && strcmp(ocean_version(), expected) == 0,
          "ocean_version() = %s, header macros say %s", ocean_version(), expected);

    /* Every code has its own non-empty text; unknown codes are safe and say so. */
    for (s = OCEAN_STATUS_OK; s <= OCEAN_STATUS_VERSION_MISMATCH; s++) {
        uint32_t t;
        const char *m = ocean_status_message(s);
        CHECK(m != NULL && m[0] != '\0', "status %u has no message", (unsigned)s);
        CHECK(strcmp(m, "unknown status") != 0, "status %u is unknown", (unsigned)s);
        for (t = 0; t < s; t++)
            CHECK(strcmp(m, ocean_status_message(t)) != 0, "statuses %u and %u share \"%s\"",
                  (unsigned)s, (unsigned)t, m);
    }
    /* OCEAN_STATUS_VERSION_MISMATCH is the last code: the next value is unknown. */
    CHECK(strcmp(ocean_status_message(OCEAN_STATUS_VERSION_MISMATCH + 1), "unknown status") == 0,
          "status %u: %s", (unsigned)OCEAN_STATUS_VERSION_MISMATCH + 1,
          ocean_status_message(OCEAN_STATUS_VERSION_MISMATCH + 1));
    CHECK(strcmp(ocean_status_message(UINT32_MAX), "unknown status") == 0, "status max: %s",
          ocean_status_message(UINT32_MAX));
    CHECK(OCEAN_STATUS_OK == 0, "OCEAN_STATUS_OK must be 0");
}

static void test_queries(const OceanWaves *w)
{
    size_t count = 0;
    double steep = -1.0, amp = -1.0, want_steep = 0.0, want_amp = 0.0;
    size_t i;
    for (i = 0; i < NWAVES; i++) {
        want_steep += 2.0 * PI / WAVES[i].wavelength * WAVES[i].amplitude;
        want_amp += WAVES[i].amplitude;
    }
    CHECK(ocean_waves_count(w, &count) == OCEAN_STATUS_OK && count == NWAVES, "count = %zu",
          count);
    CHECK(strcmp(last_error(), "") == 0, "success must clear the last error, got \"%s\"",
          last_error());
    /* Same double formula, summed in the same order: equal to rounding (1e-12). */
    CHECK(ocean_waves_steepness_sum(w, &steep) == OCEAN_STATUS_OK &&
              fabs(steep - want_steep) <= 1e-12,
          "steepness sum %.15f, expected %.15f", steep, want_steep);
    CHECK(ocean_waves_max_amplitude(w, &amp) == OCEAN_STATUS_OK && fabs(amp - 1.32) <= 1e-12,
          "max amplitude %.15f, expected 0.8 + 0.35 + 0.12 + 0.05 = 1.32", amp);
    CHECK(fabs(want_amp - 1.32) <= 1e-12, "reference amplitude sum %.15f", want_amp);
}

/* Rest points, world x and z in double precision, up to 250 m from the origin; test_points
 * also moves them 100 km away. */
static const OceanDVec2 POINTS[] = {
    {0.0, 0.0},      {3.25, -17.5},   {123.375, 45.125}, {-250.5, 77.75},  {0.5, 200.25},
    {-9.0, -9.0},    {17.125, 0.0625}, {64.0, -128.0},   {-3.75, 5.5},     {11.0, 13.0},
    {-100.0, -100.0}, {1.0, 2.0},     {42.5, -0.25},     {-0.125, 33.0},   {7.75, 7.75},
    {250.0, 250.0},  {-60.1, 180.53},
};
#define NPOINTS (sizeof POINTS / sizeof POINTS[0])

static void test_points(const OceanWaves *w)
{
    /* t = 1e6 s: phases of ~2.5e6 rad, which lose whole radians if not reduced in double. */
    const double times[] = {0.0, 1.75, -3.5, 1.0e6 + 0.25};
    /* Positions cross the ABI in double precision: 100 km from the origin (where a float
     * resolves only 7.8 mm) the same 1e-4 m tolerance holds. */
    const double offsets[][2] = {{0.0, 0.0}, {100000.0, -50000.0}};
    OceanDVec2 xz[NPOINTS];
    OceanDVec3 pos[NPOINTS];
    OceanVec3 nrm[NPOINTS];
    size_t ti, i, oi;
    for (oi = 0; oi < 2; oi++) {
        for (i = 0; i < NPOINTS; i++) {
            xz[i].x = POINTS[i].x + offsets[oi][0];
            xz[i].z = POINTS[i].z + offsets[oi][1];
        }
        for (ti = 0; ti < sizeof times / sizeof times[0]; ti++) {
            double t = times[ti];
            OceanStatus s = ocean_waves_evaluate(w, xz, NPOINTS, t, pos, nrm);
            CHECK(s == OCEAN_STATUS_OK, "evaluate at t = %g: status %u: %s", t, (unsigned)s,
                  last_error());
            if (s != OCEAN_STATUS_OK)
                continue;
            for (i = 0; i < NPOINTS; i++) {
                double ep[3], en[3];
                const double got[3] = {pos[i].x, pos[i].y, pos[i].z};
                surface(WAVES, NWAVES, xz[i].x, xz[i].z, t, ep);
                normal(WAVES, NWAVES, xz[i].x, xz[i].z, t, en);
                compare(got, &nrm[i], ep, en, "points", i);
                /* The steepness sum is < 1, so the surface never folds: normals point up. */
                CHECK(nrm[i].y > 0.0f, "normal %zu points down", i);
            }
        }
    }
}

static void test_single_wave_closed_form(void)
{
    /* One deep-water wave along +x, A = 1 m, lambda = 2*pi*4 m (k = 0.25, steepness 0.25),
     * omega = sqrt(9.81 * 0.25) = 1.5660 rad/s. At x0 = 0, t = 0, phase 0: theta = 0, so the
     * point sits on a crest: p = (0 - sin 0, cos 0, 0) = (0, 1, 0), normal exactly +y. At
     * theta = -pi/2 (t = pi/2 / omega) p = (0 + 1, 0, 0): moved 1 m forward, at rest height. */
    OceanWaveDesc d = {1.0, 2.0 * PI * 4.0, 2.0, 0.0, 0.0, INFINITY};
    OceanWaves *w = NULL;
    OceanDVec2 x0 = {0.0, 0.0};
    OceanDVec3 p;
    OceanVec3 n;
    double omega = sqrt(9.81 * 0.25);
    CHECK(ocean_waves_create(&d, 1, &w) == OCEAN_STATUS_OK && w != NULL, "create: %s",
          last_error());
    if (!w)
        return;
    CHECK(ocean_waves_evaluate(w, &x0, 1, 0.0, &p, &n) == OCEAN_STATUS_OK, "%s", last_error());
    CHECK(fabs(p.x) <= POS_TOL && fabs(p.y - 1.0) <= POS_TOL && fabs(p.z) <= POS_TOL,
          "crest at (%f, %f, %f), expected (0, 1, 0)", p.x, p.y, p.z);
    CHECK(fabs(n.x) <= NRM_TOL && fabs(n.y - 1.0) <= NRM_TOL && fabs(n.z) <= NRM_TOL,
          "crest normal (%f, %f, %f), expected (0, 1, 0)", n.x, n.y, n.z);
    CHECK(ocean_waves_evaluate(w, &x0, 1, (PI / 2.0) / omega, &p, &n) == OCEAN_STATUS_OK, "%s",
          last_error());
    CHECK(fabs(p.x - 1.0) <= POS_TOL && fabs(p.y) <= POS_TOL && fabs(p.z) <= POS_TOL,
          "quarter period: (%f, %f, %f), expected (1, 0, 0)", p.x, p.y, p.z);
    /* There dp/dx = (1 - kA cos, -kA sin, 0) = (1, 0.25, 0): the normal is (-0.25, 1, 0)/|..|. */
    CHECK(fabs(n.x + 0.25 / sqrt(1.0625)) <= NRM_TOL && fabs(n.y - 1.0 / sqrt(1.0625)) <= NRM_TOL,
          "quarter period normal (%f, %f, %f), expected (-0.2425, 0.9701, 0)", n.x, n.y, n.z);
    ocean_waves_destroy(w);
}

static void test_grid(const OceanWaves *w)
{
    /* 100 km from the origin: world-space floats would resolve only ~8 mm there, but grid
     * positions are relative to the double origin, so the same 1e-4 m tolerance holds.
     * nx = 37 is not a multiple of the kernel's 8 lanes, so the ragged tail is covered. */
    OceanGrid g = {100000.0, -50000.0, 0.75, 1.25, 37, 5};
    const double t = 3.5;
    OceanVec3 pos[37 * 5], nrm[37 * 5];
    size_t i, j;
    OceanStatus s = ocean_waves_evaluate_grid(w, &g, t, pos, nrm);
    CHECK(s == OCEAN_STATUS_OK, "grid: status %u: %s", (unsigned)s, last_error());
    if (s != OCEAN_STATUS_OK)
        return;
    for (j = 0; j < g.nz; j++) {
        for (i = 0; i < g.nx; i++) {
            double x0 = g.origin_x + (double)i * g.spacing_x;
            double z0 = g.origin_z + (double)j * g.spacing_z;
            double ep[3], en[3];
            size_t idx = j * g.nx + i; /* row-major */
            surface(WAVES, NWAVES, x0, z0, t, ep);
            normal(WAVES, NWAVES, x0, z0, t, en);
            ep[0] -= g.origin_x; /* relative to the grid origin */
            ep[2] -= g.origin_z;
            const double got[3] = {pos[idx].x, pos[idx].y, pos[idx].z};
            compare(got, &nrm[idx], ep, en, "grid", idx);
        }
    }
}

/* ------------------------------------------------------------------------------------------ */
/* Error paths: status, message, and untouched outputs.                                       */


#define SENTINEL (-7777.0f)

static void fill(OceanVec3 *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        v[i].x = v[i].y = v[i].z = SENTINEL;
}

static int untouched(const OceanVec3 *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (v[i].x != SENTINEL || v[i].y != SENTINEL || v[i].z != SENTINEL)
            return 0;
    return 1;
}

static void fill_d(OceanDVec3 *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        v[i].x = v[i].y = v[i].z = SENTINEL;
}

static int untouched_d(const OceanDVec3 *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (v[i].x != SENTINEL || v[i].y != SENTINEL || v[i].z != SENTINEL)
            return 0;
    return 1;
}

static void test_create_errors(OceanWaves *valid)
{
    struct {
        const char *what;
        OceanWaveDesc d;
        OceanStatus want;
    } cases[] = {
        {"NaN amplitude", {NAN, 10.0, 1.0, 0.0, 0.0, INFINITY}, OCEAN_STATUS_NON_FINITE},
        {"infinite amplitude", {INFINITY, 10.0, 1.0, 0.0, 0.0, INFINITY},
         OCEAN_STATUS_NON_FINITE},
        {"negative amplitude", {-0.1, 10.0, 1.0, 0.0, 0.0, INFINITY},
         OCEAN_STATUS_INVALID_ARGUMENT},
        /* k*A = 2*pi/10 * 1.7 = 1.068 > 1 */
        {"too steep", {1.7, 10.0, 1.0, 0.0, 0.0, INFINITY}, OCEAN_STATUS_TOO_STEEP},
        {"zero wavelength", {0.1, 0.0, 1.0, 0.0, 0.0, INFINITY}, OCEAN_STATUS_INVALID_ARGUMENT},
        {"NaN wavelength", {0.1, NAN, 1.0, 0.0, 0.0, INFINITY}, OCEAN_STATUS_NON_FINITE},
        {"zero direction", {0.1, 10.0, 0.0, 0.0, 0.0, INFINITY}, OCEAN_STATUS_INVALID_ARGUMENT},
        {"infinite direction", {0.1, 10.0, INFINITY, 0.0, 0.0, INFINITY},
         OCEAN_STATUS_NON_FINITE},
        {"NaN phase", {0.1, 10.0, 1.0, 0.0, NAN, INFINITY}, OCEAN_STATUS_NON_FINITE},
        {"negative depth", {0.1, 10.0, 1.0, 0.0, 0.0, -5.0}, OCEAN_STATUS_INVALID_ARGUMENT},
        {"zero depth", {0.1, 10.0, 1.0, 0.0, 0.0, 0.0}, OCEAN_STATUS_INVALID_ARGUMENT},
        {"NaN depth", {0.1, 10.0, 1.0, 0.0, 0.0, NAN}, OCEAN_STATUS_NON_FINITE},
        {"-INFINITY depth", {0.1, 10.0, 1.0, 0.0, 0.0, -INFINITY}, OCEAN_STATUS_NON_FINITE},
    };
    size_t i;
    OceanWaves *out = valid;
    OceanWaveDesc three[3];

    expect(ocean_waves_create(NULL, 1, &out), OCEAN_STATUS_NULL_POINTER, "create(descs NULL)");
    CHECK(out == valid, "create(descs NULL) wrote *out");
    expect(ocean_waves_create(WAVES, NWAVES, NULL), OCEAN_STATUS_NULL_POINTER,
           "create(out NULL)");
    expect(ocean_waves_create(WAVES, 0, &out), OCEAN_STATUS_EMPTY, "create(n = 0)");
    CHECK(out == valid, "create(n = 0) wrote *out");
    /* 48-byte descriptions: SIZE_MAX/4 of them overflow size_t; the array is never read. */
    expect(ocean_waves_create(WAVES, SIZE_MAX / 4, &out), OCEAN_STATUS_LENGTH_OVERFLOW,
           "create(n = SIZE_MAX/4)");
    CHECK(out == valid, "create(n = SIZE_MAX/4) wrote *out");

    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        expect(ocean_waves_create(&cases[i].d, 1, &out), cases[i].want, cases[i].what);
        CHECK(out == valid, "create(%s) wrote *out", cases[i].what);
    }

    /* The message names the offending description. */
    memcpy(three, WAVES, sizeof three);
    three[2].direction_x = 0.0;
    three[2].direction_z = 0.0;
    expect(ocean_waves_create(three, 3, &out), OCEAN_STATUS_INVALID_ARGUMENT,
           "create(descs[2] zero direction)");
    CHECK(strstr(last_error(), "descs[2]") != NULL, "message does not name descs[2]: %s",
          last_error());
    CHECK(out == valid, "create(descs[2] bad) wrote *out");

    /* The cusp k*A = 1 exactly is accepted (A = lambda / 2pi). */
    {
        OceanWaveDesc cusp = {10.0 / (2.0 * PI), 10.0, 0.0, 1.0, 0.0, 50.0};
        OceanWaves *c = NULL;
        CHECK(ocean_waves_create(&cusp, 1, &c) == OCEAN_STATUS_OK && c != NULL,
              "cusp wave refused: %s", last_error());
        ocean_waves_destroy(c);
    }
}

static void test_evaluate_errors(const OceanWaves *w)
{
    OceanDVec3 pos[NPOINTS];
    OceanVec3 nrm[NPOINTS];
    OceanDVec2 bad[NPOINTS];
    const double bad_times[] = {NAN, INFINITY, -INFINITY};
    size_t i;
    fill_d(pos, NPOINTS);
    fill(nrm, NPOINTS);

#define EXPECT_UNTOUCHED(what)                                                              \
    CHECK(untouched_d(pos, NPOINTS) && untouched(nrm, NPOINTS), "%s wrote the outputs", what)

    expect(ocean_waves_evaluate(NULL, POINTS, NPOINTS, 1.0, pos, nrm), OCEAN_STATUS_NULL_POINTER,
           "evaluate(waves NULL)");
    EXPECT_UNTOUCHED("evaluate(waves NULL)");
    expect(ocean_waves_evaluate(w, NULL, NPOINTS, 1.0, pos, nrm), OCEAN_STATUS_NULL_POINTER,
           "evaluate(xz NULL)");
    EXPECT_UNTOUCHED("evaluate(xz NULL)");
    expect(ocean_waves_evaluate(w, POINTS, NPOINTS, 1.0, NULL, nrm), OCEAN_STATUS_NULL_POINTER,
           "evaluate(out_pos NULL)");
    EXPECT_UNTOUCHED("evaluate(out_pos NULL)");
    expect(ocean_waves_evaluate(w, POINTS, NPOINTS, 1.0, pos, NULL), OCEAN_STATUS_NULL_POINTER,
           "evaluate(out_normal NULL)");
    EXPECT_UNTOUCHED("evaluate(out_normal NULL)");
    expect(ocean_waves_evaluate(w, POINTS, 0, 1.0, pos, nrm), OCEAN_STATUS_EMPTY,
           "evaluate(n = 0)");
    EXPECT_UNTOUCHED("evaluate(n = 0)");
    for (i = 0; i < 3; i++) {
        expect(ocean_waves_evaluate(w, POINTS, NPOINTS, bad_times[i], pos, nrm),
               OCEAN_STATUS_NON_FINITE, "evaluate(non-finite time)");
        EXPECT_UNTOUCHED("evaluate(non-finite time)");
    }
    /* SIZE_MAX/4 points of 16 bytes overflow size_t; PTRDIFF_MAX/16 points fit the input
     * (16 bytes each) but not their positions (24 bytes each): both must be refused before any
     * memory is touched. */
    expect(ocean_waves_evaluate(w, POINTS, SIZE_MAX / 4, 1.0, pos, nrm),
           OCEAN_STATUS_LENGTH_OVERFLOW, "evaluate(n = SIZE_MAX/4)");
    EXPECT_UNTOUCHED("evaluate(n = SIZE_MAX/4)");
    expect(ocean_waves_evaluate(w, POINTS, (size_t)PTRDIFF_MAX / 16, 1.0, pos, nrm),
           OCEAN_STATUS_LENGTH_OVERFLOW, "evaluate(n = PTRDIFF_MAX/16)");
    EXPECT_UNTOUCHED("evaluate(n = PTRDIFF_MAX/16)");
    /* Positions and normals in one array. */
    expect(ocean_waves_evaluate(w, POINTS, NPOINTS, 1.0, pos, (OceanVec3 *)(void *)pos),
           OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(out_pos == out_normal)");
    EXPECT_UNTOUCHED("evaluate(out_pos == out_normal)");
    /* A NaN and an infinite rest coordinate, late in the array: nothing may be written even for
     * the valid points before it. */
    memcpy(bad, POINTS, sizeof bad);
    bad[13].z = NAN;
    expect(ocean_waves_evaluate(w, bad, NPOINTS, 1.0, pos, nrm), OCEAN_STATUS_NON_FINITE,
           "evaluate(xz[13] NaN)");
    CHECK(strstr(last_error(), "xz[13]") != NULL, "message does not name xz[13]: %s",
          last_error());
    EXPECT_UNTOUCHED("evaluate(xz[13] NaN)");
    bad[13].z = 0.0;
    bad[16].x = -INFINITY;
    expect(ocean_waves_evaluate(w, bad, NPOINTS, 1.0, pos, nrm), OCEAN_STATUS_NON_FINITE,
           "evaluate(xz[16] -inf)");
    EXPECT_UNTOUCHED("evaluate(xz[16] -inf)");
#undef EXPECT_UNTOUCHED
}

static void test_grid_errors(const OceanWaves *w)
{
    enum { N = 12 };
    OceanVec3 pos[N], nrm[N];
    const OceanGrid ok = {0.0, 0.0, 1.0, 1.0, 4, 3}; /* 12 points */
    OceanGrid g;
    fill(pos, N);
    fill(nrm, N);

#define GRID_CASE(field_assign, want, what)                                                  \
    do {                                                                                     \
        g = ok;                                                                              \
        field_assign;                                                                        \
        expect(ocean_waves_evaluate_grid(w, &g, 1.0, pos, nrm), want, what);                 \
        CHECK(untouched(pos, N) && untouched(nrm, N), "%s wrote the outputs", what);         \
    } while (0)

    expect(ocean_waves_evaluate_grid(NULL, &ok, 1.0, pos, nrm), OCEAN_STATUS_NULL_POINTER,
           "grid(waves NULL)");
    expect(ocean_waves_evaluate_grid(w, NULL, 1.0, pos, nrm), OCEAN_STATUS_NULL_POINTER,
           "grid(grid NULL)");
    expect(ocean_waves_evaluate_grid(w, &ok, 1.0, NULL, nrm), OCEAN_STATUS_NULL_POINTER,
           "grid(out_pos NULL)");
    expect(ocean_waves_evaluate_grid(w, &ok, 1.0, pos, NULL), OCEAN_STATUS_NULL_POINTER,
           "grid(out_normal NULL)");
    expect(ocean_waves_evaluate_grid(w, &ok, NAN, pos, nrm), OCEAN_STATUS_NON_FINITE,
           "grid(NaN time)");
    expect(ocean_waves_evaluate_grid(w, &ok, INFINITY, pos, nrm), OCEAN_STATUS_NON_FINITE,
           "grid(infinite time)");
    expect(ocean_waves_evaluate_grid(w, &ok, 1.0, pos, pos), OCEAN_STATUS_INVALID_ARGUMENT,
           "grid(out_pos == out_normal)");
    CHECK(untouched(pos, N) && untouched(nrm, N), "grid NULL/time/overlap cases wrote outputs");

    GRID_CASE(g.nx = 0, OCEAN_STATUS_EMPTY, "grid(nx = 0)");
    GRID_CASE(g.nz = 0, OCEAN_STATUS_EMPTY, "grid(nz = 0)");
    /* nx * nz overflows size_t. */
    GRID_CASE((g.nx = SIZE_MAX / 2, g.nz = 3), OCEAN_STATUS_LENGTH_OVERFLOW,
              "grid(nx*nz overflows)");
    /* nx * nz fits but the bytes do not. */
    GRID_CASE((g.nx = SIZE_MAX / 4, g.nz = 1), OCEAN_STATUS_LENGTH_OVERFLOW,
              "grid(bytes overflow)");
    GRID_CASE(g.spacing_x = NAN, OCEAN_STATUS_NON_FINITE, "grid(NaN spacing)");
    GRID_CASE(g.spacing_z = 0.0, OCEAN_STATUS_INVALID_ARGUMENT, "grid(zero spacing)");
    GRID_CASE(g.spacing_x = -1.0, OCEAN_STATUS_INVALID_ARGUMENT, "grid(negative spacing)");
    GRID_CASE(g.origin_x = INFINITY, OCEAN_STATUS_NON_FINITE, "grid(infinite origin)");
    GRID_CASE(g.origin_z = NAN, OCEAN_STATUS_NON_FINITE, "grid(NaN origin)");
    /* More than 2^24 columns: float column indices would no longer be exact. */
    GRID_CASE((g.nx = ((size_t)1 << 24) + 1, g.nz = 1), OCEAN_STATUS_INVALID_ARGUMENT,
              "grid(nx > 2^24)");
#undef GRID_CASE
}

static void test_query_errors(const OceanWaves *w)
{
    size_t count = 12345;
    double d = -42.0;
    expect(ocean_waves_count(NULL, &count), OCEAN_STATUS_NULL_POINTER, "count(waves NULL)");
    CHECK(count == 12345, "count(waves NULL) wrote the output");
    expect(ocean_waves_count(w, NULL), OCEAN_STATUS_NULL_POINTER, "count(out NULL)");
    expect(ocean_waves_steepness_sum(NULL, &d), OCEAN_STATUS_NULL_POINTER,
           "steepness_sum(waves NULL)");
    expect(ocean_waves_steepness_sum(w, NULL), OCEAN_STATUS_NULL_POINTER,
           "steepness_sum(out NULL)");
    expect(ocean_waves_max_amplitude(NULL, &d), OCEAN_STATUS_NULL_POINTER,
           "max_amplitude(waves NULL)");
    expect(ocean_waves_max_amplitude(w, NULL), OCEAN_STATUS_NULL_POINTER,
           "max_amplitude(out NULL)");
    CHECK(d == -42.0, "a failed getter wrote its output");

    /* A failure is followed by a success: the message is cleared. A non-status function leaves
     * it alone. */
    expect(ocean_waves_count(NULL, &count), OCEAN_STATUS_NULL_POINTER, "count(waves NULL)");
    (void)ocean_version();
    (void)ocean_status_message(OCEAN_STATUS_OK);
    ocean_waves_destroy(NULL);
    CHECK(last_error()[0] != '\0', "non-status functions cleared the last error");
    CHECK(ocean_waves_count(w, &count) == OCEAN_STATUS_OK, "count: %s", last_error());
    CHECK(last_error()[0] == '\0', "success left the last error \"%s\"", last_error());
}

int main(void)
{
    OceanWaves *w = NULL;
    OceanStatus s;

    test_version_and_messages();

    s = ocean_waves_create(WAVES, NWAVES, &w);
    CHECK(s == OCEAN_STATUS_OK && w != NULL, "create: status %u: %s", (unsigned)s, last_error());
    if (w == NULL) {
        fprintf(stderr, "test_waves.c: cannot continue without a wave set\n");
        return 1;
    }
    test_queries(w);
    test_points(w);
    test_single_wave_closed_form();
    test_grid(w);
    test_create_errors(w);
    test_evaluate_errors(w);
    test_grid_errors(w);
    test_query_errors(w);

    ocean_waves_destroy(w);
    ocean_waves_destroy(NULL); /* NULL-safe */

    printf("test_waves.c: library %s, %d checks, %d failures; max |position error| %.3g m "
           "(tolerance %g), max |normal error| %.3g (tolerance %g)\n",
           ocean_version(), checks, failures, max_pos_err, POS_TOL, max_nrm_err, NRM_TOL);
    return failures == 0 ? 0 : 1;
}
