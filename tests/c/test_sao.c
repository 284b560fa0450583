/*
 * C11 test of the Scalable Ambient Obscurance part of the ocean C ABI (ocean_sao_*), linked
 * against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_sao.c libocean.a ...
 *
 * Scene: a floor (y = 0) meeting a wall (z = -4 m, 2.5 m tall) in a 90 degree crease, seen
 * from eye height (0, 1.6, 0.5) m looking at (0, 0.3, -4) m through a 60 degree perspective,
 * with sky above the wall. Each pixel's depth is computed here, analytically: the ray through
 * the pixel centre is intersected with both planes in double precision and its view depth is
 * projected by the same float matrix the library is given, as a GPU would store it. The input
 * is 160 x 120 pixels with a 16 px guard band, so the AO image is 128 x 88.
 *
 * Checks: the planes and constants ocean_sao_describe reads from GLM-style matrices; the view
 * z of every pixel against the analytic one; the AO against what SAO's estimator implies (see
 * check_ao); a reversed-Z infinite camera on the same scene against the OpenGL one; every
 * error path with the outputs untouched; the uniform block of the exported shaders
 * (ocean_sao_uniforms); and the GPU passes on the headless device (ocean_sao_gpu_*) against
 * the CPU (check_gpu).
 *
 * Prints a summary; exits 0 only if every check passed.
 */
#include "ocean.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* The size the uniform-block functions report (OCEAN_*_UNIFORMS_SIZE). */

static const double PI = 3.14159265358979323846;

#define W 160
#define H 120
#define GUARD 16
#define OW (W - 2 * GUARD)
#define OH (H - 2 * GUARD)
#define IN_LEN ((size_t)W * H)
#define OUT_LEN ((size_t)OW * OH)

static const double EYE[3] = {0.0, 1.6, 0.5};
static const double TARGET[3] = {0.0, 0.3, -4.0};
static const double WALL_Z = -4.0;   /* the wall's plane, facing +z */
static const double WALL_TOP = 2.5;  /* metres; above it, sky */
static const double FOV_Y = 60.0;    /* degrees */
static const double NEAR = 0.1, FAR = 100.0;

enum { SKY = 0, FLOOR = 1, WALL = 2 };

/* What the ray through an input pixel's centre hits. */
typedef struct Hit {
    int kind;        /* SKY, FLOOR or WALL */
    double depth;    /* view depth (distance along the view axis), metres; 0 for sky */
    double p[3];     /* world point */
} Hit;

static Hit hits[IN_LEN];
static float depth_gl[IN_LEN], depth_rev[IN_LEN];
static float ao_gl[OUT_LEN], ao_rev[OUT_LEN];
static float zbuf[IN_LEN];

static void normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
}

/* glm::perspective (right-handed, depth [-1, 1]), element [4 * column + row]. */
static void perspective_gl(float m[16])
{
    double t = tan(FOV_Y * PI / 360.0), aspect = (double)W / H;
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = (float)(1.0 / (aspect * t));
    m[5] = (float)(1.0 / t);
    m[10] = (float)(-(FAR + NEAR) / (FAR - NEAR));
    m[11] = -1.0f;
    m[14] = (float)(-(2.0 * FAR * NEAR) / (FAR - NEAR));
}

/* The same frustum with reversed Z in [0, 1] and no far plane: depth = near / distance. */
static void perspective_reversed_infinite(float m[16])
{
    perspective_gl(m);
    m[10] = 0.0f;
    m[14] = (float)NEAR;
}

/* Intersects every pixel's ray with the scene; the ray's x and y slopes come from the float
 * matrix, so the library's reconstruction (Eq. 3) and this agree. */
static void trace(const float m[16])
{
    double f[3], s[3], u[3];
    int i, k, x, y;
    for (k = 0; k < 3; k++)
        f[k] = TARGET[k] - EYE[k];
    normalize(f);
    /* s = f x up, up = (0, 1, 0); u = s x f. */
    s[0] = -f[2];
    s[1] = 0.0;
    s[2] = f[0];
    normalize(s);
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            /* Row 0 at the top: NDC y falls with the row. */
            double nx = 2.0 * (x + 0.5) / W - 1.0, ny = 1.0 - 2.0 * (y + 0.5) / H;
            double vx = nx / m[0], vy = ny / m[5], d[3], best = INFINITY;
            Hit h;
            memset(&h, 0, sizeof h);
            for (k = 0; k < 3; k++)
                d[k] = s[k] * vx + u[k] * vy + f[k]; /* forward component 1: t = view depth */
            if (d[1] < 0.0) {
                double t = -EYE[1] / d[1], z = EYE[2] + t * d[2];
                if (z >= WALL_Z && t < best) {
                    best = t;
                    h.kind = FLOOR;
                }
            }
            if (d[2] < 0.0) {
                double t = (WALL_Z - EYE[2]) / d[2], hy = EYE[1] + t * d[1];
                if (hy >= 0.0 && hy <= WALL_TOP && t < best) {
                    best = t;
                    h.kind = WALL;
                }
            }
            if (h.kind != SKY) {
                h.depth = best;
                for (i = 0; i < 3; i++)
                    h.p[i] = EYE[i] + best * d[i];
            }
            hits[y * W + x] = h;
        }
    }
}

/* Window depth of every pixel under matrix m and a depth convention: clip z / clip w with the
 * matrix's own (float) depth row, evaluated in double and stored as float; sky gets the clear
 * value. */
static void make_depth(const float m[16], int gl, float *out)
{
    size_t i;
    for (i = 0; i < IN_LEN; i++) {
        if (hits[i].kind == SKY) {
            out[i] = gl ? 1.0f : 0.0f;
        } else {
            double zv = -hits[i].depth;
            double ndc = ((double)m[10] * zv + (double)m[14]) / -zv;
            out[i] = (float)(gl ? 0.5 * ndc + 0.5 : ndc);
        }
    }
}

static const Hit *out_hit(int x, int y) { return &hits[(y + GUARD) * W + (x + GUARD)]; }

/* Distance of an output pixel's point from the crease line (y = 0, z = -4). */
static double crease_distance(const Hit *h)
{
    return h->kind == FLOOR ? h->p[2] - WALL_Z : h->p[1];
}

/* The camera of a float projection matrix (as a renderer keeps it), widened to double, with
 * the identity view: SAO reads only the projection. */
static OceanCamera camera_of(const float projection[16], uint32_t convention)
{
    OceanCamera c;
    int i;
    memset(&c, 0, sizeof c);
    c.view[0] = c.view[5] = c.view[10] = c.view[15] = 1.0;
    for (i = 0; i < 16; i++)
        c.projection[i] = projection[i];
    c.depth_convention = convention;
    return c;
}

static OceanCamera camera_gl(void)
{
    float m[16];
    perspective_gl(m);
    return camera_of(m, OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
}

static OceanCamera camera_rev(void)
{
    float m[16];
    perspective_reversed_infinite(m);
    return camera_of(m, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED);
}

/* ------------------------------------------------------------------------------------------ */

static void check_describe(const OceanSao *sao, int gl)
{
    OceanSaoInfo info;
    memset(&info, 0, sizeof info);
    if (!OK(ocean_sao_describe(sao, &info)))
        return;
    CHECK(info.input_width == W && info.input_height == H && info.guard == GUARD &&
              info.output_width == OW && info.output_height == OH,
          "sizes %u x %u guard %u -> %u x %u", info.input_width, info.input_height, info.guard,
          info.output_width, info.output_height);
    CHECK(info.orthographic == 0, "orthographic %u", (unsigned)info.orthographic);
    CHECK(fabs(info.near - NEAR) <= 1e-5 * NEAR, "near %.9g m", info.near);
    if (gl) {
        /* far = P23 / (1 + P22) with 1 + P22 = -2n/(f - n): its float rounding (6e-8 of P22)
         * grows by (f - n)/2n = 500, to 3e-5 of far. */
        CHECK(fabs(info.far - FAR) <= 1e-4 * FAR, "far %.9g m", info.far);
        CHECK(info.near_depth == 0.0f && info.far_depth == 1.0f, "depth range %g .. %g",
              info.near_depth, info.far_depth);
    } else {
        CHECK(isinf(info.far) && info.far > 0.0, "far %g: expected INFINITY", info.far);
        CHECK(info.near_depth == 1.0f && info.far_depth == 0.0f, "depth range %g .. %g",
              info.near_depth, info.far_depth);
    }
    /* Eq. 5: S' = h P11 / 2. */
    CHECK(fabs(info.pixels_per_metre - 0.5 * H / tan(FOV_Y * PI / 360.0)) <= 1e-4,
          "pixels per metre %g", info.pixels_per_metre);
    /* The constants reproduce the depth of a wall pixel: Eq. 2 in float, as documented. */
    {
        const float *c = info.z_constants;
        const float *d = gl ? depth_gl : depth_rev;
        size_t i = (size_t)(H / 2) * W + W / 2;
        float z = (c[0] + c[3] * d[i]) / (c[1] * d[i] + c[2]);
        CHECK(hits[i].kind != SKY && fabs(z + hits[i].depth) <= 1e-4 * hits[i].depth,
              "Eq. 2 at the centre: %g, expected %g", z, -hits[i].depth);
    }
}

/* Eq. 2 over the whole buffer against the analytic view depth. A float window depth near 1
 * carries an error of at most 3e-8; at the farthest geometry (about 6 m) that is 1e-5 m of z
 * under this matrix, and the float evaluation adds cancellation of the same order: 1e-4 of the
 * depth bounds both. Sky reads as OCEAN_SAO_SKY_Z exactly. */
static void check_view_z(const OceanSao *sao, const float *depth, const char *what)
{
    size_t i, bad = 0, sky = 0;
    for (i = 0; i < IN_LEN; i++)
        zbuf[i] = 7.0f;
    if (!OK(ocean_sao_view_z(sao, depth, IN_LEN, zbuf, IN_LEN)))
        return;
    for (i = 0; i < IN_LEN; i++) {
        if (hits[i].kind == SKY) {
            sky++;
            bad += zbuf[i] != (float)OCEAN_SAO_SKY_Z;
        } else {
            bad += !(fabs(zbuf[i] + hits[i].depth) <= 1e-4 * hits[i].depth);
        }
    }
    CHECK(sky > 100 && sky < IN_LEN / 2, "%s: %zu sky pixels", what, sky);
    CHECK(bad == 0, "%s: %zu pixels with a wrong view z", what, bad);
}

/*
 * What SAO must give on this scene (r = 1 m, the appendix's falloff, the paper's blur):
 *
 * - Every A is in [0, 1], and sky pixels are exactly 1 (the library's documented background).
 * - Nothing occludes a point farther than r from the other plane: the floor is flat and the
 *   wall is flat, so every sample on the point's own plane lies on its tangent plane (v.n is
 *   within the depth error, far below beta = 1 cm) and contributes 0, and the falloff
 *   (r^2 - v.v)^3 vanishes outside the ball. The blur mixes only pixels within 3 taps * 3 px =
 *   9 px and within 200 m / 2048 = 0.1 m of view depth. On the floor, rows run parallel to
 *   the crease and 0.1 m of view depth is about 0.1 m of distance to the wall, so floor pixels
 *   from 1.2 m on stay exactly 1. Up the wall, view depth changes by only sin(16 deg) = 0.28 of
 *   the height, and 9 px there span 0.4 m: wall pixels from r + 0.4 m + a pixel = 1.45 m up
 *   (and 9 px below the top edge, which also borders the sky) stay exactly 1.
 * - Toward the crease the obscurance grows: in 0.2 m bands of distance to the crease, the mean
 *   A falls monotonically toward the contact on both planes, and the band touching it is dark
 *   (mean A <= 0.6; ocean-sao's own crease test measures 0.02 to 0.34 there before the blur).
 */
static void check_ao(const float *ao, const char *what)
{
    double floor_sum[8] = {0}, wall_sum[8] = {0};
    int floor_n[8] = {0}, wall_n[8] = {0};
    size_t out_of_range = 0, sky_bad = 0, far_bad = 0, far_n = 0;
    int x, y, b;
    for (y = 0; y < OH; y++) {
        for (x = 0; x < OW; x++) {
            const Hit *h = out_hit(x, y);
            float a = ao[y * OW + x];
            double dist;
            if (!(a >= 0.0f && a <= 1.0f))
                out_of_range++;
            if (h->kind == SKY) {
                sky_bad += a != 1.0f;
                continue;
            }
            dist = crease_distance(h);
            if ((h->kind == FLOOR && dist >= 1.2) ||
                (h->kind == WALL && dist >= 1.45 && h->p[1] <= WALL_TOP - 0.45)) {
                far_n++;
                if (a != 1.0f) {
                    if (far_bad < 5)
                        fprintf(stderr, "%s: pixel (%d, %d) %s %.3f m from the crease: A = %.6f\n",
                                what, x, y, h->kind == FLOOR ? "floor" : "wall", dist, a);
                    far_bad++;
                }
            }
            b = (int)(dist / 0.2);
            if (b < 8) {
                if (h->kind == FLOOR) {
                    floor_sum[b] += a;
                    floor_n[b]++;
                } else {
                    wall_sum[b] += a;
                    wall_n[b]++;
                }
            }
        }
    }
    CHECK(out_of_range == 0, "%s: %zu values outside [0, 1]", what, out_of_range);
    CHECK(sky_bad == 0, "%s: %zu sky pixels not exactly 1", what, sky_bad);
    CHECK(far_n > 2000, "%s: only %zu pixels far from the crease", what, far_n);
    CHECK(far_bad == 0, "%s: %zu of %zu pixels far from the crease are not exactly 1", what,
          far_bad, far_n);
    printf("%s: mean A in 0.2 m bands from the crease, floor:", what);
    for (b = 0; b < 8; b++)
        printf(" %.3f", floor_n[b] ? floor_sum[b] / floor_n[b] : -1.0);
    printf("; wall:");
    for (b = 0; b < 8; b++)
        printf(" %.3f", wall_n[b] ? wall_sum[b] / wall_n[b] : -1.0);
    printf("\n");
    for (b = 0; b < 8; b++)
        CHECK(floor_n[b] > 0 && wall_n[b] > 0, "%s: band %d is empty", what, b);
    CHECK(floor_sum[0] / floor_n[0] <= 0.6 && wall_sum[0] / wall_n[0] <= 0.6,
          "%s: the crease is not dark: floor %.3f, wall %.3f", what, floor_sum[0] / floor_n[0],
          wall_sum[0] / wall_n[0]);
    for (b = 1; b < 8; b++) {
        CHECK(floor_sum[b] / floor_n[b] >= floor_sum[b - 1] / floor_n[b - 1],
              "%s: floor band %d (%.3f) darker than band %d (%.3f)", what, b,
              floor_sum[b] / floor_n[b], b - 1, floor_sum[b - 1] / floor_n[b - 1]);
        CHECK(wall_sum[b] / wall_n[b] >= wall_sum[b - 1] / wall_n[b - 1],
              "%s: wall band %d (%.3f) darker than band %d (%.3f)", what, b,
              wall_sum[b] / wall_n[b], b - 1, wall_sum[b - 1] / wall_n[b - 1]);
    }
    CHECK(floor_sum[0] / floor_n[0] < floor_sum[5] / floor_n[5] - 0.3,
          "%s: the floor's contact band is not clearly darker than 1 m away", what);
}

/* ------------------------------------------------------------------------------------------ */

static int untouched(const float *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (v[i] != 7.0f)
            return 0;
    return 1;
}

static void test_create_errors(void)
{
    OceanSaoParams p, bad;
    OceanCamera c = camera_gl(), cb;
    OceanSao *keep = (OceanSao *)&p; /* a sentinel: must survive every failure */
    OceanSao *out = keep;

    EXPECT(ocean_sao_params_default(NULL), OCEAN_STATUS_NULL_POINTER);
    if (!OK(ocean_sao_params_default(&p)))
        return;
    CHECK(p.radius == 1.0f && p.samples == 9 && p.spiral_turns == 7.0f &&
              p.mip_filter == OCEAN_SAO_MIP_FILTER_ROTATED_GRID &&
              p.estimator == OCEAN_SAO_ESTIMATOR_FALLOFF && p.quad_filter == 1 &&
              p.normal_rejection == 0 && p.blur.taps == 13 && p.blur.stride == 1 &&
              p.blur.sigma == 3.0f &&
              p.normals == OCEAN_SAO_NORMALS_NEAREST &&
              p.blur.weight == OCEAN_SAO_BLUR_WEIGHT_PLANE && p.blur.world_extent == 0.5f,
          "unexpected defaults");

    EXPECT(ocean_sao_create(W, H, GUARD, NULL, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, NULL, &out), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &p, NULL), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_sao_create(0, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_EMPTY, "0 x 120");
    EXPECT_MSG(ocean_sao_create(1, H, 0, &c, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "image size");
    EXPECT_MSG(ocean_sao_create(OCEAN_SAO_MAX_SIDE + 1, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &p, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "image size");
    /* A guard band larger than the image: 2 * 60 is not below 120. */
    EXPECT_MSG(ocean_sao_create(W, H, H / 2, &c, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "guard band");

    /* Matrices that are not projections, or not for this convention. */
    cb = c;
    memset(cb.projection, 0, sizeof cb.projection);
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "bottom row");
    cb = c;
    cb.projection[11] = 1.0; /* left-handed: w_clip = +z */
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "bottom row");
    cb = c;
    cb.projection[5] = NAN;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_NON_FINITE,
               "projection[5]");
    cb = c;
    cb.projection[8] = 0.01; /* a jittered frustum */
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "off-centre");
    cb = c;
    cb.projection[5] = -cb.projection[5];
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "y-flipped");
    cb = c;
    cb.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED; /* an OpenGL matrix */
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "far plane");
    cb = c;
    cb.projection[10] = -1.0; /* a depth row that puts the near plane at the eye */
    cb.projection[14] = 0.0;
    EXPECT(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT);
    cb = c;
    /* Valid (fov_y = 2e-38 rad), but S' = h P11 / 2 overflows float. */
    cb.projection[0] = 7.5e37f;
    cb.projection[5] = 1.0e38f;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "degenerate");
    cb = c;
    cb.depth_convention = 3;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &cb, OCEAN_SAO_DEPTH_WINDOW, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "depth_convention");
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, 2, &p, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "depth_source");

    /* The documented bounds, written as C float literals, are inside: 1e-4f, 1e-12f, 1e-2f and
     * -1e-4f are the nearest floats to the decimal bounds, which lie just outside them. */
    {
        OceanSao *edge = NULL;
        bad = p;
        bad.radius = 1e-4f;
        bad.epsilon = 1e-12f;
        bad.z_min = -1e-4f;
        if (OK(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &edge)))
            ocean_sao_destroy(edge);
        bad = p;
        bad.estimator = OCEAN_SAO_ESTIMATOR_ALCHEMY;
        bad.alchemy_k = 1e-2f;
        bad.radius = 1e4f;
        if (OK(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &edge)))
            ocean_sao_destroy(edge);
        /* The next float beyond a bound is outside, and the message prints it briefly. */
        bad = p;
        bad.radius = nextafterf(1e-4f, 0.0f);
        EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
                   "radius");
        CHECK(strlen(last_error()) < 160, "long message: %s", last_error());
    }

    /* Parameters out of range. */
    bad = p;
    bad.samples = 0;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "samples");
    bad = p;
    bad.radius = NAN;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_NON_FINITE,
               "radius");
    bad = p;
    bad.blur.taps = 8;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "odd");
    bad = p;
    bad.mip_filter = 5;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "mip_filter");
    bad = p;
    bad.estimator = 2;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "estimator");
    bad = p;
    bad.quad_filter = 2;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "quad_filter");
    bad = p;
    bad.normals = 2;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "normals");
    bad = p;
    bad.blur.weight = 2;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "blur.weight");
    bad = p;
    bad.blur.world_extent = -1.0f;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "world_extent");
    bad = p;
    bad.z_min = 10.0f;
    EXPECT_MSG(ocean_sao_create(W, H, GUARD, &c, OCEAN_SAO_DEPTH_WINDOW, &bad, &out), OCEAN_STATUS_INVALID_ARGUMENT,
               "z_min");
    CHECK(out == keep, "a failed create wrote *out");
}

static void test_run_errors(const OceanSao *sao)
{
    static float d[IN_LEN], ao[OUT_LEN], z[IN_LEN];
    size_t i;
    memcpy(d, depth_gl, sizeof d);
    for (i = 0; i < OUT_LEN; i++)
        ao[i] = 7.0f;
    for (i = 0; i < IN_LEN; i++)
        z[i] = 7.0f;

    EXPECT(ocean_sao_run(NULL, d, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_sao_run(sao, NULL, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_sao_run(sao, d, IN_LEN, NULL, OUT_LEN), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN - 1, ao, OUT_LEN), OCEAN_STATUS_LENGTH_MISMATCH,
               "depth_len");
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN + 1), OCEAN_STATUS_LENGTH_MISMATCH,
               "ao_len");
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, IN_LEN), OCEAN_STATUS_LENGTH_MISMATCH,
               "128 x 88");
    /* The AO written over the depth it reads. */
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, d + 10, OUT_LEN), OCEAN_STATUS_INVALID_ARGUMENT,
               "overlap");
    CHECK(memcmp(d, depth_gl, sizeof d) == 0, "a failed run wrote the depth buffer");

    /* Bad depth values: the message names the first one's pixel. */
    d[3 * W + 5] = NAN;
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_NON_FINITE, "(5, 3)");
    EXPECT_MSG(ocean_sao_view_z(sao, d, IN_LEN, z, IN_LEN), OCEAN_STATUS_NON_FINITE, "(5, 3)");
    d[3 * W + 5] = INFINITY;
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_NON_FINITE, "(5, 3)");
    d[3 * W + 5] = depth_gl[3 * W + 5];
    d[100 * W + 17] = 1.5f;
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_INVALID_ARGUMENT,
               "(17, 100)");
    /* NDC depth handed over as window depth: -0.5 is outside [0, 1]. */
    d[100 * W + 17] = -0.5f;
    EXPECT_MSG(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN), OCEAN_STATUS_INVALID_ARGUMENT,
               "outside [0, 1]");
    EXPECT_MSG(ocean_sao_view_z(sao, d, IN_LEN, z, IN_LEN), OCEAN_STATUS_INVALID_ARGUMENT,
               "outside [0, 1]");
    d[100 * W + 17] = depth_gl[100 * W + 17];
    EXPECT(ocean_sao_view_z(sao, d, IN_LEN, NULL, IN_LEN), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_sao_view_z(sao, d, IN_LEN, z, OUT_LEN), OCEAN_STATUS_LENGTH_MISMATCH,
               "z_len");
    EXPECT(ocean_sao_describe(NULL, NULL), OCEAN_STATUS_NULL_POINTER);
    CHECK(untouched(ao, OUT_LEN), "a failed run wrote the AO buffer");
    CHECK(untouched(z, IN_LEN), "a failed view_z wrote the z buffer");

    /* After the failures a good call succeeds and clears the message. */
    OK(ocean_sao_run(sao, d, IN_LEN, ao, OUT_LEN));
    CHECK(memcmp(ao, ao_gl, sizeof ao) == 0, "a second run differs from the first");
}

/* The uniform block of the exported shaders: its size, the z constants that ocean_sao_describe
 * reports at offset 0, the sizes at offsets 32-51 (the binding table's layout), a level count
 * for a 160 x 120 input (at most 1 + floor(log2(120)) = 7 levels), and LENGTH_MISMATCH with
 * nothing written for a buffer of any other length. */
static void check_uniforms(const OceanSao *sao)
{
    unsigned char block[OCEAN_SAO_UNIFORMS_SIZE], other[OCEAN_SAO_UNIFORMS_SIZE + 1];
    float z[4];
    uint32_t sizes[5], levels = 0, kept = 99;
    OceanSaoInfo info;
    size_t i;

    CHECK(OCEAN_SAO_UNIFORMS_SIZE == 304, "uniform block of %d bytes", OCEAN_SAO_UNIFORMS_SIZE);
    if (!OK(ocean_sao_uniforms(sao, block, sizeof block, &levels)) ||
        !OK(ocean_sao_describe(sao, &info)))
        return;
    memcpy(z, block, sizeof z);
    memcpy(sizes, block + 32, sizeof sizes);
    for (i = 0; i < 4; i++)
        CHECK(z[i] == info.z_constants[i], "z constant %zu: %g in the block, %g described", i,
              (double)z[i], (double)info.z_constants[i]);
    CHECK(sizes[0] == W && sizes[1] == H, "input size %u x %u", sizes[0], sizes[1]);
    CHECK(sizes[2] == W - 2 * GUARD && sizes[3] == H - 2 * GUARD, "output size %u x %u",
          sizes[2], sizes[3]);
    CHECK(sizes[4] == GUARD, "guard %u", sizes[4]);
    CHECK(levels >= 1 && levels <= 7, "%u z levels", levels);
    memset(other, 7, sizeof other);
    EXPECT_MSG(ocean_sao_uniforms(sao, other, sizeof other, &kept), OCEAN_STATUS_LENGTH_MISMATCH,
               "holds exactly 304");
    EXPECT_MSG(ocean_sao_uniforms(sao, other, sizeof other - 2, &kept),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 304");
    for (i = 0; i < sizeof other && other[i] == 7; i++)
        ;
    CHECK(i == sizeof other && kept == 99, "written on failure");
    EXPECT(ocean_sao_uniforms(sao, NULL, 0, &kept), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_sao_uniforms(sao, other, sizeof block, NULL), OCEAN_STATUS_NULL_POINTER,
               "levels");
}

/* The GPU passes on the library's headless device (ocean_sao_gpu_*): the CPU's AO within 2/255
 * on at least 99.9% of the pixels (the library's parity bound), and a handle refused on another
 * context with the output untouched. Without an adapter this part is skipped, unless
 * OCEAN_REQUIRE_GPU=1 makes that a failure. */
static void check_gpu(const OceanSao *sao, const float *depth, const float *cpu_ao)
{
    static float gpu_ao[OUT_LEN], other_ao[OUT_LEN];
    OceanGpuContext *ctx = NULL, *other = NULL;
    OceanSaoGpu *gpu = NULL;
    const char *require = getenv("OCEAN_REQUIRE_GPU");
    OceanStatus s = ocean_gpu_context_create(&ctx);
    size_t i, beyond = 0;

    if (s == OCEAN_STATUS_NO_ADAPTER) {
        if (require != NULL && strcmp(require, "1") == 0)
            CHECK(0, "OCEAN_REQUIRE_GPU=1 but no GPU context: %s", last_error());
        else
            printf("SKIPPED: the GPU passes (no usable adapter: %s)\n", last_error());
        return;
    }
    if (!OK(s))
        return;
    if (OK(ocean_sao_gpu_create(ctx, &gpu)) &&
        OK(ocean_sao_gpu_run(gpu, ctx, sao, depth, IN_LEN, gpu_ao, OUT_LEN))) {
        for (i = 0; i < OUT_LEN; i++)
            beyond += fabs((double)gpu_ao[i] - cpu_ao[i]) > 2.0 / 255.0;
        printf("GPU: %zu of %zu pixels beyond 2/255 of the CPU\n", beyond, OUT_LEN);
        CHECK(beyond * 1000 <= OUT_LEN, "%zu GPU pixels beyond 2/255", beyond);
        if (OK(ocean_gpu_context_create(&other))) {
            for (i = 0; i < OUT_LEN; i++)
                other_ao[i] = 7.0f;
            EXPECT(ocean_sao_gpu_run(gpu, other, sao, depth, IN_LEN, other_ao, OUT_LEN),
                   OCEAN_STATUS_INVALID_ARGUMENT);
            CHECK(untouched(other_ao, OUT_LEN), "AO written on another context");
            ocean_gpu_context_destroy(other);
        }
    }
    ocean_sao_gpu_destroy(gpu);
    ocean_sao_gpu_destroy(NULL);
    ocean_gpu_context_destroy(ctx);
}

int main(void)
{
    OceanSaoParams p;
    OceanCamera gl = camera_gl(), rev = camera_rev();
    OceanSao *sao_gl = NULL, *sao_rev = NULL;
    size_t i, differ = 0, beyond = 0;
    double worst = 0.0;
    float m_gl[16], m_rev[16];

    perspective_gl(m_gl);
    perspective_reversed_infinite(m_rev);
    trace(m_gl);
    make_depth(m_gl, 1, depth_gl);
    make_depth(m_rev, 0, depth_rev);

    test_create_errors();

    if (OK(ocean_sao_params_default(&p)) && OK(ocean_sao_create(W, H, GUARD, &gl, OCEAN_SAO_DEPTH_WINDOW, &p, &sao_gl)) &&
        OK(ocean_sao_create(W, H, GUARD, &rev, OCEAN_SAO_DEPTH_WINDOW, &p, &sao_rev))) {
        check_describe(sao_gl, 1);
        check_describe(sao_rev, 0);
        check_view_z(sao_gl, depth_gl, "OpenGL [-1, 1]");
        check_view_z(sao_rev, depth_rev, "reversed-Z infinite");

        if (OK(ocean_sao_run(sao_gl, depth_gl, IN_LEN, ao_gl, OUT_LEN)))
            check_ao(ao_gl, "OpenGL [-1, 1]");
        if (OK(ocean_sao_run(sao_rev, depth_rev, IN_LEN, ao_rev, OUT_LEN)))
            check_ao(ao_rev, "reversed-Z infinite");

        /* The same scene through two depth conventions: only the depth precision differs. */
        for (i = 0; i < OUT_LEN; i++) {
            double e = fabs((double)ao_gl[i] - ao_rev[i]);
            differ += e != 0.0;
            beyond += e > 2.0 / 255.0;
            if (e > worst)
                worst = e;
        }
        printf("conventions: %zu of %zu pixels differ, %zu by more than 2/255, worst %.4f\n",
               differ, OUT_LEN, beyond, worst);
        CHECK(beyond * 1000 <= OUT_LEN, "%zu pixels differ by more than 2/255", beyond);

        test_run_errors(sao_gl);
        check_uniforms(sao_gl);
        check_gpu(sao_rev, depth_rev, ao_rev);
    }
    ocean_sao_destroy(sao_gl);
    ocean_sao_destroy(sao_rev);
    ocean_sao_destroy(NULL); /* NULL-safe */

    printf("test_sao.c: library %s, %d checks, %d failures\n", ocean_version(), checks,
           failures);
    return failures == 0 ? 0 : 1;
}
