/*
 * C11 + POSIX threads stress test of the thread-safety promises of the ocean C ABI, linked
 * against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -pthread -Wall -Wextra -Werror -pedantic -I include tests/c/test_threads.c \
 *      libocean.a ...
 * and by .ci/sanitize again under ThreadSanitizer and valgrind (see docs/sanitizers.md).
 *
 * What include/ocean.h promises: every function may be called from any thread; a const handle
 * may be used by many threads at once (OceanWaves, OceanSpectrum, OceanLighting, OceanSkyMap,
 * OceanReliefMap, OceanReliefCones, OceanReliefMips, OceanSao, OceanShaderExport are each
 * documented as immutable and shareable); an OceanWtbScene may be used by several threads at once
 * (a lock inside serialises the calls); the last-error message is per thread.
 *
 * Phases:
 * 1. Cold start: before the main thread calls the library at all, 8 threads make the first
 *    calls at once (the version, the shader names, whose table is built lazily, the thread's
 *    error message, a wave grid large enough to start the worker pool, a spectrum).
 * 2. Shared handles: 8 threads use one set of handles made by the main thread (one of each
 *    kind above, and one scene), each call many times over several rounds.
 * 3. Own handles: at the same time as phase 2, 8 threads each create, use and destroy their
 *    own handles of every kind, scenes included (create, add boxes, evaluate, height queries,
 *    move and remove a box), every round, and provoke a failure whose message names a
 *    thread-specific index.
 * Every result, status and error message is appended to a per-thread byte log and compared
 * bit for bit with the log of the same calls made on the main thread alone (before the
 * threads start, or, for phase 1, after they end): the library is deterministic, so any
 * difference is a data race, a lost update or a message leaking between threads.
 *
 * The worker threads never touch check.h's counters (they are plain ints); the main thread
 * checks each worker's result after joining it.
 *
 * OCEAN_THREADS_ROUNDS=<n> (default 4) sets the rounds per thread; the race detectors run
 * fewer. Prints a summary; exits 0 only if every check passed.
 */
#define _POSIX_C_SOURCE 200809L

#include "ocean.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

static const double PI = 3.14159265358979323846;

#define THREADS 8      /* per phase */
#define TIMES 3        /* distinct times (or variants) the rounds cycle through */
#define DEFAULT_ROUNDS 4

/* ------------------------------------------------------------------------------------------ */
/* The byte log, and calls that record into it.                                               */

typedef struct Log {
    unsigned char *bytes;
    size_t len, cap;
} Log;

/* One thread's (or the main thread's reference) record of a job. */
typedef struct Worker {
    Log log;
    long calls;      /* library calls made */
    long failures;   /* unexpected statuses, or a success that left a message */
    char first[512]; /* the first of them */
    char message[256]; /* the message of the last call that was to fail */
} Worker;

static void log_bytes(Worker *w, const void *p, size_t n)
{
    if (w->log.len + n > w->log.cap) {
        size_t cap = w->log.cap ? w->log.cap : 4096;
        unsigned char *b;
        while (cap < w->log.len + n)
            cap *= 2;
        b = realloc(w->log.bytes, cap);
        if (b == NULL) {
            fprintf(stderr, "out of memory\n");
            exit(2);
        }
        w->log.bytes = b;
        w->log.cap = cap;
    }
    memcpy(w->log.bytes + w->log.len, p, n);
    w->log.len += n;
}

static void log_u32(Worker *w, uint32_t v) { log_bytes(w, &v, sizeof v); }
static void log_u64(Worker *w, uint64_t v) { log_bytes(w, &v, sizeof v); }
static void log_f64(Worker *w, double v) { log_bytes(w, &v, sizeof v); }
static void log_str(Worker *w, const char *s)
{
    size_t n = strlen(s);
    log_u64(w, n);
    log_bytes(w, s, n);
}

/* Floats and doubles are logged by their bits: -0.0 and NaN payloads count. Structs are logged
 * member by member where they have padding (whose bytes are unspecified). */
static void log_vec3s(Worker *w, const OceanVec3 *v, size_t n) { log_bytes(w, v, n * sizeof *v); }
static void log_dvec3s(Worker *w, const OceanDVec3 *v, size_t n)
{
    log_bytes(w, v, n * sizeof *v);
}
static void log_rgb(Worker *w, OceanRgb c)
{
    log_f64(w, c.r);
    log_f64(w, c.g);
    log_f64(w, c.b);
}
static void log_dvec3(Worker *w, OceanDVec3 v)
{
    log_f64(w, v.x);
    log_f64(w, v.y);
    log_f64(w, v.z);
}

static void fail(Worker *w, const char *fmt, const char *what, unsigned s, const char *msg)
{
    w->failures++;
    if (w->first[0] == '\0')
        snprintf(w->first, sizeof w->first, fmt, what, s, msg);
}

/* A call that must succeed: logs its status, and fails unless it is OK with no message. */
#define CALL(w, call) call_ok((w), (call), #call)
static int call_ok(Worker *w, OceanStatus s, const char *what)
{
    const char *m = ocean_last_error_message();
    w->calls++;
    log_u32(w, (uint32_t)s);
    if (s != OCEAN_STATUS_OK)
        fail(w, "%s: status %u: %s", what, (unsigned)s, m);
    else if (m[0] != '\0')
        fail(w, "%s: success (%u) left the message \"%s\"", what, (unsigned)s, m);
    return s == OCEAN_STATUS_OK;
}

/* A call that must fail with `want`: logs its status and this thread's message. */
#define CALL_FAILS(w, call, want) call_fails((w), (call), (want), #call)
static void call_fails(Worker *w, OceanStatus s, OceanStatus want, const char *what)
{
    const char *m = ocean_last_error_message();
    w->calls++;
    log_u32(w, (uint32_t)s);
    log_str(w, m);
    snprintf(w->message, sizeof w->message, "%s", m);
    if (s != want)
        fail(w, "%s: status %u, expected a failure: %s", what, (unsigned)s, m);
}

static void worker_reset(Worker *w)
{
    w->log.len = 0;
    w->calls = 0;
    w->failures = 0;
    w->first[0] = '\0';
    w->message[0] = '\0';
}

static void worker_free(Worker *w)
{
    free(w->log.bytes);
    memset(w, 0, sizeof *w);
}

/* Offset of the first differing byte of two logs, or -1 if they are equal. */
static long log_diff(const Log *a, const Log *b)
{
    size_t i, n = a->len < b->len ? a->len : b->len;
    for (i = 0; i < n; i++)
        if (a->bytes[i] != b->bytes[i])
            return (long)i;
    return a->len == b->len ? -1 : (long)n;
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n);
    if (p == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return p;
}

/* ------------------------------------------------------------------------------------------ */
/* Inputs, made once by the main thread and read by every thread.                            */

#define NPOINTS 256
#define GRID_NX 48
#define GRID_NZ 32
#define COLD_NX 256 /* the cold-start grid: 2 tasks of the worker pool */
#define COLD_NZ 128
#define NDIRS 16
#define NSEA 48
#define SKY_SIZE 32
#define RELIEF_SHARED 32
#define RELIEF_OWN 16
#define NRAYS 48
#define SAO_W 64
#define SAO_H 48
#define SAO_GUARD 8
#define SAO_IN ((size_t)SAO_W * SAO_H)
#define SAO_OUT ((size_t)(SAO_W - 2 * SAO_GUARD) * (SAO_H - 2 * SAO_GUARD))
#define SCENE_N 32
#define SCENE_PTS (SCENE_N * SCENE_N)
#define NQUERY 64

static const double TIME[TIMES] = {0.25, 7.5, 1234.5};

static OceanDVec2 points[NPOINTS];
static OceanDVec3 dirs[NDIRS];
static OceanSeaColorInput sea_inputs[NSEA];
static OceanReliefRay rays[NRAYS];
static OceanReliefPoint relief_points[NRAYS];
static OceanDVec2 queries[NQUERY];
static const OceanReliefMethod RELAXED = {NULL, OCEAN_RELIEF_TRACER_RELAXED, 15, 6,
                                          OCEAN_RELIEF_SEARCH_LAST_STEP};

static OceanDVec3 dvec3(double x, double y, double z)
{
    OceanDVec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static OceanDVec3 unit(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return dvec3(x / l, y / l, z / l);
}

static void make_inputs(void)
{
    int i;
    for (i = 0; i < NPOINTS; i++) {
        points[i].x = 37.0 * sin(0.37 * i) + 0.11 * i;
        points[i].z = -21.0 * cos(0.23 * i) + 0.07 * i;
    }
    for (i = 0; i < NDIRS; i++) {
        double el = -0.3 + 1.8 * i / NDIRS, az = 2.0 * PI * i / NDIRS;
        dirs[i] = unit(cos(el) * cos(az), sin(el), cos(el) * sin(az));
    }
    for (i = 0; i < NSEA; i++) {
        double a = 2.0 * PI * i / NSEA;
        sea_inputs[i].v = unit(cos(a), 0.05 + 0.5 * (i % 5) / 5.0, sin(a));
        sea_inputs[i].n = unit(0.1 * sin(3.0 * a), 1.0, 0.1 * cos(2.0 * a));
        sea_inputs[i].wind.x = 1.0;
        sea_inputs[i].wind.z = 0.25;
        sea_inputs[i].sigma_x2 = 0.001 * (i % 7);
        sea_inputs[i].sigma_y2 = 0.0007 * (i % 3);
    }
    for (i = 0; i < NRAYS; i++) {
        double theta = (75.0 * (i % 4) / 3.0) * PI / 180.0, phi = (i / 4) * PI / 6.0;
        rays[i].start_u = (float)((i * 7 % NRAYS) / (double)NRAYS);
        rays[i].start_v = (float)((i * 13 % NRAYS) / (double)NRAYS);
        rays[i].dir_x = (float)(0.1 * tan(theta) * cos(phi));
        rays[i].dir_y = (float)(0.1 * tan(theta) * sin(phi));
        rays[i].dir_z = 1.0f;
        relief_points[i].u = rays[i].start_v;
        relief_points[i].v = rays[i].start_u;
        relief_points[i].depth = (float)((i % 9) / 9.0);
    }
    for (i = 0; i < NQUERY; i++) {
        queries[i].x = 1000.0 + 31.0 * (0.5 + 0.5 * sin(0.7 * i));
        queries[i].z = -500.0 + 31.0 * (0.5 + 0.5 * cos(1.3 * i));
    }
}

/* A height map with bumps; `variant` moves them. */
static void relief_heights(float *h, int n, int variant)
{
    int i, j;
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            double x = (double)i / n, y = (double)j / n;
            double v = 0.5 + 0.25 * sin(2.0 * PI * (x * 2.0 + 0.1 * variant)) *
                                 cos(2.0 * PI * (y * 3.0 - 0.05 * variant));
            h[j * n + i] = (float)(((i + j + variant) % 7 == 0) ? 1.0 : v);
        }
}

/* A window depth buffer of a wavy floor through a GL projection; `variant` shifts it. */
static void sao_depth(float *d, int variant)
{
    int x, y;
    for (y = 0; y < SAO_H; y++)
        for (x = 0; x < SAO_W; x++) {
            double v = 0.96 + 0.02 * sin(0.21 * x + 0.3 * variant) * cos(0.17 * y) +
                       0.015 * y / SAO_H;
            d[y * SAO_W + x] = (y < 6) ? 1.0f : (float)v; /* sky over the top rows */
        }
}

static OceanCamera sao_camera(void)
{
    return check_camera_at(0.0, 0.0, 0.0, 60.0 * PI / 180.0, (double)SAO_W / SAO_H, 0.1, 100.0,
                           OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
}

static OceanSpectrumParams spectrum_params(int variant)
{
    OceanSpectrumParams p;
    memset(&p, 0, sizeof p);
    ocean_spectrum_params_default(&p);
    if (variant >= 0) {
        p.seed = 100u + (uint64_t)variant;
        p.wave_count = 12u + (size_t)variant;
        p.wind_speed = 6.0 + variant;
    }
    return p;
}

static OceanSkyParams sky_params(int variant)
{
    OceanSkyParams s;
    memset(&s, 0, sizeof s);
    ocean_sky_params_default(&s);
    if (variant >= 0) {
        double el = (10.0 + 7.0 * variant) * PI / 180.0, az = 0.4 * variant;
        s.sun_direction = dvec3(cos(el) * sin(az), sin(el), -cos(el) * cos(az));
    }
    return s;
}

/* ------------------------------------------------------------------------------------------ */
/* Scenes.                                                                                    */

static OceanBoxDesc box(double speed, double dx, double dz, double ox, double oz, uint32_t trains,
                        uint64_t seed)
{
    OceanBoxDesc b;
    memset(&b, 0, sizeof b);
    b.wind.speed = speed;
    b.wind.direction_x = dx;
    b.wind.direction_z = dz;
    b.wind.origin_x = 1000.0 + ox;
    b.wind.origin_z = -500.0 + oz;
    b.wind.width = 40.0;
    b.wind.fetch = 45.0;
    b.wind.start = -1.0;
    b.wind.sustain = INFINITY; /* a wind that never dies */
    b.wind.seed = seed;
    b.wind.trains = trains;
    b.smoothing = 3.0;
    return b;
}

/* A 32 x 32 scene at 1 m spacing with a sloping floor and an island whose place depends on
 * `variant`, and two boxes. */
static OceanWtbScene *make_scene(Worker *w, int variant, uint32_t ids[2])
{
    static const OceanWaterGridDesc grid = {1000.0, -500.0, 1.0, SCENE_N, SCENE_N};
    float *terrain = xmalloc(SCENE_PTS * sizeof *terrain);
    OceanWtbScene *s = NULL;
    OceanBoxDesc a = box(7.0, 1.0, 0.2, -4.0, -3.0, 1, 11u + (uint64_t)variant);
    OceanBoxDesc b = box(5.0, 0.6, 1.0, 6.0, -20.0, 2, 12u + (uint64_t)variant);
    int i, j, ci = 10 + (variant + 8) % 12, cj = 12 + (variant + 8) % 9;
    for (j = 0; j < SCENE_N; j++)
        for (i = 0; i < SCENE_N; i++)
            terrain[j * SCENE_N + i] = ((i - ci) * (i - ci) + (j - cj) * (j - cj) < 10)
                                           ? 1.5f
                                           : (float)-(20.0 - 18.0 * i / (SCENE_N - 1.0));
    if (CALL(w, ocean_wtb_scene_create(&grid, terrain, SCENE_PTS, &s))) {
        CALL(w, ocean_wtb_scene_add_box(s, &a, NULL, 0, &ids[0]));
        CALL(w, ocean_wtb_scene_add_box(s, &b, NULL, 0, &ids[1]));
        log_u32(w, ids[0]);
        log_u32(w, ids[1]);
    }
    free(terrain);
    return s;
}

static void log_drawn(Worker *w, const OceanDrawnSample *d, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        log_f64(w, d[k].height);
        log_dvec3(w, d[k].normal);
        log_dvec3(w, d[k].shading_normal);
        log_f64(w, d[k].rest.x);
        log_f64(w, d[k].rest.z);
        log_bytes(w, d[k].weights, sizeof d[k].weights);
        log_u32(w, d[k].cell_i);
        log_u32(w, d[k].cell_j);
        log_u32(w, d[k].upper);
    }
}

static void log_continuous(Worker *w, const OceanHeightSample *h, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++) {
        log_f64(w, h[k].height);
        log_dvec3(w, h[k].normal);
        log_f64(w, h[k].rest.x);
        log_f64(w, h[k].rest.z);
        log_f64(w, h[k].residual);
    }
}

static void log_stats(Worker *w, const OceanFrameStats *st)
{
    log_u64(w, st->alive);
    log_u64(w, st->culled);
    log_u64(w, st->trains);
    log_u64(w, st->max_trains);
    log_f64(w, st->estimated_seconds);
    log_u64(w, st->filtered_trains);
    log_u64(w, st->removed_trains);
}

/* Evaluates `s` at `t`, then asks both height queries. */
static void scene_frame(Worker *w, OceanWtbScene *s, double t)
{
    OceanVec3 *pos = xmalloc(SCENE_PTS * sizeof *pos), *nrm = xmalloc(SCENE_PTS * sizeof *nrm);
    OceanDrawnSample drawn[NQUERY];
    OceanHeightSample cont[NQUERY];
    OceanFrameStats st;
    memset(&st, 0, sizeof st);
    if (CALL(w, ocean_wtb_scene_evaluate(s, t, NULL, pos, nrm, SCENE_PTS, &st))) {
        log_vec3s(w, pos, SCENE_PTS);
        log_vec3s(w, nrm, SCENE_PTS);
        log_stats(w, &st);
    }
    if (CALL(w, ocean_wtb_scene_heights_drawn(s, queries, NQUERY, drawn)))
        log_drawn(w, drawn, NQUERY);
    if (CALL(w, ocean_wtb_scene_heights_continuous(s, t + 0.5, queries, NQUERY, cont)))
        log_continuous(w, cont, NQUERY);
    free(pos);
    free(nrm);
}

/* ------------------------------------------------------------------------------------------ */
/* Phase 1: the first calls into the library.                                                 */

static const OceanWaveDesc COLD_WAVES[3] = {
    {0.5, 20.0, 1.0, 0.0, 0.0, INFINITY},
    {0.2, 7.0, 0.6, 0.8, 1.0, INFINITY},
    {0.05, 2.0, -0.3, 1.0, 2.0, 15.0},
};

static void cold_job(Worker *w)
{
    size_t i, n = ocean_shader_count();
    OceanWaves *waves = NULL;
    OceanSpectrum *spectrum = NULL;
    OceanSpectrumParams p = spectrum_params(-1);
    OceanGrid grid = {-50.0, 20.0, 0.5, 0.25, COLD_NX, COLD_NZ};
    OceanVec3 *pos = xmalloc((size_t)COLD_NX * COLD_NZ * sizeof *pos);
    OceanVec3 *nrm = xmalloc((size_t)COLD_NX * COLD_NZ * sizeof *nrm);
    double amplitude = 0.0;

    log_str(w, ocean_version());
    log_str(w, ocean_last_error_message());
    log_u64(w, n);
    for (i = 0; i < n; i++) {
        const char *name = NULL;
        if (CALL(w, ocean_shader_name(i, &name)))
            log_str(w, name);
    }
    if (CALL(w, ocean_waves_create(COLD_WAVES, 3, &waves))) {
        if (CALL(w, ocean_waves_evaluate_grid(waves, &grid, 3.0, pos, nrm))) {
            log_vec3s(w, pos, (size_t)COLD_NX * COLD_NZ);
            log_vec3s(w, nrm, (size_t)COLD_NX * COLD_NZ);
        }
        ocean_waves_destroy(waves);
    }
    if (CALL(w, ocean_spectrum_create(&p, &spectrum))) {
        if (CALL(w, ocean_spectrum_max_amplitude(spectrum, &amplitude)))
            log_f64(w, amplitude);
        ocean_spectrum_destroy(spectrum);
    }
    free(pos);
    free(nrm);
}

/* ------------------------------------------------------------------------------------------ */
/* Phase 2: one set of handles shared by every thread.                                        */

typedef struct Shared {
    OceanSpectrum *spectrum;
    OceanWaves *waves;
    OceanLighting *lighting;
    OceanSkyMap *sky_map;
    OceanReliefMap *relief_map;
    OceanReliefCones *cones;
    OceanReliefMips *mips;
    OceanSao *sao;
    OceanShaderExport *shader;
    OceanWtbScene *scene;
    float sao_depth[SAO_IN];
} Shared;

static Shared shared;

/* The scene's one evaluation time: every thread evaluates the shared scene at it, so the
 * "last evaluation" that the drawn-height queries read is the same whichever thread ran last. */
static const double SHARED_SCENE_TIME = 4.0;

/* Variant `k` of the shared job: the same calls, at TIME[k] where time matters. */
static void shared_job(Worker *w, const Shared *sh, int k)
{
    double t = TIME[k];
    OceanDVec3 *pos = xmalloc(NPOINTS * sizeof *pos);
    OceanVec3 *nrm = xmalloc(NPOINTS * sizeof *nrm);
    OceanVec3 *gpos = xmalloc(GRID_NX * GRID_NZ * sizeof *gpos);
    OceanVec3 *gnrm = xmalloc(GRID_NX * GRID_NZ * sizeof *gnrm);
    OceanGrid grid = {1e5, -2e4 + k, 0.75, 0.5, GRID_NX, GRID_NZ};
    OceanWaveDesc *descs;
    size_t count = 0, i;
    double d = 0.0;
    OceanSlopeVariance sv;
    OceanRgb rgb;
    OceanIrradiance irr;
    OceanSeaLight sea[NSEA];
    uint32_t levels = 0, level, side = 0;
    float *texels;
    OceanReliefHit hits[NRAYS];
    uint8_t shadow[NRAYS];
    float ao[SAO_OUT], *z = xmalloc(SAO_IN * sizeof *z);

    /* Waves. */
    if (CALL(w, ocean_waves_evaluate(sh->waves, points, NPOINTS, t, pos, nrm))) {
        log_dvec3s(w, pos, NPOINTS);
        log_vec3s(w, nrm, NPOINTS);
    }
    if (CALL(w, ocean_waves_evaluate_grid(sh->waves, &grid, t, gpos, gnrm))) {
        log_vec3s(w, gpos, GRID_NX * GRID_NZ);
        log_vec3s(w, gnrm, GRID_NX * GRID_NZ);
    }
    if (CALL(w, ocean_waves_count(sh->waves, &count)))
        log_u64(w, count);
    if (CALL(w, ocean_waves_steepness_sum(sh->waves, &d)))
        log_f64(w, d);

    /* Spectrum. */
    if (CALL(w, ocean_spectrum_wave_count(sh->spectrum, &count))) {
        descs = xmalloc(count * sizeof *descs);
        if (CALL(w, ocean_spectrum_waves(sh->spectrum, descs, count)))
            log_bytes(w, descs, count * sizeof *descs); /* six doubles: no padding */
        free(descs);
    }
    if (CALL(w, ocean_spectrum_slope_variance(sh->spectrum, OCEAN_FILTER_N_MIN,
                                              OCEAN_FILTER_N_MAX, 0.01 * (k + 1), &sv))) {
        log_f64(w, sv.sigma_x2);
        log_f64(w, sv.sigma_y2);
    }
    if (CALL(w, ocean_spectrum_height_variance(sh->spectrum, &d)))
        log_f64(w, d);

    /* Lighting and its sky map. */
    for (i = 0; i < NDIRS; i++)
        if (CALL(w, ocean_lighting_environment_radiance(sh->lighting, dirs[(i + (size_t)k) % NDIRS],
                                                        &rgb)))
            log_rgb(w, rgb);
    if (CALL(w, ocean_lighting_irradiance(sh->lighting, &irr)))
        for (i = 0; i < 9; i++)
            log_rgb(w, irr.k[i]);
    if (CALL(w, ocean_sea_color_batch(sh->lighting, sh->sky_map, sea_inputs, NSEA, sea)))
        for (i = 0; i < NSEA; i++) {
            log_rgb(w, sea[i].sun);
            log_rgb(w, sea[i].sky);
            log_rgb(w, sea[i].sea);
        }
    if (CALL(w, ocean_sky_map_level_count(sh->sky_map, &levels))) {
        level = (uint32_t)k % levels;
        if (CALL(w, ocean_sky_map_level_info(sh->sky_map, level, &side))) {
            texels = xmalloc((size_t)side * side * 4 * sizeof *texels);
            if (CALL(w, ocean_sky_map_copy_level(sh->sky_map, level, texels,
                                                 (size_t)side * side * 4)))
                log_bytes(w, texels, (size_t)side * side * 4 * sizeof *texels);
            free(texels);
        }
    }

    /* Relief. */
    if (CALL(w, ocean_relief_trace(sh->cones, &RELAXED, rays, NRAYS, hits)))
        log_bytes(w, hits, sizeof hits); /* three floats and a uint32_t: no padding */
    if (CALL(w, ocean_relief_shadow(sh->cones, &RELAXED, relief_points, NRAYS, 1.0f,
                                    0.5f * (float)k, 1.0f, 0.1f, 0.05f, shadow)))
        log_bytes(w, shadow, sizeof shadow);
    if (CALL(w, ocean_relief_mips_level_count(sh->mips, &levels))) {
        level = (uint32_t)k % levels;
        if (CALL(w, ocean_relief_mips_level_size(sh->mips, level, &side))) {
            texels = xmalloc((size_t)side * side * 3 * sizeof *texels);
            if (CALL(w, ocean_relief_mips_copy_level(sh->mips, level, OCEAN_RELIEF_ENCODING_F32,
                                                     texels, (size_t)side * side * 3)))
                log_bytes(w, texels, (size_t)side * side * 3 * sizeof *texels);
            free(texels);
        }
    }
    texels = xmalloc(RELIEF_SHARED * RELIEF_SHARED * sizeof *texels);
    if (CALL(w, ocean_relief_map_depths(sh->relief_map, texels, RELIEF_SHARED * RELIEF_SHARED)))
        log_bytes(w, texels, RELIEF_SHARED * RELIEF_SHARED * sizeof *texels);
    free(texels);

    /* Ambient obscurance. */
    if (CALL(w, ocean_sao_run(sh->sao, sh->sao_depth, SAO_IN, ao, SAO_OUT)))
        log_bytes(w, ao, sizeof ao);
    if (CALL(w, ocean_sao_view_z(sh->sao, sh->sao_depth, SAO_IN, z, SAO_IN)))
        log_bytes(w, z, SAO_IN * sizeof *z);

    /* Shader export: the same files for every thread. */
    if (CALL(w, ocean_shader_export_file_count(sh->shader, &count)))
        for (i = 0; i < count; i++) {
            const char *name = NULL;
            const uint8_t *data = NULL;
            size_t len = 0;
            if (CALL(w, ocean_shader_export_file(sh->shader, i, &name, &data, &len))) {
                log_str(w, name);
                log_u64(w, len);
                log_bytes(w, data, len);
            }
        }

    /* The scene, which serialises the threads' calls. */
    scene_frame(w, sh->scene, SHARED_SCENE_TIME);

    free(pos);
    free(nrm);
    free(gpos);
    free(gnrm);
    free(z);
}

/* ------------------------------------------------------------------------------------------ */
/* Phase 3: handles of the thread's own.                                                      */

/* A failure whose message names an index that depends on the thread and round: it must come
 * back on this thread, unchanged by the other threads' failures and successes. */
static void own_failure(Worker *w, OceanWaves *waves, int id, int k)
{
    OceanDVec2 xz[THREADS + TIMES];
    OceanDVec3 pos[THREADS + TIMES];
    OceanVec3 nrm[THREADS + TIMES];
    int i, bad = id + k;
    for (i = 0; i < THREADS + TIMES; i++) {
        xz[i].x = (double)i;
        xz[i].z = 0.0;
    }
    xz[bad].z = NAN;
    CALL_FAILS(w, ocean_waves_evaluate(waves, xz, THREADS + TIMES, 1.0, pos, nrm),
               OCEAN_STATUS_NON_FINITE);
}

/* Variant `k` of thread `id`'s job: creates every kind of handle from inputs of its own, uses
 * and destroys them. */
static void own_job(Worker *w, int id, int k)
{
    double t = TIME[k];
    OceanSpectrumParams sp = spectrum_params(id);
    OceanSkyParams sky = sky_params(id);
    OceanSeaParams sea_params;
    OceanSpectrum *spectrum = NULL;
    OceanWaves *waves = NULL;
    OceanLighting *lighting = NULL;
    OceanSkyMap *sky_map = NULL;
    OceanReliefMap *map = NULL;
    OceanReliefCones *cones = NULL;
    OceanReliefMips *mips = NULL;
    OceanReliefConeParams cp;
    OceanSao *sao = NULL;
    OceanSaoParams sao_params;
    OceanCamera camera = sao_camera();
    OceanWtbScene *scene = NULL;
    OceanWaveDesc *descs;
    OceanSeaLight sea[NSEA];
    OceanReliefHit hits[NRAYS];
    OceanDVec3 *pos = xmalloc(NPOINTS * sizeof *pos);
    OceanVec3 *nrm = xmalloc(NPOINTS * sizeof *nrm);
    float heights[RELIEF_OWN * RELIEF_OWN], texels[3 * 8 * 8];
    float *depth = xmalloc(SAO_IN * sizeof *depth), ao[SAO_OUT];
    size_t count = 0;
    uint32_t side = 0, ids[2] = {0, 0};
    int i;

    /* A spectrum and its waves. */
    if (CALL(w, ocean_spectrum_create(&sp, &spectrum))) {
        if (CALL(w, ocean_spectrum_wave_count(spectrum, &count))) {
            descs = xmalloc(count * sizeof *descs);
            if (CALL(w, ocean_spectrum_waves(spectrum, descs, count)) &&
                CALL(w, ocean_waves_create(descs, count, &waves))) {
                if (CALL(w, ocean_waves_evaluate(waves, points, NPOINTS, t, pos, nrm))) {
                    log_dvec3s(w, pos, NPOINTS);
                    log_vec3s(w, nrm, NPOINTS);
                }
                own_failure(w, waves, id, k);
                ocean_waves_destroy(waves);
            }
            free(descs);
        }
        ocean_spectrum_destroy(spectrum);
    }

    /* A lighting, its sky map and the sea's colour. */
    ocean_sea_params_default(&sea_params);
    if (CALL(w, ocean_lighting_create(&sky, &sea_params, &lighting))) {
        if (CALL(w, ocean_lighting_sky_map_create(lighting, 16, &sky_map))) {
            if (CALL(w, ocean_sea_color_batch(lighting, sky_map, sea_inputs, NSEA, sea)))
                for (i = 0; i < NSEA; i++) {
                    log_rgb(w, sea[i].sun);
                    log_rgb(w, sea[i].sky);
                    log_rgb(w, sea[i].sea);
                }
            ocean_sky_map_destroy(sky_map);
        }
        ocean_lighting_destroy(lighting);
    }

    /* A relief map, its cones and their mips. */
    relief_heights(heights, RELIEF_OWN, id + k);
    ocean_relief_cone_params_default(&cp);
    if (CALL(w, ocean_relief_map_create_f32(heights, RELIEF_OWN * RELIEF_OWN, RELIEF_OWN,
                                            RELIEF_OWN, OCEAN_RELIEF_EDGE_WRAP,
                                            OCEAN_RELIEF_RANGE_REFUSE, &map))) {
        if (CALL(w, ocean_relief_cones_create(map, &cp, NULL, NULL, &cones))) {
            if (CALL(w, ocean_relief_trace(cones, &RELAXED, rays, NRAYS, hits)))
                log_bytes(w, hits, sizeof hits);
            if (CALL(w, ocean_relief_mips_create(cones, OCEAN_RELIEF_MIP_WINDOW, &mips))) {
                if (CALL(w, ocean_relief_mips_level_size(mips, 1, &side)) &&
                    CALL(w, ocean_relief_mips_copy_level(mips, 1, OCEAN_RELIEF_ENCODING_F32,
                                                         texels, (size_t)side * side * 3)))
                    log_bytes(w, texels, (size_t)side * side * 3 * sizeof *texels);
                ocean_relief_mips_destroy(mips);
            }
            ocean_relief_cones_destroy(cones);
        }
        ocean_relief_map_destroy(map);
    }

    /* An SAO set-up. */
    sao_depth(depth, id * TIMES + k);
    ocean_sao_params_default(&sao_params);
    if (CALL(w, ocean_sao_create(SAO_W, SAO_H, SAO_GUARD, &camera, OCEAN_SAO_DEPTH_WINDOW,
                                 &sao_params, &sao))) {
        if (CALL(w, ocean_sao_run(sao, depth, SAO_IN, ao, SAO_OUT)))
            log_bytes(w, ao, sizeof ao);
        ocean_sao_destroy(sao);
    }

    /* A scene: evaluate, query, move a box, evaluate again, remove a box. */
    scene = make_scene(w, id, ids);
    if (scene != NULL) {
        OceanBoxDesc moved = box(6.0, 0.0, 1.0, 2.0 + k, -10.0, 1, 77);
        scene_frame(w, scene, t);
        if (CALL(w, ocean_wtb_scene_update_box(scene, ids[1], &moved, NULL, 0)))
            scene_frame(w, scene, t + 1.0);
        if (CALL(w, ocean_wtb_scene_remove_box(scene, ids[0])) &&
            CALL(w, ocean_wtb_scene_box_count(scene, &count)))
            log_u64(w, count);
        scene_frame(w, scene, t + 2.0);
        ocean_wtb_scene_destroy(scene);
    }

    free(pos);
    free(nrm);
    free(depth);
}

/* ------------------------------------------------------------------------------------------ */
/* The threads.                                                                               */

typedef enum Phase { COLD, SHARED, OWN } Phase;

typedef struct Thread {
    pthread_t handle;
    Phase phase;
    int id;
    int rounds;
    pthread_barrier_t *start;
    const Worker *reference; /* COLD: none (compared after); else [TIMES] (SHARED) or
                              * [THREADS][TIMES] (OWN) */
    Worker w;       /* the current round's log */
    long compared;  /* rounds whose log equalled the reference */
    long mismatched;
    char mismatch[512];
    long calls;
} Thread;

static void *thread_main(void *arg)
{
    Thread *th = arg;
    int r;
    pthread_barrier_wait(th->start);
    if (th->phase == COLD) {
        cold_job(&th->w);
        th->calls = th->w.calls;
        return NULL;
    }
    for (r = 0; r < th->rounds; r++) {
        /* Threads start at different variants, so that different calls overlap. */
        int k = (r + th->id) % TIMES;
        const Worker *ref = th->phase == SHARED ? &th->reference[k]
                                                : &th->reference[th->id * TIMES + k];
        long at;
        worker_reset(&th->w);
        if (th->phase == SHARED)
            shared_job(&th->w, &shared, k);
        else
            own_job(&th->w, th->id, k);
        th->calls += th->w.calls;
        if (th->w.failures != 0)
            break; /* reported by the main thread */
        at = log_diff(&th->w.log, &ref->log);
        if (at < 0) {
            th->compared++;
        } else {
            if (th->mismatched++ == 0)
                snprintf(th->mismatch, sizeof th->mismatch,
                         "round %d (variant %d): log of %zu bytes differs from the reference's "
                         "%zu bytes at byte %ld",
                         r, k, th->w.log.len, ref->log.len, at);
        }
    }
    return NULL;
}

/* Starts `n` threads; they wait at their barrier until all have started. */
static void start_threads(Thread *t, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        int e = pthread_create(&t[i].handle, NULL, thread_main, &t[i]);
        CHECK(e == 0, "pthread_create: error %d", e);
        if (e != 0) {
            /* The started threads wait at the barrier forever: nothing to join. */
            fprintf(stderr, "cannot start thread %d\n", i);
            exit(2);
        }
    }
}

static void join_threads(Thread *t, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        int e = pthread_join(t[i].handle, NULL);
        CHECK(e == 0, "pthread_join: error %d", e);
    }
}

static int rounds_from_env(void)
{
    const char *v = getenv("OCEAN_THREADS_ROUNDS");
    long r;
    char *end = NULL;
    if (v == NULL || v[0] == '\0')
        return DEFAULT_ROUNDS;
    r = strtol(v, &end, 10);
    if (*end != '\0' || r < 1 || r > 1000) {
        fprintf(stderr, "OCEAN_THREADS_ROUNDS=%s: expected 1 to 1000\n", v);
        exit(2);
    }
    return (int)r;
}

/* ------------------------------------------------------------------------------------------ */

static void check_worker(const char *what, int id, const Worker *w)
{
    CHECK(w->failures == 0, "%s %d: %ld unexpected results; first: %s", what, id, w->failures,
          w->first);
    CHECK(w->calls > 0, "%s %d made no call", what, id);
}

static void make_shared(Worker *w)
{
    OceanSpectrumParams sp = spectrum_params(-1);
    OceanSkyParams sky = sky_params(-1);
    OceanSeaParams sea;
    OceanReliefConeParams cp;
    OceanSaoParams sao_params;
    OceanCamera camera = sao_camera();
    float heights[RELIEF_SHARED * RELIEF_SHARED];
    OceanWaveDesc *descs;
    size_t count = 0;
    const char *name = NULL;
    uint32_t ids[2] = {0, 0};

    CALL(w, ocean_spectrum_create(&sp, &shared.spectrum));
    CALL(w, ocean_spectrum_wave_count(shared.spectrum, &count));
    descs = xmalloc(count * sizeof *descs);
    CALL(w, ocean_spectrum_waves(shared.spectrum, descs, count));
    CALL(w, ocean_waves_create(descs, count, &shared.waves));
    free(descs);
    ocean_sea_params_default(&sea);
    CALL(w, ocean_lighting_create(&sky, &sea, &shared.lighting));
    CALL(w, ocean_lighting_sky_map_create(shared.lighting, SKY_SIZE, &shared.sky_map));
    relief_heights(heights, RELIEF_SHARED, 0);
    CALL(w, ocean_relief_map_create_f32(heights, RELIEF_SHARED * RELIEF_SHARED, RELIEF_SHARED,
                                        RELIEF_SHARED, OCEAN_RELIEF_EDGE_WRAP,
                                        OCEAN_RELIEF_RANGE_REFUSE, &shared.relief_map));
    ocean_relief_cone_params_default(&cp);
    CALL(w, ocean_relief_cones_create(shared.relief_map, &cp, NULL, NULL, &shared.cones));
    CALL(w, ocean_relief_mips_create(shared.cones, OCEAN_RELIEF_MIP_WINDOW, &shared.mips));
    ocean_sao_params_default(&sao_params);
    CALL(w, ocean_sao_create(SAO_W, SAO_H, SAO_GUARD, &camera, OCEAN_SAO_DEPTH_WINDOW,
                          &sao_params, &shared.sao));
    sao_depth(shared.sao_depth, 0);
    /* The cheapest pass to translate: the one with the shortest GLSL is not known here, so
     * the first registered one. */
    CALL(w, ocean_shader_name(0, &name));
    CALL(w, ocean_shader_export(name, OCEAN_SHADER_LANGUAGE_GLSL, &shared.shader));
    shared.scene = make_scene(w, -1, ids);
    if (shared.scene != NULL) {
        /* Evaluated once before the threads, so the drawn-height queries have a mesh. */
        OceanVec3 *pos = xmalloc(SCENE_PTS * sizeof *pos);
        OceanVec3 *nrm = xmalloc(SCENE_PTS * sizeof *nrm);
        CALL(w, ocean_wtb_scene_evaluate(shared.scene, SHARED_SCENE_TIME, NULL, pos, nrm,
                                         SCENE_PTS, NULL));
        free(pos);
        free(nrm);
    }
}

static void destroy_shared(void)
{
    ocean_wtb_scene_destroy(shared.scene);
    ocean_shader_export_destroy(shared.shader);
    ocean_sao_destroy(shared.sao);
    ocean_relief_mips_destroy(shared.mips);
    ocean_relief_cones_destroy(shared.cones);
    ocean_relief_map_destroy(shared.relief_map);
    ocean_sky_map_destroy(shared.sky_map);
    ocean_lighting_destroy(shared.lighting);
    ocean_waves_destroy(shared.waves);
    ocean_spectrum_destroy(shared.spectrum);
}

int main(void)
{
    static Thread cold[THREADS], workers[2 * THREADS];
    static Worker shared_ref[TIMES], own_ref[THREADS * TIMES];
    pthread_barrier_t barrier;
    Worker setup, cold_ref;
    int rounds = rounds_from_env(), i, k;
    long calls = 0, compared = 0;

    memset(&setup, 0, sizeof setup);
    memset(&cold_ref, 0, sizeof cold_ref);

    /* Phase 1, before this thread has called the library. */
    pthread_barrier_init(&barrier, NULL, THREADS);
    for (i = 0; i < THREADS; i++) {
        cold[i].phase = COLD;
        cold[i].id = i;
        cold[i].start = &barrier;
    }
    start_threads(cold, THREADS);
    join_threads(cold, THREADS);
    pthread_barrier_destroy(&barrier);
    cold_job(&cold_ref);
    check_worker("cold-start reference", 0, &cold_ref);
    for (i = 0; i < THREADS; i++) {
        long at = log_diff(&cold[i].w.log, &cold_ref.log);
        check_worker("cold-start thread", i, &cold[i].w);
        CHECK(at < 0, "cold-start thread %d: its log (%zu bytes) differs from the reference "
                      "(%zu bytes) at byte %ld",
              i, cold[i].w.log.len, cold_ref.log.len, at);
        calls += cold[i].calls;
        compared += at < 0;
        worker_free(&cold[i].w);
    }

    /* The references of phases 2 and 3, on this thread alone. */
    make_inputs();
    make_shared(&setup);
    check_worker("set-up", 0, &setup);
    if (setup.failures != 0) {
        printf("test_threads.c: library %s, %d checks, %d failures; the set-up failed\n",
               ocean_version(), checks, failures);
        return 1;
    }
    for (k = 0; k < TIMES; k++) {
        shared_job(&shared_ref[k], &shared, k);
        check_worker("shared reference", k, &shared_ref[k]);
        for (i = 0; i < THREADS; i++) {
            own_job(&own_ref[i * TIMES + k], i, k);
            check_worker("own reference", i * TIMES + k, &own_ref[i * TIMES + k]);
        }
    }
    /* The failures' messages differ wherever the bad index does, so a message that crossed to
     * another thread would show in its log. */
    for (i = 0; i < THREADS * TIMES; i++)
        for (k = 0; k < THREADS * TIMES; k++) {
            int bad_i = i / TIMES + i % TIMES, bad_k = k / TIMES + k % TIMES;
            if (bad_i < bad_k)
                CHECK(strcmp(own_ref[i].message, own_ref[k].message) != 0,
                      "the messages for bad indices %d and %d are the same: %s", bad_i, bad_k,
                      own_ref[i].message);
        }

    /* Phases 2 and 3 together. */
    pthread_barrier_init(&barrier, NULL, 2 * THREADS);
    for (i = 0; i < 2 * THREADS; i++) {
        Thread *t = &workers[i];
        t->phase = i < THREADS ? SHARED : OWN;
        t->id = i % THREADS;
        t->rounds = rounds;
        t->start = &barrier;
        t->reference = i < THREADS ? shared_ref : own_ref;
    }
    start_threads(workers, 2 * THREADS);
    join_threads(workers, 2 * THREADS);
    pthread_barrier_destroy(&barrier);

    for (i = 0; i < 2 * THREADS; i++) {
        Thread *t = &workers[i];
        const char *what = t->phase == SHARED ? "shared-handle thread" : "own-handle thread";
        check_worker(what, t->id, &t->w);
        CHECK(t->mismatched == 0, "%s %d: %ld of %d rounds differ from the reference; first: %s",
              what, t->id, t->mismatched, rounds, t->mismatch);
        CHECK(t->compared == rounds, "%s %d: %ld of %d rounds compared", what, t->id,
              t->compared, rounds);
        calls += t->calls;
        compared += t->compared;
        worker_free(&t->w);
    }

    destroy_shared();
    worker_free(&setup);
    worker_free(&cold_ref);
    for (k = 0; k < TIMES; k++)
        worker_free(&shared_ref[k]);
    for (i = 0; i < THREADS * TIMES; i++)
        worker_free(&own_ref[i]);

    printf("test_threads.c: library %s, %d checks, %d failures; %d cold-start threads, "
           "%d shared-handle and %d own-handle threads x %d rounds: %ld library calls, %ld "
           "logs equal to the single-threaded reference\n",
           ocean_version(), checks, failures, THREADS, THREADS, THREADS, rounds, calls,
           compared);
    return failures == 0 ? 0 : 1;
}
