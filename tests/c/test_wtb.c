/*
 * C11 test of the Wave Train Boxes part of the ocean C ABI (ocean_wtb_scene_*), linked against
 * libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_wtb.c libocean.a ...
 *
 * Scene: the paper's scenario 1 (two winds, 1 and 2 trains, 7 and 5 m/s) on a 64 x 64 grid over
 * a sea floor sloping from 30 m to 1 m deep, with a small island; at 1 m spacing, and again at
 * 0.5 m and 2 m (surface bounds and height queries). Checks every output against
 * bounds derived here from the paper's Eq. 1, a single explicit train against the closed-form
 * trochoid, culling, height queries against the grid, moving and removing boxes, and every
 * error path with the outputs untouched.
 *
 * Prints a summary; exits 0 only if every check passed.
 */
#include "ocean.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;
static const double G = 9.81; /* m/s^2, the library's documented gravity */

#define NX 64
#define NZ 64
#define NPTS (NX * NZ)
/* The grid's origin is far from the world's, so world and grid-relative coordinates differ. */
static const double OX = 1000.0, OZ = -500.0;
/* Grid spacing, metres: 1 m for most of the test; scenario 1 also runs at 0.5 m and 2 m, with
 * its layout (island, boxes) scaled with the grid. */
static double SP = 1.0;

#include "check.h"

/* Eq. 1: fully developed crest-to-trough height H = 0.21 h^2 / g. */
static double wind_height(double speed) { return 0.21 * speed * speed / G; }

/* ------------------------------------------------------------------------------------------ */
/* The scene.                                                                                 */

static float terrain[NPTS];

/* Island: land within 4 cells of grid point (44, 32) (2 m high); elsewhere a floor sloping
 * from 30 m deep at x = 0 to 1 m deep at the far side. */
static int is_island(int i, int j)
{
    double dx = i - 44.0, dz = j - 32.0;
    return dx * dx + dz * dz < 16.0;
}

static void make_terrain(void)
{
    int i, j;
    for (j = 0; j < NZ; j++)
        for (i = 0; i < NX; i++)
            terrain[j * NX + i] =
                is_island(i, j) ? 2.0f : (float)-(30.0 - 29.0 * (i * SP) / ((NX - 1) * SP));
}

static OceanWindDesc steady_wind(double speed, double dx, double dz, double ox, double oz,
                                 double width, double fetch, uint32_t trains, uint64_t seed)
{
    OceanWindDesc w;
    memset(&w, 0, sizeof w);
    w.speed = speed;
    w.direction_x = dx;
    w.direction_z = dz;
    w.origin_x = OX + ox;
    w.origin_z = OZ + oz;
    w.width = width;
    w.fetch = fetch;
    w.start = -1.0;
    w.build_up = 0.0;
    w.sustain = INFINITY; /* documented: a wind that never dies */
    w.decay = 0.0;
    w.seed = seed;
    w.trains = trains;
    return w;
}

static OceanBoxDesc box_of(OceanWindDesc w)
{
    OceanBoxDesc b;
    memset(&b, 0, sizeof b);
    b.wind = w;
    b.smoothing = 4.0;
    b.has_recovery = 0;
    b.recovery = 0.0;
    return b;
}

/* Scenario 1's winds (grid-local origins, in cells). */
static OceanBoxDesc box_a(void)
{
    return box_of(steady_wind(7.0, 1.0, 0.15, -2.0 * SP, -4.0 * SP, 66.0 * SP, 70.0 * SP, 1, 11));
}
static OceanBoxDesc box_b(void)
{
    return box_of(steady_wind(5.0, 0.7, 1.0, 30.0 * SP, -30.0 * SP, 60.0 * SP, 90.0 * SP, 2, 12));
}

static OceanWaterGridDesc grid_desc(void)
{
    OceanWaterGridDesc g;
    g.origin_x = OX;
    g.origin_z = OZ;
    g.spacing = SP;
    g.nx = NX;
    g.nz = NZ;
    return g;
}

static OceanVec3 pos[NPTS], nrm[NPTS], pos2[NPTS], nrm2[NPTS];

static const float SENTINEL = -7777.0f;

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

static int evaluate(OceanWtbScene *s, double t, OceanVec3 *p, OceanVec3 *n, OceanFrameStats *st)
{
    return OK(ocean_wtb_scene_evaluate(s, t, NULL, p, n, NPTS,
                                   st));
}

/* Whether point (i, j) is exactly at rest: no displacement, up normal. */
static int at_rest(const OceanVec3 *p, const OceanVec3 *n, int i, int j)
{
    size_t k = (size_t)j * NX + (size_t)i;
    return p[k].y == 0.0f && fabs(p[k].x - i * SP) <= 1e-6 && fabs(p[k].z - j * SP) <= 1e-6 &&
           n[k].x == 0.0f && n[k].y == 1.0f && n[k].z == 0.0f;
}

/* Internal coordinates (a along the wind, b across) of grid point (i, j) in a box. */
static void internal(const OceanWindDesc *w, int i, int j, double *a, double *b)
{
    double len = sqrt(w->direction_x * w->direction_x + w->direction_z * w->direction_z);
    double ux = w->direction_x / len, uz = w->direction_z / len;
    double px = OX + i * SP - w->origin_x, pz = OZ + j * SP - w->origin_z;
    *a = px * ux + pz * uz;
    *b = -px * uz + pz * ux; /* v = (-u.z, u.x) */
}

static int outside_box(const OceanWindDesc *w, int i, int j)
{
    double a, b, e = 1e-6;
    internal(w, i, j, &a, &b);
    return a < -e || b < -e || a > w->fetch + e || b > w->width + e;
}

/* Strictly inside the box, past its 4 m smoothing, and at sea. */
static int deep_inside_box(const OceanWindDesc *w, int i, int j)
{
    double a, b, m = 5.0;
    internal(w, i, j, &a, &b);
    return a > m && b > m && a < w->fetch - m && b < w->width - m && !is_island(i, j);
}

/* ------------------------------------------------------------------------------------------ */

/*
 * Bounds. Each box's trains have amplitudes summing to H/2 (Eq. 1; the steepness limits only
 * lower them); the modulation (land, recovery, side smoothing) is at most 1 and shoaling
 * multiplies by at most 1.5 (the library's documented cap); refraction only shifts phases; the
 * two boxes add. So |y| and the horizontal displacement are at most 1.5 (H1 + H2)/2. The
 * margin covers float rounding (~1e-6 m).
 */
static double bound(void) { return 1.5 * (wind_height(7.0) + wind_height(5.0)) / 2.0 + 1e-4; }

static void check_surface(const char *what, double t)
{
    int i, j, land = 0;
    double ymax = 0.0, b = bound();
    for (j = 0; j < NZ; j++) {
        for (i = 0; i < NX; i++) {
            size_t k = (size_t)j * NX + (size_t)i;
            const OceanVec3 *p = &pos[k], *n = &nrm[k];
            double len = sqrt((double)n->x * n->x + (double)n->y * n->y + (double)n->z * n->z);
            int finite = isfinite(p->x) && isfinite(p->y) && isfinite(p->z) && isfinite(n->x) &&
                         isfinite(n->y) && isfinite(n->z);
            CHECK(finite, "%s t=%g: point (%d, %d) not finite", what, t, i, j);
            /* A float normalisation is within a few ulps of 1. */
            CHECK(fabs(len - 1.0) <= 1e-5, "%s t=%g: |normal(%d, %d)| = %.8f", what, t, i, j,
                  len);
            /* The summed steepness stays well below 1, so the surface never folds. */
            CHECK(n->y > 0.0f, "%s t=%g: normal(%d, %d) points down", what, t, i, j);
            CHECK(fabs(p->y) <= b, "%s t=%g: |y(%d, %d)| = %.5f above the bound %.5f", what, t,
                  i, j, fabs(p->y), b);
            CHECK(fabs(p->x - i * SP) <= b && fabs(p->z - j * SP) <= b,
                  "%s t=%g: point (%d, %d) moved sideways by more than %.4f", what, t, i, j, b);
            if (is_island(i, j)) {
                land++;
                /* Amplitude is zero on land: the grid point stays at its rest height. */
                CHECK(p->y == 0.0f && fabs(p->x - i * SP) <= 1e-6 && fabs(p->z - j * SP) <= 1e-6,
                      "%s t=%g: land point (%d, %d) moved to (%.6f, %.6f, %.6f)", what, t, i, j,
                      p->x, p->y, p->z);
            }
            ymax = fmax(ymax, fabs(p->y));
        }
    }
    CHECK(land > 20, "the island has only %d grid points", land);
    /* Waves exist: crests of a 7 m/s wind reach ~H1/2 = 0.52 m somewhere on 64 x 64 m. */
    CHECK(ymax > 0.2 * b, "%s t=%g: largest |y| %.4f: no waves?", what, t, ymax);
}

/* Column-major 4x4 helpers (m[col*4 + row]), GLM's conventions. */

/* glm::lookAtRH */
static void look_at(const double eye[3], const double f_in[3], const double up[3], double m[16])
{
    double f[3], s[3], u[3], l;
    int i;
    l = sqrt(f_in[0] * f_in[0] + f_in[1] * f_in[1] + f_in[2] * f_in[2]);
    for (i = 0; i < 3; i++)
        f[i] = f_in[i] / l;
    s[0] = f[1] * up[2] - f[2] * up[1];
    s[1] = f[2] * up[0] - f[0] * up[2];
    s[2] = f[0] * up[1] - f[1] * up[0];
    l = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (i = 0; i < 3; i++)
        s[i] /= l;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    memset(m, 0, 16 * sizeof m[0]);
    for (i = 0; i < 3; i++) {
        m[i * 4 + 0] = s[i];
        m[i * 4 + 1] = u[i];
        m[i * 4 + 2] = -f[i];
    }
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    m[15] = 1.0;
}

/* A camera at `eye` looking along `dir` (up: +z), 90 degrees, near 0.5 m, far 500 m. */
static OceanCamera camera_looking(const double eye[3], const double dir[3], uint32_t convention)
{
    static const double up[3] = {0.0, 0.0, 1.0};
    OceanCamera c;
    memset(&c, 0, sizeof c);
    look_at(eye, dir, up, c.view);
    check_perspective(PI / 2.0, 1.0, 0.5, 500.0, convention, c.projection);
    c.depth_convention = convention;
    return c;
}

static void test_culling(OceanWtbScene *s, double t)
{
    /* Above the grid's centre (world coordinates), 30 m up. */
    const double eye_up[3] = {OX + 32.0 * SP, 30.0, OZ + 32.0 * SP};
    const double up_dir[3] = {0.0, 1.0, 0.0};
    const double eye_high[3] = {OX + 32.0 * SP, 80.0, OZ + 32.0 * SP};
    const double down_dir[3] = {0.0, -1.0, 0.0};
    OceanCamera m;
    OceanFrameStats st;
    int i, j, rest = 1;

    evaluate(s, t, pos, nrm, &st);
    /* Looking at the sky: the frustum holds only y > 30.5 m (near plane 0.5 m), and every
     * box's bounding volume ends ~1.2 m above the sea: both boxes are culled, the grid is at
     * rest. */
    m = camera_looking(eye_up, up_dir, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE);
    OK(ocean_wtb_scene_evaluate(s, t, &m, pos2, nrm2, NPTS, &st));
    CHECK(st.alive == 2 && st.culled == 2 && st.trains == 0,
          "looking away: alive %zu, culled %zu, trains %zu", st.alive, st.culled, st.trains);
    for (j = 0; j < NZ; j++)
        for (i = 0; i < NX; i++)
            rest &= at_rest(pos2, nrm2, i, j);
    CHECK(rest, "looking away from the grid left points displaced");

    /* Looking down from 80 m with a 90 degree field of view (OpenGL depth): the frustum's
     * footprint at sea level is 160 m wide, covering the 63 m grid, so nothing is culled and the
     * result is the unculled one, bit for bit. */
    m = camera_looking(eye_high, down_dir, OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
    OK(ocean_wtb_scene_evaluate(s, t, &m, pos2, nrm2, NPTS, &st));
    CHECK(st.alive == 2 && st.culled == 0, "looking down: alive %zu, culled %zu", st.alive,
          st.culled);
    CHECK(memcmp(pos, pos2, sizeof pos) == 0 && memcmp(nrm, nrm2, sizeof nrm) == 0,
          "a frustum holding every box changed the result");
}

static OceanDVec2 dxz[8 * NPTS];
static OceanDrawnSample dout[8 * NPTS];

/* The highest triangle of the mesh of pos over world (x, z), by Cramer's rule over every cell
 * within `reach` cells (the largest vertex displacement plus one); 0 with *covered 0 when
 * none. The triangulation is the header's: each cell split along (i+1, j)-(i, j+1). */
static double mesh_height(double x, double z, double reach, int *covered)
{
    double gx = (x - OX) / SP, gz = (z - OZ) / SP, best = 0.0;
    int i, j, h, i0 = (int)fmax(0.0, floor(gx - reach)), j0 = (int)fmax(0.0, floor(gz - reach));
    int i1 = (int)fmin(NX - 2, floor(gx + reach)), j1 = (int)fmin(NZ - 2, floor(gz + reach));
    *covered = 0;
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++)
            for (h = 0; h < 2; h++) {
                size_t a = (size_t)j * NX + (size_t)i, b = a + 1, c = a + NX, d = c + 1;
                size_t t0 = h ? b : a, t1 = h ? d : b, t2 = c;
                double ax = OX + pos[t0].x, az = OZ + pos[t0].z;
                /* In double: a float difference would round to 1e-7 of the cell. */
                double e1x = (double)pos[t1].x - pos[t0].x, e1z = (double)pos[t1].z - pos[t0].z;
                double e2x = (double)pos[t2].x - pos[t0].x, e2z = (double)pos[t2].z - pos[t0].z;
                double qx = x - ax, qz = z - az, det = e1x * e2z - e1z * e2x, u, v, y;
                if (det == 0.0)
                    continue;
                u = (qx * e2z - qz * e2x) / det;
                v = (e1x * qz - e1z * qx) / det;
                if (u < -1e-9 || v < -1e-9 || 1.0 - u - v < -1e-9)
                    continue;
                y = pos[t0].y + u * ((double)pos[t1].y - pos[t0].y) +
                    v * ((double)pos[t2].y - pos[t0].y);
                if (!*covered || y > best)
                    best = y;
                *covered = 1;
            }
    return best;
}

/* Drawn queries equal the triangles drawn from the evaluated grid (within 0.1 mm) at every
 * vertex, along both diagonals of every cell and at points scattered over and around the
 * grid; a scene never evaluated, or changed since, is refused with nothing written. */
static void test_drawn(OceanWtbScene *s, double t)
{
    size_t n = 0, k;
    int i, j, f, covered, misses = 0;
    double reach = 0.0, worst = 0.0;
    OceanEffects e;
    evaluate(s, t, pos, nrm, NULL);
    for (j = 0; j < NZ; j++)
        for (i = 0; i < NX; i++) {
            k = (size_t)j * NX + (size_t)i;
            reach = fmax(reach, hypot(pos[k].x - i * SP, pos[k].z - j * SP) / SP);
            dxz[n].x = OX + pos[k].x;
            dxz[n++].z = OZ + pos[k].z;
            if (i + 1 < NX && j + 1 < NZ)
                for (f = 1; f <= 3; f++) {
                    double w = 0.25 * f;
                    size_t b = k + 1, c = k + NX, d = c + 1;
                    dxz[n].x = OX + pos[k].x + w * (pos[d].x - pos[k].x);
                    dxz[n++].z = OZ + pos[k].z + w * (pos[d].z - pos[k].z);
                    dxz[n].x = OX + pos[b].x + w * (pos[c].x - pos[b].x);
                    dxz[n++].z = OZ + pos[b].z + w * (pos[c].z - pos[b].z);
                }
        }
    for (k = 0; k < 4000; k++) {
        /* A fixed low-discrepancy scatter over the grid and 4 m around it. */
        dxz[n].x = OX - 4.0 + fmod(0.618034 * (double)k, 1.0) * ((NX - 1) * SP + 8.0);
        dxz[n++].z = OZ - 4.0 + fmod(0.754878 * (double)k, 1.0) * ((NZ - 1) * SP + 8.0);
    }
    if (!OK(ocean_wtb_scene_heights_drawn(s, dxz, n, dout)))
        return;
    for (k = 0; k < n; k++) {
        double want = mesh_height(dxz[k].x, dxz[k].z, reach + 1.0, &covered);
        if (covered != (int)dout[k].covered)
            misses++;
        worst = fmax(worst, fabs(want - dout[k].height));
        CHECK(fabs(want - dout[k].height) <= 1e-4, "drawn at (%.4f, %.4f): %.6f, mesh %.6f",
              dxz[k].x, dxz[k].z, dout[k].height, want);
    }
    CHECK(misses == 0, "%d drawn queries disagree with the mesh on coverage", misses);
    printf("test_wtb.c: %zu drawn queries at t = %g: worst |drawn - mesh| %.3g m\n", n, t, worst);

    /* Any change of the scene needs a new evaluation first; nothing is written meanwhile. */
    OK(ocean_wtb_effects_default(&e));
    OK(ocean_wtb_scene_set_effects(s, &e));
    dout[0].height = 42.0;
    expect(ocean_wtb_scene_heights_drawn(s, dxz, 1, dout), OCEAN_STATUS_NOT_EVALUATED,
           "drawn query after a change");
    CHECK(dout[0].height == 42.0, "a refused drawn query wrote its output");
    evaluate(s, t, pos, nrm, NULL);
    OK(ocean_wtb_scene_heights_drawn(s, dxz, 1, dout));
}

static OceanDVec2 qxz[NPTS];
static OceanHeightSample qout[NPTS];

/* Height queries at the displaced grid points return the grid's heights within 1 mm: the
 * query inverts the horizontal displacement to a residual of at most 1 mm (checked below), and
 * with surface slopes below 0.5 that moves the height by at most 0.5 mm; the float grid itself
 * is exact to ~1e-6 m. */
static void test_heights(OceanWtbScene *s, double t, double lipschitz)
{
    size_t n = 0, k;
    int i, j;
    double worst = 0.0, max_res = 0.0, rest_err = 0.0;
    evaluate(s, t, pos, nrm, NULL);
    for (j = 2; j < NZ - 2; j++)
        for (i = 2; i < NX - 2; i++) {
            k = (size_t)j * NX + (size_t)i;
            qxz[n].x = OX + pos[k].x;
            qxz[n].z = OZ + pos[k].z;
            n++;
        }
    if (!OK(ocean_wtb_scene_heights_continuous(s, t, qxz, n, qout)))
        return;
    n = 0;
    for (j = 2; j < NZ - 2; j++)
        for (i = 2; i < NX - 2; i++) {
            const OceanHeightSample *q = &qout[n++];
            double nl;
            k = (size_t)j * NX + (size_t)i;
            worst = fmax(worst, fabs(q->height - pos[k].y));
            CHECK(fabs(q->height - pos[k].y) <= 1e-3,
                  "query at displaced (%d, %d): height %.6f, grid %.6f", i, j, q->height,
                  pos[k].y);
            /* The inversion's residual: the library stops at 10 micrometres (within 16
             * Newton steps); 1 mm is the most a buoy would notice. */
            CHECK(q->residual <= 1e-3, "query (%d, %d): residual %g", i, j, q->residual);
            max_res = fmax(max_res, q->residual);
            /* With a Lipschitz bound L for the inverse of p0 -> p0 + D(p0), the rest position
             * found is within L (residual + float rounding of the query, < 1e-5 m) of the grid
             * point's own. Only asked where L is known (see the callers). */
            rest_err = fmax(rest_err, hypot(q->rest.x - (OX + i * SP), q->rest.z - (OZ + j * SP)));
            if (lipschitz > 0.0)
                CHECK(hypot(q->rest.x - (OX + i * SP), q->rest.z - (OZ + j * SP)) <=
                          lipschitz * (q->residual + 1e-5),
                      "query at displaced (%d, %d): rest (%.5f, %.5f), residual %g", i, j,
                      q->rest.x - OX, q->rest.z - OZ, q->residual);
            nl = sqrt(q->normal.x * q->normal.x + q->normal.y * q->normal.y +
                      q->normal.z * q->normal.z);
            CHECK(fabs(nl - 1.0) <= 1e-9 && q->normal.y > 0.0, "query (%d, %d): normal", i, j);
        }
    printf("test_wtb.c: %zu height queries at t = %g: worst |query - grid| %.3g m, largest "
           "residual %.3g m, largest rest offset %.3g m\n",
           n, t, worst, max_res, rest_err);

    /* Outside the grid the water is at rest. */
    qxz[0].x = OX - 50.0;
    qxz[0].z = OZ + 10.0;
    OK(ocean_wtb_scene_heights_continuous(s, t, qxz, 1, qout));
    CHECK(qout[0].height == 0.0 && qout[0].normal.y == 1.0, "outside the grid: height %g",
          qout[0].height);
}

/* A single explicit train in a box covering the whole grid, over a deep sea with every effect
 * off: grid points past the smoothing must follow the closed-form trochoid (Eq. 6-7, deep
 * water omega = sqrt(g k), phase from world coordinates). Float tolerance as in test_waves.c:
 * 1e-4 m. */
static void test_explicit_train(void)
{
    OceanWaterGridDesc g = grid_desc();
    OceanWtbScene *s = NULL;
    OceanEffects e;
    OceanBoxDesc b = box_of(steady_wind(6.0, 1.0, 0.0, -10.0, -10.0, 90.0, 90.0, 1, 1));
    const OceanWaveDesc w = {0.3, 16.0, 1.0, 0.5, 0.7, INFINITY};
    uint32_t id = 0;
    double t = 7.25, worst = 0.0, len = sqrt(1.25), hx = 1.0 / len, hz = 0.5 / len;
    double k = 2.0 * PI / 16.0, omega = sqrt(G * k);
    int i, j;
    if (!OK(ocean_wtb_scene_create(&g, NULL, 0, &s)))
        return;
    OK(ocean_wtb_effects_default(&e));
    CHECK(e.refraction == OCEAN_REFRACTION_PHASE_SHIFT && e.shoaling == 1 && e.noise.enabled == 0,
          "defaults: refraction %u shoaling %u", (unsigned)e.refraction, (unsigned)e.shoaling);
    e.refraction = OCEAN_REFRACTION_OFF;
    e.shoaling = 0;
    OK(ocean_wtb_scene_set_effects(s, &e));
    OK(ocean_wtb_scene_add_box(s, &b, &w, 1, &id));
    evaluate(s, t, pos, nrm, NULL);
    for (j = 0; j < NZ; j++)
        for (i = 0; i < NX; i++) {
            size_t q = (size_t)j * NX + (size_t)i;
            double x0 = OX + i * SP, z0 = OZ + j * SP;
            double th = k * (hx * x0 + hz * z0) - omega * t + w.phase;
            double ex = i * SP - hx * w.amplitude * sin(th);
            double ey = w.amplitude * cos(th);
            double ez = j * SP - hz * w.amplitude * sin(th);
            double d = fmax(fabs(pos[q].x - ex), fmax(fabs(pos[q].y - ey), fabs(pos[q].z - ez)));
            worst = fmax(worst, d);
            CHECK(d <= 1e-4, "explicit train at (%d, %d): (%.6f, %.6f, %.6f), expected (%.6f, %.6f, %.6f)",
                  i, j, pos[q].x, pos[q].y, pos[q].z, ex, ey, ez);
        }
    printf("test_wtb.c: explicit train against the closed form: worst %.3g m\n", worst);
    /* One train with k*A = 2 pi 0.3 / 16 = 0.118 and a constant modulation of 1 over the grid:
     * the displacement's Jacobian is within 0.118 of the identity, so the inverse is
     * 1/(1 - 0.118) = 1.13-Lipschitz; 1.2 covers it. */
    test_heights(s, t, 1.2);
    ocean_wtb_scene_destroy(s);
}

/* Remove box B, then move box A: points outside the (new) box rest, points well inside move;
 * removing the last box leaves the whole grid at rest. */
static void test_move_and_remove(OceanWtbScene *s, uint32_t id_a, uint32_t id_b)
{
    OceanBoxDesc a = box_a();
    OceanFrameStats st;
    size_t count = 99;
    int pass;
    for (pass = 0; pass < 2; pass++) {
        int i, j, outside = 0, inside = 0, moved = 0, rest = 1;
        if (pass == 0) {
            OK(ocean_wtb_scene_remove_box(s, id_b));
        } else {
            a.wind.origin_x += 30.0;
            a.wind.origin_z += 20.0;
            OK(ocean_wtb_scene_update_box(s, id_a, &a, NULL, 0));
        }
        evaluate(s, 12.5, pos, nrm, &st);
        CHECK(st.alive == 1 && st.trains == 1, "pass %d: alive %zu trains %zu", pass, st.alive,
              st.trains);
        /* The moved box's action points are recomputed. */
        if (pass == 1)
            CHECK(st.rebuilt == 1, "moved box: rebuilt %zu", st.rebuilt);
        for (j = 0; j < NZ; j++)
            for (i = 0; i < NX; i++) {
                size_t k = (size_t)j * NX + (size_t)i;
                if (outside_box(&a.wind, i, j)) {
                    outside++;
                    rest &= at_rest(pos, nrm, i, j);
                } else if (deep_inside_box(&a.wind, i, j)) {
                    inside++;
                    moved += fabs(pos[k].y) > 0.05;
                }
            }
        CHECK(outside > 100 && rest, "pass %d: %d points outside the box, all at rest: %d", pass,
              outside, rest);
        /* A 7 m/s train (amplitude ~0.52 m) lifts most interior points by more than 5 cm. */
        CHECK(inside > 100 && moved > inside / 2, "pass %d: %d of %d interior points moved",
              pass, moved, inside);
    }
    OK(ocean_wtb_scene_box_count(s, &count));
    CHECK(count == 1, "box count %zu", count);
    OK(ocean_wtb_scene_remove_box(s, id_a));
    expect(ocean_wtb_scene_remove_box(s, id_a), OCEAN_STATUS_NOT_FOUND, "remove twice");
    expect(ocean_wtb_scene_update_box(s, id_b, &a, NULL, 0), OCEAN_STATUS_NOT_FOUND,
           "update removed");
    evaluate(s, 12.5, pos, nrm, &st);
    {
        int i, j, rest = 1;
        for (j = 0; j < NZ; j++)
            for (i = 0; i < NX; i++)
                rest &= at_rest(pos, nrm, i, j);
        CHECK(rest && st.alive == 0, "no boxes: grid not at rest (alive %zu)", st.alive);
    }
}

/* ------------------------------------------------------------------------------------------ */
/* Errors: status, message, and nothing written.                                              */

static void test_create_errors(void)
{
    static char storage[16];
    OceanWtbScene *const SENT = (OceanWtbScene *)(void *)storage;
    OceanWtbScene *s = SENT;
    OceanWaterGridDesc g;
    float bad[NPTS];

#define CREATE_FAILS(gd, h, n, want, what)                                                 \
    do {                                                                                   \
        s = SENT;                                                                          \
        expect(ocean_wtb_scene_create((gd), (h), (n), &s), (want), (what));                   \
        CHECK(s == SENT, "%s wrote *out", (what));                                         \
    } while (0)

    g = grid_desc();
    CREATE_FAILS(NULL, terrain, NPTS, OCEAN_STATUS_NULL_POINTER, "create(grid NULL)");
    expect(ocean_wtb_scene_create(&g, terrain, NPTS, NULL), OCEAN_STATUS_NULL_POINTER,
           "create(out NULL)");
    g.nx = 0;
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_EMPTY, "create(nx 0)");
    g = grid_desc();
    g.nz = 1; /* a water grid needs a neighbour along both axes */
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_INVALID_ARGUMENT, "create(nz 1)");
    g = grid_desc();
    g.nx = 5000; /* documented cap: 4096 per side */
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_INVALID_ARGUMENT, "create(nx 5000)");
    g = grid_desc();
    g.nx = SIZE_MAX;
    g.nz = 2;
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_LENGTH_OVERFLOW, "create(nx*nz overflows)");
    g = grid_desc();
    g.spacing = NAN;
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_NON_FINITE, "create(spacing NaN)");
    g.spacing = 0.0;
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_INVALID_ARGUMENT, "create(spacing 0)");
    g = grid_desc();
    g.origin_z = -INFINITY;
    CREATE_FAILS(&g, NULL, 0, OCEAN_STATUS_NON_FINITE, "create(origin -inf)");
    g = grid_desc();
    CREATE_FAILS(&g, terrain, NPTS - 1, OCEAN_STATUS_LENGTH_MISMATCH, "create(terrain short)");
    CREATE_FAILS(&g, terrain, NPTS + 1, OCEAN_STATUS_LENGTH_MISMATCH, "create(terrain long)");
    CREATE_FAILS(&g, NULL, NPTS, OCEAN_STATUS_NULL_POINTER, "create(terrain NULL, len)");
    memcpy(bad, terrain, sizeof bad);
    bad[77] = NAN;
    CREATE_FAILS(&g, bad, NPTS, OCEAN_STATUS_NON_FINITE, "create(terrain NaN)");
    CHECK(strstr(last_error(), "77") != NULL, "terrain NaN message lacks its index: %s",
          last_error());
#undef CREATE_FAILS
}

static void test_box_errors(OceanWtbScene *s)
{
    static OceanWaveDesc many[65];
    const OceanWaveDesc steep = {3.0, 16.0, 1.0, 0.0, 0.0, INFINITY};    /* k*A = 1.18 */
    const OceanWaveDesc half[2] = {{1.5, 16.0, 1.0, 0.0, 0.0, INFINITY}, /* k*A = 0.59 each */
                                   {1.5, 16.0, 0.0, 1.0, 0.0, INFINITY}};
    const OceanWaveDesc nan_train = {NAN, 16.0, 1.0, 0.0, 0.0, INFINITY};
    OceanBoxDesc d;
    uint32_t id = 0xdeadbeefu;
    size_t before = 0, after = 0, i;

    for (i = 0; i < 65; i++) {
        OceanWaveDesc w = {0.01, 16.0, 1.0, 0.0, 0.0, INFINITY};
        many[i] = w;
    }
    OK(ocean_wtb_scene_box_count(s, &before));

#define ADD_FAILS(desc, tr, n, want, what)                                                  \
    do {                                                                                    \
        id = 0xdeadbeefu;                                                                   \
        expect(ocean_wtb_scene_add_box(s, (desc), (tr), (n), &id), (want), (what));            \
        CHECK(id == 0xdeadbeefu, "%s wrote *out_id", (what));                               \
    } while (0)
#define BAD_FIELD(field, value, want)                                                       \
    do {                                                                                    \
        d = box_a();                                                                        \
        d.field = (value);                                                                  \
        ADD_FAILS(&d, NULL, 0, (want), "add(" #field " = " #value ")");                    \
    } while (0)

    d = box_a();
    expect(ocean_wtb_scene_add_box(NULL, &d, NULL, 0, &id), OCEAN_STATUS_NULL_POINTER,
           "add(scene NULL)");
    ADD_FAILS(NULL, NULL, 0, OCEAN_STATUS_NULL_POINTER, "add(desc NULL)");
    expect(ocean_wtb_scene_add_box(s, &d, NULL, 0, NULL), OCEAN_STATUS_NULL_POINTER,
           "add(out_id NULL)");
    BAD_FIELD(wind.speed, 0.0, OCEAN_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(last_error(), "speed") != NULL, "zero wind message: %s", last_error());
    BAD_FIELD(wind.speed, -3.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.speed, NAN, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.speed, 1000.0, OCEAN_STATUS_INVALID_ARGUMENT);
    d = box_a();
    d.wind.direction_x = 0.0;
    d.wind.direction_z = 0.0;
    ADD_FAILS(&d, NULL, 0, OCEAN_STATUS_INVALID_ARGUMENT, "add(zero direction)");
    BAD_FIELD(wind.direction_z, INFINITY, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.width, 0.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.fetch, INFINITY, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.fetch, -1.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.origin_x, NAN, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.start, -INFINITY, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.build_up, -1.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.sustain, NAN, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.sustain, -INFINITY, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.sustain, -2.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.decay, INFINITY, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(wind.trains, 0u, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(wind.trains, 9u, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(smoothing, -1.0, OCEAN_STATUS_INVALID_ARGUMENT);
    BAD_FIELD(smoothing, NAN, OCEAN_STATUS_NON_FINITE);
    BAD_FIELD(has_recovery, 2, OCEAN_STATUS_INVALID_ARGUMENT);
    d = box_a();
    d.has_recovery = 1;
    d.recovery = NAN;
    ADD_FAILS(&d, NULL, 0, OCEAN_STATUS_NON_FINITE, "add(recovery NaN)");
    d.recovery = -5.0;
    ADD_FAILS(&d, NULL, 0, OCEAN_STATUS_INVALID_ARGUMENT, "add(recovery < 0)");
    /* 2^24 grid spacings is the documented cap on a box's extent. */
    BAD_FIELD(wind.fetch, 2e7 * SP, OCEAN_STATUS_INVALID_ARGUMENT);

    /* Wholly outside the grid: 200 m to the -x side, blowing away from it; and a box whose
     * fetch ends 1 m before the grid's edge. */
    d = box_of(steady_wind(7.0, -1.0, 0.0, -200.0, 0.0, 50.0, 60.0, 1, 3));
    ADD_FAILS(&d, NULL, 0, OCEAN_STATUS_OUTSIDE_GRID, "add(box outside the grid)");
    CHECK(strstr(last_error(), "outside") != NULL, "outside message: %s", last_error());
    d = box_of(steady_wind(7.0, 1.0, 0.0, -61.0 * SP, 0.0, 50.0, 60.0 * SP, 1, 3));
    ADD_FAILS(&d, NULL, 0, OCEAN_STATUS_OUTSIDE_GRID, "add(box ending before the grid)");
    /* Touching the grid's edge counts as reaching it (a grid point lies on the box's edge). */
    d = box_of(steady_wind(7.0, 1.0, 0.0, -60.0 * SP, 0.0, 50.0, 60.0 * SP, 1, 3));
    if (OK(ocean_wtb_scene_add_box(s, &d, NULL, 0, &id)))
        OK(ocean_wtb_scene_remove_box(s, id));

    /* Explicit trains. */
    d = box_a();
    ADD_FAILS(&d, NULL, 1, OCEAN_STATUS_NULL_POINTER, "add(trains NULL, n 1)");
    ADD_FAILS(&d, many, 65, OCEAN_STATUS_INVALID_ARGUMENT, "add(65 trains)");
    ADD_FAILS(&d, many, SIZE_MAX, OCEAN_STATUS_LENGTH_OVERFLOW, "add(n_trains SIZE_MAX)");
    ADD_FAILS(&d, &steep, 1, OCEAN_STATUS_TOO_STEEP, "add(train k*A > 1)");
    ADD_FAILS(&d, half, 2, OCEAN_STATUS_TOO_STEEP, "add(summed k*A > 1)");
    ADD_FAILS(&d, &nan_train, 1, OCEAN_STATUS_NON_FINITE, "add(train NaN)");
    CHECK(strstr(last_error(), "trains[0]") != NULL, "train message: %s", last_error());
    /* 64 trains is the cap, and is accepted. */
    if (OK(ocean_wtb_scene_add_box(s, &d, many, 64, &id)))
        OK(ocean_wtb_scene_remove_box(s, id));

    OK(ocean_wtb_scene_box_count(s, &after));
    CHECK(before == after, "failed adds changed the box count: %zu -> %zu", before, after);
#undef BAD_FIELD
#undef ADD_FAILS
}

/* Failed updates, effect and budget changes, and terrain changes leave the scene as it was:
 * the evaluation stays bit-identical. */
static void test_unchanged_after_errors(OceanWtbScene *s, uint32_t id_a)
{
    const double t = 3.5;
    OceanBoxDesc d = box_a();
    OceanEffects e;
    float bad[NPTS];
    evaluate(s, t, pos, nrm, NULL);

    d.wind.speed = NAN;
    expect(ocean_wtb_scene_update_box(s, id_a, &d, NULL, 0), OCEAN_STATUS_NON_FINITE, "update(NaN)");
    d = box_of(steady_wind(7.0, -1.0, 0.0, -200.0, 0.0, 50.0, 60.0, 1, 3));
    expect(ocean_wtb_scene_update_box(s, id_a, &d, NULL, 0), OCEAN_STATUS_OUTSIDE_GRID,
           "update(outside)");
    d = box_a();
    expect(ocean_wtb_scene_update_box(s, 999999u, &d, NULL, 0), OCEAN_STATUS_NOT_FOUND,
           "update(unknown id)");
    expect(ocean_wtb_scene_update_box(s, id_a, NULL, NULL, 0), OCEAN_STATUS_NULL_POINTER,
           "update(desc NULL)");
    expect(ocean_wtb_scene_remove_box(s, 999999u), OCEAN_STATUS_NOT_FOUND, "remove(unknown id)");
    expect(ocean_wtb_scene_remove_box(NULL, id_a), OCEAN_STATUS_NULL_POINTER, "remove(scene NULL)");

    OK(ocean_wtb_effects_default(&e));
    expect(ocean_wtb_scene_set_effects(s, NULL), OCEAN_STATUS_NULL_POINTER, "effects(NULL)");
    e.refraction = 3;
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_INVALID_ARGUMENT, "effects(refraction 3)");
    OK(ocean_wtb_effects_default(&e));
    e.shoaling = 2;
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_INVALID_ARGUMENT, "effects(shoaling 2)");
    OK(ocean_wtb_effects_default(&e));
    e.noise.enabled = 1;
    e.noise.amplitude = NAN;
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_NON_FINITE, "effects(noise NaN)");
    e.noise.amplitude = -0.1;
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_INVALID_ARGUMENT, "effects(noise < 0)");
    OK(ocean_wtb_effects_default(&e));
    e.irregular.enabled = 1;
    e.irregular.scale = 2.0; /* a share, at most 1 */
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_INVALID_ARGUMENT, "effects(irregular 2)");
    OK(ocean_wtb_effects_default(&e));
    e.beach.enabled = 1;
    e.beach.max_depth_share = 0.0;
    expect(ocean_wtb_scene_set_effects(s, &e), OCEAN_STATUS_INVALID_ARGUMENT, "effects(beach 0)");

    expect(ocean_wtb_scene_set_budget_seconds(s, NAN), OCEAN_STATUS_NON_FINITE, "budget(NaN)");
    expect(ocean_wtb_scene_set_budget_seconds(s, INFINITY), OCEAN_STATUS_NON_FINITE, "budget(inf)");
    expect(ocean_wtb_scene_set_budget_seconds(s, -1.0), OCEAN_STATUS_INVALID_ARGUMENT, "budget(-1)");
    expect(ocean_wtb_scene_set_budget_explicit(s, 1, NULL), OCEAN_STATUS_NULL_POINTER,
           "budget(explicit NULL)");

    expect(ocean_wtb_scene_set_terrain(s, terrain, NPTS - 1), OCEAN_STATUS_LENGTH_MISMATCH,
           "terrain(short)");
    expect(ocean_wtb_scene_set_terrain(s, NULL, NPTS), OCEAN_STATUS_NULL_POINTER, "terrain(NULL)");
    memcpy(bad, terrain, sizeof bad);
    bad[NPTS - 1] = INFINITY;
    expect(ocean_wtb_scene_set_terrain(s, bad, NPTS), OCEAN_STATUS_NON_FINITE, "terrain(inf)");

    evaluate(s, t, pos2, nrm2, NULL);
    CHECK(memcmp(pos, pos2, sizeof pos) == 0 && memcmp(nrm, nrm2, sizeof nrm) == 0,
          "failed calls changed the scene");

    /* Disabled effects' parameters are ignored, as documented: NaN noise amplitude is fine
     * while the noise is off. */
    OK(ocean_wtb_effects_default(&e));
    e.noise.amplitude = NAN;
    OK(ocean_wtb_scene_set_effects(s, &e));

    /* A deep sea has no island: some former land points now move. Then restore. */
    OK(ocean_wtb_scene_set_terrain(s, NULL, 0));
    evaluate(s, t, pos2, nrm2, NULL);
    {
        int i, j, moved = 0;
        for (j = 0; j < NZ; j++)
            for (i = 0; i < NX; i++)
                if (is_island(i, j))
                    moved += fabs(pos2[(size_t)j * NX + (size_t)i].y) > 1e-3f;
        CHECK(moved > 0, "without terrain the island's points still rest");
    }
    OK(ocean_wtb_scene_set_terrain(s, terrain, NPTS));
    evaluate(s, t, pos2, nrm2, NULL);
    CHECK(memcmp(pos, pos2, sizeof pos) == 0, "restoring the terrain did not restore the surface");
}

static void test_budget(OceanWtbScene *s)
{
    OceanFrameStats st;
    OceanEffects e;
    int i, j, rest = 1;
    /* Nothing fits in a picosecond, not even one train: the grid rests. */
    OK(ocean_wtb_scene_set_budget_seconds(s, 1e-12));
    evaluate(s, 2.0, pos, nrm, &st);
    CHECK(st.max_trains == 0 && st.trains == 0, "tiny budget: max_trains %zu trains %zu",
          st.max_trains, st.trains);
    for (j = 0; j < NZ; j++)
        for (i = 0; i < NX; i++)
            rest &= at_rest(pos, nrm, i, j);
    CHECK(rest, "tiny budget: grid not at rest");
    /* Explicitly one train per box (each box's largest): 2 of the 3 trains run. */
    OK(ocean_wtb_effects_default(&e));
    OK(ocean_wtb_scene_set_budget_explicit(s, 1, &e));
    evaluate(s, 2.0, pos, nrm, &st);
    CHECK(st.max_trains == 1 && st.trains == 2, "explicit: max_trains %zu trains %zu",
          st.max_trains, st.trains);
    OK(ocean_wtb_scene_set_budget_unlimited(s));
    evaluate(s, 2.0, pos, nrm, &st);
    CHECK(st.max_trains == SIZE_MAX && st.trains == 3 && st.effects.shoaling == 1,
          "unlimited: max_trains %zu trains %zu", st.max_trains, st.trains);
}

static void test_evaluate_errors(OceanWtbScene *s)
{
    static OceanVec3 big[2 * NPTS];
    OceanCamera m, cam;
    OceanFrameStats st;
    OceanDVec2 xz[4] = {{OX, OZ}, {OX + 1, OZ}, {OX + 2, OZ}, {OX + 3, OZ}};
    OceanHeightSample out[4];
    static const OceanHeightSample zero_sample;

#define EVAL_FAILS(call, want, what)                                                        \
    do {                                                                                    \
        fill(pos, NPTS);                                                                    \
        fill(nrm, NPTS);                                                                    \
        expect((call), (want), (what));                                                     \
        CHECK(untouched(pos, NPTS) && untouched(nrm, NPTS), "%s wrote outputs", (what));    \
    } while (0)

    EVAL_FAILS(ocean_wtb_scene_evaluate(NULL, 0.0, NULL, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_NULL_POINTER, "evaluate(scene NULL)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, NULL, nrm, NPTS, NULL),
               OCEAN_STATUS_NULL_POINTER, "evaluate(out_pos NULL)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, pos, NULL, NPTS, NULL),
               OCEAN_STATUS_NULL_POINTER, "evaluate(out_normal NULL)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, pos, nrm, 0, NULL), OCEAN_STATUS_EMPTY,
               "evaluate(n 0)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, pos, nrm, NPTS - 1, NULL),
               OCEAN_STATUS_LENGTH_MISMATCH, "evaluate(n != nx*nz)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, pos, nrm, SIZE_MAX, NULL),
               OCEAN_STATUS_LENGTH_OVERFLOW, "evaluate(n SIZE_MAX)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, NAN, NULL, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_NON_FINITE, "evaluate(time NaN)");
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, -INFINITY, NULL, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_NON_FINITE, "evaluate(time -inf)");
    /* The stats struct inside the positions buffer (an 8-aligned address in it). */
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, NULL, pos, nrm, NPTS,
                                    (OceanFrameStats *)(void *)((char *)pos + 24)),
               OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(stats overlaps out_pos)");
    /* Normals starting inside the positions. */
    fill(big, 2 * NPTS);
    expect(ocean_wtb_scene_evaluate(s, 0.0, NULL, big, big + NPTS - 1, NPTS, NULL),
           OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(overlap)");
    CHECK(untouched(big, 2 * NPTS), "overlap wrote outputs");
    {
        const double eye[3] = {OX, 50.0, OZ}, dir[3] = {0.0, -1.0, 0.0};
        m = camera_looking(eye, dir, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE);
    }
    cam = m;
    memset(cam.projection, 0, sizeof cam.projection);
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, &cam, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(zero projection)");
    cam.projection[5] = NAN;
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, &cam, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_NON_FINITE, "evaluate(projection NaN)");
    cam = m;
    cam.depth_convention = 7;
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, &cam, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(depth convention 7)");
    /* A [0, 1] matrix declared reversed puts its far plane before its near plane. */
    cam = m;
    cam.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED;
    EVAL_FAILS(ocean_wtb_scene_evaluate(s, 0.0, &cam, pos, nrm, NPTS, NULL),
               OCEAN_STATUS_INVALID_ARGUMENT, "evaluate(forward matrix declared reversed)");
    /* Adjacent, non-overlapping buffers are fine. */
    OK(ocean_wtb_scene_evaluate(s, 0.0, &m, big, big + NPTS, NPTS, &st));
#undef EVAL_FAILS

#define HEIGHTS_FAILS(call, want, what)                                                      \
    do {                                                                                     \
        memset(out, 0, sizeof out);                                                          \
        expect((call), (want), (what));                                                      \
        CHECK(memcmp(&out[0], &zero_sample, sizeof zero_sample) == 0 &&                      \
                  memcmp(&out[3], &zero_sample, sizeof zero_sample) == 0,                    \
              "%s wrote outputs", (what));                                                   \
    } while (0)
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(NULL, 0.0, xz, 4, out), OCEAN_STATUS_NULL_POINTER,
                  "heights(scene NULL)");
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, 0.0, NULL, 4, out), OCEAN_STATUS_NULL_POINTER,
                  "heights(xz NULL)");
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, 0.0, xz, 4, NULL), OCEAN_STATUS_NULL_POINTER,
                  "heights(out NULL)");
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, 0.0, xz, 0, out), OCEAN_STATUS_EMPTY, "heights(n 0)");
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, 0.0, xz, SIZE_MAX, out), OCEAN_STATUS_LENGTH_OVERFLOW,
                  "heights(n SIZE_MAX)");
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, INFINITY, xz, 4, out), OCEAN_STATUS_NON_FINITE,
                  "heights(time inf)");
    xz[3].z = NAN;
    HEIGHTS_FAILS(ocean_wtb_scene_heights_continuous(s, 0.0, xz, 4, out), OCEAN_STATUS_NON_FINITE,
                  "heights(xz NaN)");
    CHECK(strstr(last_error(), "xz[3]") != NULL, "heights message lacks the index: %s",
          last_error());
    xz[3].z = OZ;
    /* Output over the input. */
    expect(ocean_wtb_scene_heights_continuous(s, 0.0, xz, 4, (OceanHeightSample *)(void *)xz),
           OCEAN_STATUS_INVALID_ARGUMENT, "heights(overlap)");
    CHECK(xz[3].z == OZ && xz[0].x == OX, "overlapping heights wrote the input");
#undef HEIGHTS_FAILS

    /* Functions that return no status leave the last error alone. */
    expect(ocean_wtb_scene_remove_box(s, 424242u), OCEAN_STATUS_NOT_FOUND, "remove(unknown)");
    ocean_wtb_scene_destroy(NULL);
    CHECK(last_error()[0] != '\0', "destroy(NULL) cleared the last error");
    {
        size_t c = 0;
        OK(ocean_wtb_scene_box_count(s, &c));
        CHECK(last_error()[0] == '\0', "success left the last error \"%s\"", last_error());
    }
}

/* Scenario 1 at another spacing: the surface checks and the height queries. */
static void scenario_at_spacing(double spacing)
{
    OceanWaterGridDesc g;
    OceanWtbScene *s = NULL;
    OceanBoxDesc a, b;
    OceanFrameStats st;
    uint32_t id = 0;
    char what[64];
    SP = spacing;
    g = grid_desc();
    a = box_a();
    b = box_b();
    snprintf(what, sizeof what, "scenario 1 at %g m", spacing);
    make_terrain();
    if (OK(ocean_wtb_scene_create(&g, terrain, NPTS, &s)) && s != NULL) {
        OK(ocean_wtb_scene_add_box(s, &a, NULL, 0, &id));
        OK(ocean_wtb_scene_add_box(s, &b, NULL, 0, &id));
        if (evaluate(s, 12.5, pos, nrm, &st)) {
            CHECK(st.alive == 2 && st.trains == 3, "%s: alive %zu trains %zu", what, st.alive,
                  st.trains);
            check_surface(what, 12.5);
        }
        test_heights(s, 12.5, 0.0);
        test_heights(s, 1000.25, 0.0);
    }
    ocean_wtb_scene_destroy(s);
    SP = 1.0;
    make_terrain();
}

int main(void)
{
    OceanWaterGridDesc g = grid_desc();
    OceanWtbScene *s = NULL;
    OceanBoxDesc a = box_a(), b = box_b();
    uint32_t id_a = 0, id_b = 0;
    OceanFrameStats st;
    static const double times[] = {0.0, 1.7, 12.5, 1000.25};
    size_t i;

    scenario_at_spacing(0.5);
    scenario_at_spacing(2.0);
    make_terrain();
    if (!OK(ocean_wtb_scene_create(&g, terrain, NPTS, &s)) || s == NULL) {
        fprintf(stderr, "test_wtb.c: cannot continue without a scene\n");
        return 1;
    }
    {
        /* A scene never evaluated has no drawn surface to answer for. */
        OceanDVec2 p = {OX + 10.0, OZ + 10.0};
        OceanDrawnSample d = {0};
        expect(ocean_wtb_scene_heights_drawn(s, &p, 1, &d), OCEAN_STATUS_NOT_EVALUATED,
               "drawn query before any evaluation");
    }
    OK(ocean_wtb_scene_add_box(s, &a, NULL, 0, &id_a));
    OK(ocean_wtb_scene_add_box(s, &b, NULL, 0, &id_b));
    CHECK(id_a != id_b, "two boxes share id %u", (unsigned)id_a);

    for (i = 0; i < sizeof times / sizeof times[0]; i++) {
        if (evaluate(s, times[i], pos, nrm, &st)) {
            /* Both steady winds are alive at every time; 1 + 2 trains. */
            CHECK(st.alive == 2 && st.culled == 0 && st.trains == 3,
                  "t=%g: alive %zu culled %zu trains %zu", times[i], st.alive, st.culled,
                  st.trains);
            check_surface("scenario 1", times[i]);
        }
    }
    /* Frame independence: evaluating an earlier time again gives the same result. */
    evaluate(s, 1.7, pos, nrm, NULL);
    evaluate(s, 1.7, pos2, nrm2, NULL);
    CHECK(memcmp(pos, pos2, sizeof pos) == 0, "re-evaluating t = 1.7 differs");

    test_culling(s, 12.5);
    /* No rest-position bound here: it would need a Lipschitz constant of the inverse map, that
     * is a lower bound on the Jacobian near the island's ramps, which this test does not
     * derive. */
    test_heights(s, 12.5, 0.0);
    test_heights(s, 1000.25, 0.0);
    test_drawn(s, 12.5);
    test_drawn(s, 1000.25);
    test_budget(s);
    test_create_errors();
    test_box_errors(s);
    test_unchanged_after_errors(s, id_a);
    test_evaluate_errors(s);
    test_explicit_train();
    test_move_and_remove(s, id_a, id_b);

    ocean_wtb_scene_destroy(s);
    ocean_wtb_scene_destroy(NULL); /* NULL-safe */

    printf("test_wtb.c: library %s, %d checks, %d failures; bound on |y| %.4f m (Eq. 1, "
           "shoaling cap 1.5)\n",
           ocean_version(), checks, failures, bound());
    return failures == 0 ? 0 : 1;
}
