/*
 * C11 test of the relief-mapping part of the ocean C ABI (ocean_relief_*), linked against
 * libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_relief.c libocean.a ...
 *
 * Scenes, each with expectations derived here from the geometry:
 * - Flat maps. A map at height 1 (8-bit 255 everywhere) is the polygon itself: every relaxed or
 *   cone-step ray stops exactly where it enters (the first fetch finds the ray at the surface,
 *   every step is 0). A map at height 0.5 (depth 0.5) has no obstacle, so every cone is the cap
 *   (8-bit code 255 for a cap of 1, binary16 0x4400 for a cap of 4), every normal is (0, 0, 1),
 *   and rays hit the plane z = 0.5 at the analytic point: a vertical ray steps exactly onto it
 *   (a step is c h / (0 + c) = h) and the 6 bisections of [0, 0.5] that follow end at
 *   0.5 - 0.5 / 2^7; linear search 16 + 8 brackets [7/16, 8/16] and ends 1/16 / 2^9 above it.
 * - A single box: a 64 x 64 clamp-mode map, floor at height 0, a box of height 1 over texels
 *   24..39 in both directions. A vertical ray on its top stops at depth 0; one on the floor
 *   reaches depth 1 - 1/128 (as above); a 45-degree ray aimed at the box's -u wall meets the
 *   bilinear ramp between texel centres 23.5 and 24.5 at the analytic point. Under a light 45
 *   degrees up from +u with a relief 0.1 texture widths deep, the box's shadow covers the floor
 *   for 6.4 texels on its -u side: a point 2.5 texels from the wall is shadowed, one 9.5 texels
 *   away and one on the lit side are not.
 * - The uniform block of the exported relief shader: for the default scene seen from an eye at
 *   (0.5, 2, -0.5) looking down -z, the corner (0, 0, 0) is stored relative to the eye,
 *   (-0.5, -2, 0.5), and the texture, method and flag words are the ones asked for.
 * - Quad-directional cones (section 18.1) on the box map: the 4-layer texture against the map
 *   and the isotropic cones, the cap where a quadrant sees only floor, hits and shadows as
 *   above, progress over the four layers (test_quad derives the counts).
 * - Level of detail: the next level's 2 x 2 means on the box map, cones of that map, the level
 *   a footprint reads and where each level lies in the texture (test_lod derives the values).
 * - Cancellation from a C callback, progress to completion, and every error path with the
 *   outputs untouched.
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

#define FLAT 16
#define FLAT_TEXELS (FLAT * FLAT)
#define BOX 64
#define BOX_TEXELS (BOX * BOX)

static OceanReliefMethod method(uint32_t m, uint32_t steps, uint32_t binary, uint32_t search)
{
    OceanReliefMethod r;
    /* A parameter struct starts from its defaults: they set `next` (no extensions). */
    ocean_relief_method_default(&r);
    r.method = m;
    r.steps = steps;
    r.binary = binary;
    r.search = search;
    return r;
}

static OceanReliefConeParams cone_params(uint32_t kind, float max_ratio)
{
    OceanReliefConeParams p;
    ocean_relief_cone_params_default(&p);
    p.kind = kind;
    p.max_ratio = max_ratio;
    return p;
}

static OceanReliefRay ray(float u, float v, float dx, float dy, float dz)
{
    OceanReliefRay r;
    r.start_u = u;
    r.start_v = v;
    r.dir_x = dx;
    r.dir_y = dy;
    r.dir_z = dz;
    return r;
}

/* Rays in 8 directions at 0 to 70 degrees from the normal, from scattered starts. */
#define FAN 24
static void fan(OceanReliefRay rays[FAN], float depth)
{
    int i;
    for (i = 0; i < FAN; i++) {
        double theta = (70.0 * (i % 3) / 2.0) * 3.14159265358979323846 / 180.0;
        double phi = (i / 3) * 3.14159265358979323846 / 4.0;
        float u = (float)((i * 7 % 24) / 24.0), v = (float)((i * 11 % 24) / 24.0);
        CHECK(ocean_relief_ray_from_view(u, v, (float)(sin(theta) * cos(phi)),
                                         (float)(sin(theta) * sin(phi)), (float)-cos(theta),
                                         depth, &rays[i]) == OCEAN_STATUS_OK,
              "ray_from_view: %s", last_error());
    }
}

static void test_flat_top(void)
{
    static uint8_t h[FLAT_TEXELS];
    OceanReliefMap *map = NULL;
    OceanReliefCones *relaxed = NULL, *conservative = NULL;
    OceanReliefConeParams p;
    OceanReliefRay rays[FAN];
    OceanReliefHit hits[FAN];
    OceanReliefMethod methods[2];
    OceanReliefCones *handles[2];
    int m, i;

    memset(h, 255, sizeof h);
    if (!OK(ocean_relief_map_create_u8(h, FLAT_TEXELS, FLAT, FLAT, OCEAN_RELIEF_EDGE_WRAP, &map)))
        return;
    OK(ocean_relief_cone_params_default(&p));
    CHECK(p.kind == OCEAN_RELIEF_CONE_KIND_RELAXED && p.max_ratio == 1.0f, "default params");
    OK(ocean_relief_cones_create(map, &p, NULL, NULL, &relaxed));
    p.kind = OCEAN_RELIEF_CONE_KIND_CONSERVATIVE;
    OK(ocean_relief_cones_create(map, &p, NULL, NULL, &conservative));
    fan(rays, 0.1f);
    methods[0] = method(OCEAN_RELIEF_TRACER_RELAXED, 15, 6, OCEAN_RELIEF_SEARCH_LAST_STEP);
    methods[1] = method(OCEAN_RELIEF_TRACER_CONE_STEP, 21, 0, 0);
    handles[0] = relaxed;
    handles[1] = conservative;
    for (m = 0; m < 2; m++) {
        if (!OK(ocean_relief_trace(handles[m], &methods[m], rays, FAN, hits)))
            continue;
        for (i = 0; i < FAN; i++) {
            CHECK(hits[i].pos.u == rays[i].start_u && hits[i].pos.v == rays[i].start_v &&
                      hits[i].pos.depth == 0.0f,
                  "flat top, method %d ray %d: hit (%g, %g, %g), expected its start (%g, %g, 0)",
                  m, i, hits[i].pos.u, hits[i].pos.v, hits[i].pos.depth, rays[i].start_u,
                  rays[i].start_v);
            CHECK(hits[i].fetches == 21u, "fetches %u, expected 21", hits[i].fetches);
        }
    }
    ocean_relief_cones_destroy(relaxed);
    ocean_relief_cones_destroy(conservative);
    ocean_relief_map_destroy(map);
}

static void test_flat_half(void)
{
    static float h[FLAT_TEXELS], normals[3 * FLAT_TEXELS], depths[FLAT_TEXELS];
    static uint8_t codes[3 * FLAT_TEXELS];
    static uint16_t halves[3 * FLAT_TEXELS];
    OceanReliefMap *map = NULL;
    OceanReliefCones *cones = NULL;
    OceanReliefMips *mips = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 1.0f);
    OceanReliefRay rays[FAN];
    OceanReliefHit hits[FAN];
    OceanReliefMethod relaxed = method(OCEAN_RELIEF_TRACER_RELAXED, 15, 6,
                                       OCEAN_RELIEF_SEARCH_LAST_STEP);
    OceanReliefMethod linear = method(OCEAN_RELIEF_TRACER_LINEAR, 16, 8, 0);
    uint32_t side = 0, count = 0, level;
    size_t i, bad = 0;

    for (i = 0; i < FLAT_TEXELS; i++)
        h[i] = 0.5f;
    if (!OK(ocean_relief_map_create_f32(h, FLAT_TEXELS, FLAT, FLAT, OCEAN_RELIEF_EDGE_CLAMP,
                                        OCEAN_RELIEF_RANGE_REFUSE, &map)))
        return;
    OK(ocean_relief_map_size(map, &side));
    CHECK(side == FLAT, "side %u", side);
    if (OK(ocean_relief_map_depths(map, depths, FLAT_TEXELS)))
        for (i = 0; i < FLAT_TEXELS; i++)
            bad += depths[i] != 0.5f;
    CHECK(bad == 0, "%zu depths differ from 1 - 0.5", bad);

    /* A plane: every normal is exactly (0, 0, 1). */
    bad = 0;
    if (OK(ocean_relief_normals(map, 20.0f, normals, 3 * FLAT_TEXELS)))
        for (i = 0; i < FLAT_TEXELS; i++)
            bad += normals[3 * i] != 0.0f || normals[3 * i + 1] != 0.0f ||
                   normals[3 * i + 2] != 1.0f;
    CHECK(bad == 0, "%zu normals differ from (0, 0, 1)", bad);

    /* No obstacle anywhere: every channel is the cap, 1.0 -> code 255. */
    bad = 0;
    if (OK(ocean_relief_generate_encoded(map, &p, NULL, NULL, OCEAN_RELIEF_ENCODING_UNORM8,
                                         codes, 3 * FLAT_TEXELS)))
        for (i = 0; i < 3 * FLAT_TEXELS; i++)
            bad += codes[i] != 255;
    CHECK(bad == 0, "%zu 8-bit codes differ from 255", bad);
    /* Capped at 4: binary16 4.0 is 0x4400. */
    p.max_ratio = 4.0f;
    bad = 0;
    if (OK(ocean_relief_generate_encoded(map, &p, NULL, NULL, OCEAN_RELIEF_ENCODING_F16, halves,
                                         3 * FLAT_TEXELS)))
        for (i = 0; i < 3 * FLAT_TEXELS; i++)
            bad += halves[i] != 0x4400;
    CHECK(bad == 0, "%zu binary16 values differ from 0x4400", bad);

    p.max_ratio = 1.0f;
    if (!OK(ocean_relief_cones_create(map, &p, NULL, NULL, &cones))) {
        ocean_relief_map_destroy(map);
        return;
    }
    /* The mip chain of a constant map is constant: 16, 8, 4, 2, 1, all at the cap. */
    if (OK(ocean_relief_mips_create(cones, OCEAN_RELIEF_MIP_WINDOW, &mips))) {
        OK(ocean_relief_mips_level_count(mips, &count));
        CHECK(count == 5, "mip levels %u, expected 5", count);
        for (level = 0; level < count; level++) {
            OK(ocean_relief_mips_level_size(mips, level, &side));
            CHECK(side == (uint32_t)FLAT >> level, "level %u side %u", level, side);
            memset(codes, 0, sizeof codes);
            bad = 0;
            if (OK(ocean_relief_mips_copy_level(mips, level, OCEAN_RELIEF_ENCODING_UNORM8_SQRT,
                                                codes, 3 * (size_t)side * side)))
                for (i = 0; i < 3 * (size_t)side * side; i++)
                    bad += codes[i] != 255;
            CHECK(bad == 0, "level %u: %zu codes differ from 255", level, bad);
        }
        EXPECT_MSG(ocean_relief_mips_level_size(mips, 5, &side), OCEAN_STATUS_INVALID_ARGUMENT,
                   "levels 0 to 4");
    }
    ocean_relief_mips_destroy(mips);

    /* Vertical rays: exactly onto the plane, then 6 bisections of [0, 0.5]. */
    for (i = 0; i < FAN; i++)
        rays[i] = ray((float)i / FAN, 1.0f - (float)i / FAN, 0.0f, 0.0f, 1.0f);
    if (OK(ocean_relief_trace(cones, &relaxed, rays, FAN, hits)))
        for (i = 0; i < FAN; i++)
            CHECK(hits[i].pos.u == rays[i].start_u && hits[i].pos.v == rays[i].start_v &&
                      hits[i].pos.depth == 0.5f - 0.5f / 128.0f,
                  "vertical ray %zu: (%g, %g, %.9g), expected (%g, %g, %.9g)", i, hits[i].pos.u,
                  hits[i].pos.v, hits[i].pos.depth, rays[i].start_u, rays[i].start_v,
                  0.5 - 0.5 / 128.0);

    /* Oblique rays, linear search 16 + 8: depth 0.5 - 1/16/2^9, at the analytic point. */
    fan(rays, 0.1f);
    if (OK(ocean_relief_trace(cones, &linear, rays, FAN, hits)))
        for (i = 0; i < FAN; i++) {
            double z = 0.5 - 1.0 / 16.0 / 512.0;
            double u = rays[i].start_u + rays[i].dir_x / rays[i].dir_z * z;
            double v = rays[i].start_v + rays[i].dir_y / rays[i].dir_z * z;
            CHECK(hits[i].pos.depth == (float)z, "linear ray %zu: depth %.9g, expected %.9g", i,
                  hits[i].pos.depth, z);
            CHECK(fabs(hits[i].pos.u - u) < 1e-6 && fabs(hits[i].pos.v - v) < 1e-6,
                  "linear ray %zu: (%.7g, %.7g), expected (%.7g, %.7g)", i, hits[i].pos.u,
                  hits[i].pos.v, u, v);
            CHECK(hits[i].fetches == 16 / 2 + 8, "linear ray %zu: %u fetches, expected 16", i,
                  hits[i].fetches);
        }
    ocean_relief_cones_destroy(cones);
    ocean_relief_map_destroy(map);
}

/* The box: floor at height 0, box of height 1 over texels 24..39. */
static float box_heights[BOX_TEXELS];

static void make_box(void)
{
    int i, j;
    for (j = 0; j < BOX; j++)
        for (i = 0; i < BOX; i++)
            box_heights[j * BOX + i] = (i >= 24 && i < 40 && j >= 24 && j < 40) ? 1.0f : 0.0f;
}

static void test_box(void)
{
    OceanReliefMap *map = NULL;
    OceanReliefCones *cones = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 4.0f);
    OceanReliefMethod relaxed = method(OCEAN_RELIEF_TRACER_RELAXED, 15, 6,
                                       OCEAN_RELIEF_SEARCH_LAST_STEP);
    OceanReliefMethod shared = method(OCEAN_RELIEF_TRACER_RELAXED, 58, 6,
                                      OCEAN_RELIEF_SEARCH_SHARED);
    OceanReliefRay rays[3];
    OceanReliefHit hits[3];
    OceanReliefPoint points[4];
    uint8_t shadow[4];
    double z_wall, u_wall;

    make_box();
    if (!OK(ocean_relief_map_create_f32(box_heights, BOX_TEXELS, BOX, BOX,
                                        OCEAN_RELIEF_EDGE_CLAMP, OCEAN_RELIEF_RANGE_REFUSE,
                                        &map)) ||
        !OK(ocean_relief_cones_create(map, &p, NULL, NULL, &cones))) {
        ocean_relief_map_destroy(map);
        return;
    }
    rays[0] = ray(0.5f, 0.5f, 0.0f, 0.0f, 1.0f);  /* on the top */
    rays[1] = ray(0.1f, 0.1f, 0.0f, 0.0f, 1.0f);  /* on the floor */
    /* 45 degrees towards +u with a relief 0.1 texture widths deep: 6.4 texels per unit depth,
       from u = 20/64. The ramp of the -u wall has depth 1 - (64 u - 23.5) for 64 u in
       [23.5, 24.5]; the ray 64 u = 20 + 6.4 z meets it where z = 4.5 - 6.4 z. */
    rays[2] = ray(20.0f / 64.0f, 0.5f, 0.1f, 0.0f, 1.0f);
    z_wall = 4.5 / 7.4;
    u_wall = (20.0 + 6.4 * z_wall) / 64.0;
    if (OK(ocean_relief_trace(cones, &relaxed, rays, 2, hits))) {
        CHECK(hits[0].pos.u == 0.5f && hits[0].pos.v == 0.5f && hits[0].pos.depth == 0.0f,
              "box top: (%g, %g, %g), expected (0.5, 0.5, 0)", hits[0].pos.u, hits[0].pos.v,
              hits[0].pos.depth);
        CHECK(hits[1].pos.u == 0.1f && hits[1].pos.v == 0.1f &&
                  hits[1].pos.depth == 1.0f - 1.0f / 128.0f,
              "floor: (%g, %g, %.9g), expected (0.1, 0.1, %.9g)", hits[1].pos.u, hits[1].pos.v,
              hits[1].pos.depth, 1.0 - 1.0 / 128.0);
    }
    /* The wall: a shared budget of 64 fetches lands within a hundredth of a texel of the analytic
       point (the cones in front of a wall are narrow: a grazing approach needs the steps). */
    if (OK(ocean_relief_trace(cones, &shared, &rays[2], 1, &hits[2]))) {
        printf("wall hit: u %.6f (analytic %.6f), depth %.6f (analytic %.6f), %u fetches\n",
               64.0 * hits[2].pos.u, 64.0 * u_wall, hits[2].pos.depth, z_wall,
               hits[2].fetches);
        CHECK(fabs(64.0 * (hits[2].pos.u - u_wall)) < 0.01 && hits[2].pos.v == 0.5f,
              "wall hit at 64 u = %.5f, expected %.5f", 64.0 * hits[2].pos.u, 64.0 * u_wall);
        CHECK(fabs(hits[2].pos.depth - z_wall) < 0.01 / 6.4,
              "wall hit at depth %.5f, expected %.5f", hits[2].pos.depth, z_wall);
    }

    /* Shadows: light 45 degrees up from +u, relief 0.1 texture widths deep. */
    points[0].u = 21.0f / 64.0f; /* floor, 2.5 texels from the ramp's foot: shadowed */
    points[1].u = 14.0f / 64.0f; /* floor, 9.5 texels away, beyond 6.4: lit */
    points[2].u = 48.0f / 64.0f; /* floor on the lit side */
    points[3].u = 0.5f;          /* the box's top */
    points[0].v = points[1].v = points[2].v = points[3].v = 0.5f;
    points[0].depth = points[1].depth = points[2].depth = 1.0f;
    points[3].depth = 0.0f;
    memset(shadow, 7, sizeof shadow);
    if (OK(ocean_relief_shadow(cones, &relaxed, points, 4, 1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                               shadow)))
        CHECK(shadow[0] == 1 && shadow[1] == 0 && shadow[2] == 0 && shadow[3] == 0,
              "shadows %u %u %u %u, expected 1 0 0 0", shadow[0], shadow[1], shadow[2],
              shadow[3]);
    /* The light from -u: the mirror image (43/64 is 2.5 texels beyond the +u ramp's foot). */
    points[0].u = 43.0f / 64.0f;
    points[1].u = 50.0f / 64.0f;
    points[2].u = 16.0f / 64.0f;
    if (OK(ocean_relief_shadow(cones, &relaxed, points, 4, -1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                               shadow)))
        CHECK(shadow[0] == 1 && shadow[1] == 0 && shadow[2] == 0 && shadow[3] == 0,
              "mirrored shadows %u %u %u %u, expected 1 0 0 0", shadow[0], shadow[1],
              shadow[2], shadow[3]);
    /* Below the horizon everything is in shadow. */
    if (OK(ocean_relief_shadow(cones, &relaxed, points, 4, 1.0f, 0.0f, -0.1f, 0.1f, 0.05f,
                               shadow)))
        CHECK(shadow[0] == 1 && shadow[1] == 1 && shadow[2] == 1 && shadow[3] == 1,
              "light below the horizon: %u %u %u %u", shadow[0], shadow[1], shadow[2],
              shadow[3]);
    ocean_relief_cones_destroy(cones);
    ocean_relief_map_destroy(map);
}

/* A progress callback: records the calls and cancels on call `cancel_at` (0: never). */
typedef struct Progress {
    int calls;
    int cancel_at;
    size_t first_done, last_done, total;
    int monotonic;
} Progress;

static int on_progress(void *user, size_t done, size_t total)
{
    Progress *p = (Progress *)user;
    if (p->calls == 0)
        p->first_done = done;
    else if (done <= p->last_done)
        p->monotonic = 0;
    p->calls++;
    p->last_done = done;
    p->total = total;
    return p->calls == p->cancel_at;
}

static void test_progress_and_cancel(void)
{
    static float texels[4 * BOX_TEXELS];
    OceanReliefMap *map = NULL;
    OceanReliefCones *cones = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 1.0f);
    Progress prog;
    size_t i;
    int untouched = 1;

    make_box();
    if (!OK(ocean_relief_map_create_f32(box_heights, BOX_TEXELS, BOX, BOX,
                                        OCEAN_RELIEF_EDGE_CLAMP, OCEAN_RELIEF_RANGE_REFUSE,
                                        &map)))
        return;
    /* To completion: 65 rows of cells in clamp mode, 2 rows a band (ceil(65 / 64)), so 33
       bands and 34 calls, from 0 to 65. */
    memset(&prog, 0, sizeof prog);
    prog.monotonic = 1;
    if (OK(ocean_relief_cones_create(map, &p, on_progress, &prog, &cones))) {
        CHECK(prog.calls == 34, "%d progress calls, expected 34", prog.calls);
        CHECK(prog.first_done == 0 && prog.last_done == 65 && prog.total == 65,
              "progress from %zu to %zu of %zu, expected 0 to 65 of 65", prog.first_done,
              prog.last_done, prog.total);
        CHECK(prog.monotonic, "progress went backwards");
    }
    ocean_relief_cones_destroy(cones);

    /* Cancelled on the second call (after the first band). */
    memset(&prog, 0, sizeof prog);
    prog.cancel_at = 2;
    cones = NULL;
    EXPECT_MSG(ocean_relief_cones_create(map, &p, on_progress, &prog, &cones),
               OCEAN_STATUS_CANCELLED, "cancelled");
    CHECK(cones == NULL, "handle written on cancellation");
    CHECK(prog.calls == 2, "%d calls after cancelling on the second", prog.calls);

    /* Cancelled straight into a buffer: untouched. */
    for (i = 0; i < 4 * BOX_TEXELS; i++)
        texels[i] = 7.0f;
    memset(&prog, 0, sizeof prog);
    prog.cancel_at = 5;
    EXPECT(ocean_relief_generate_texels(map, &p, on_progress, &prog, texels, 4 * BOX_TEXELS),
           OCEAN_STATUS_CANCELLED);
    for (i = 0; i < 4 * BOX_TEXELS; i++)
        untouched &= texels[i] == 7.0f;
    CHECK(untouched, "texels written on cancellation");
    CHECK(prog.calls == 5, "%d calls after cancelling on the fifth", prog.calls);
    CHECK(strcmp(ocean_status_message(OCEAN_STATUS_CANCELLED),
                 "cancelled by the caller's progress callback") == 0,
          "status message: %s", ocean_status_message(OCEAN_STATUS_CANCELLED));
    ocean_relief_map_destroy(map);
}

/* Quad-directional cones (section 18.1), on the box map with a cap of 4:
 * - the texture array: 4 layers of [depth, c_k, D_k, E_k]; every layer holds the map's depths,
 *   every quadrant cone is at least the isotropic one (fewer rays to serve), and at texel
 *   (10, 32), 14 texels on the -u side of the box, the layers of rays heading -u (1 and 3) see
 *   nothing but the flat floor, so their cone is the cap 4.0, while layer 0 (+u, +v) and the
 *   isotropic cone are limited by the box: a ray of ratio 4 from the top of that texel would
 *   enter the box 13.5 texels on at depth 0.05 and leave it above the floor;
 * - the tracer: a vertical ray on the floor reads layer 0 and hits at 1 - 1/128 as the
 *   isotropic one does, the 45-degree ray at the -u wall hits the analytic point within a
 *   hundredth of a texel with the same shared budget;
 * - shadows: the light ray reads its own quadrant (light from +u: rays heading -u, layer 1) and
 *   the box shadows the same points as with isotropic cones;
 * - progress: 65 rows of cells a layer in bands of ceil(65 / 16) = 5 rows, 13 bands a layer, so
 *   1 + 4 x 13 = 53 calls from 0 to 4 x 65 = 260; cancellation leaves handle and buffer alone;
 * - every error path with its outputs untouched. */
static void test_quad(void)
{
    static float quad[16 * BOX_TEXELS], iso[4 * BOX_TEXELS], depths[BOX_TEXELS];
    OceanReliefMap *map = NULL;
    OceanReliefQuadCones *cones = NULL, *sentinel = (OceanReliefQuadCones *)&map;
    OceanReliefCones *isotropic = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 4.0f);
    OceanReliefMethod relaxed = method(OCEAN_RELIEF_TRACER_RELAXED, 15, 6,
                                       OCEAN_RELIEF_SEARCH_LAST_STEP);
    OceanReliefMethod shared = method(OCEAN_RELIEF_TRACER_RELAXED, 58, 6,
                                      OCEAN_RELIEF_SEARCH_SHARED);
    OceanReliefRay rays[2];
    OceanReliefHit hits[2];
    OceanReliefPoint points[4];
    uint8_t shadow[4];
    Progress prog;
    uint32_t side = 0;
    size_t i, k, narrower = 0, depth_mismatch = 0;
    int untouched;
    double z_wall = 4.5 / 7.4, u_wall = (20.0 + 6.4 * z_wall) / 64.0;
    const size_t at = 32 * BOX + 10;

    CHECK(OCEAN_RELIEF_QUAD_LAYERS == 4 && OCEAN_RELIEF_QUAD_X_NEG == 1 &&
              OCEAN_RELIEF_QUAD_Y_NEG == 2,
          "layer constants");
    make_box();
    if (!OK(ocean_relief_map_create_f32(box_heights, BOX_TEXELS, BOX, BOX,
                                        OCEAN_RELIEF_EDGE_CLAMP, OCEAN_RELIEF_RANGE_REFUSE,
                                        &map)))
        return;
    memset(&prog, 0, sizeof prog);
    prog.monotonic = 1;
    if (!OK(ocean_relief_quad_cones_create(map, &p, on_progress, &prog, &cones)) ||
        !OK(ocean_relief_cones_create(map, &p, NULL, NULL, &isotropic))) {
        ocean_relief_quad_cones_destroy(cones);
        ocean_relief_map_destroy(map);
        return;
    }
    CHECK(prog.calls == 53, "%d progress calls, expected 53", prog.calls);
    CHECK(prog.first_done == 0 && prog.last_done == 260 && prog.total == 260,
          "progress from %zu to %zu of %zu, expected 0 to 260 of 260", prog.first_done,
          prog.last_done, prog.total);
    CHECK(prog.monotonic, "progress went backwards");
    if (OK(ocean_relief_quad_cones_size(cones, &side)))
        CHECK(side == BOX, "side %u", side);

    /* The texture array against the map and the isotropic cones. */
    if (OK(ocean_relief_quad_cones_texels(cones, quad, 16 * BOX_TEXELS)) &&
        OK(ocean_relief_cones_texels(isotropic, iso, 4 * BOX_TEXELS)) &&
        OK(ocean_relief_map_depths(map, depths, BOX_TEXELS))) {
        for (k = 0; k < 4; k++)
            for (i = 0; i < BOX_TEXELS; i++) {
                const float *t = &quad[4 * (k * BOX_TEXELS + i)];
                depth_mismatch += t[0] != depths[i];
                narrower += t[1] < iso[4 * i + 1] || t[2] < iso[4 * i + 2] ||
                            t[3] < iso[4 * i + 3];
            }
        CHECK(depth_mismatch == 0, "%zu layer depths differ from the map's", depth_mismatch);
        CHECK(narrower == 0, "%zu quadrant texels narrower than the isotropic ones", narrower);
        CHECK(quad[4 * (1 * BOX_TEXELS + at) + 1] == 4.0f &&
                  quad[4 * (3 * BOX_TEXELS + at) + 1] == 4.0f,
              "texel (10, 32), layers 1 and 3: cones %g and %g, expected the cap 4",
              quad[4 * (1 * BOX_TEXELS + at) + 1], quad[4 * (3 * BOX_TEXELS + at) + 1]);
        CHECK(quad[4 * at + 1] < 4.0f && iso[4 * at + 1] < 4.0f,
              "texel (10, 32): layer 0 cone %g, isotropic %g, expected below the cap",
              quad[4 * at + 1], iso[4 * at + 1]);
    }

    /* Tracing. */
    rays[0] = ray(0.1f, 0.1f, 0.0f, 0.0f, 1.0f);
    rays[1] = ray(20.0f / 64.0f, 0.5f, 0.1f, 0.0f, 1.0f);
    if (OK(ocean_relief_quad_trace(cones, &relaxed, rays, 1, hits)))
        CHECK(hits[0].pos.u == 0.1f && hits[0].pos.v == 0.1f &&
                  hits[0].pos.depth == 1.0f - 1.0f / 128.0f,
              "quad floor: (%g, %g, %.9g), expected (0.1, 0.1, %.9g)", hits[0].pos.u,
              hits[0].pos.v, hits[0].pos.depth, 1.0 - 1.0 / 128.0);
    if (OK(ocean_relief_quad_trace(cones, &shared, &rays[1], 1, &hits[1]))) {
        printf("quad wall hit: u %.6f (analytic %.6f), depth %.6f (analytic %.6f), %u fetches\n",
               64.0 * hits[1].pos.u, 64.0 * u_wall, hits[1].pos.depth, z_wall,
               hits[1].fetches);
        CHECK(fabs(64.0 * (hits[1].pos.u - u_wall)) < 0.01 && hits[1].pos.v == 0.5f,
              "quad wall hit at 64 u = %.5f, expected %.5f", 64.0 * hits[1].pos.u,
              64.0 * u_wall);
        CHECK(fabs(hits[1].pos.depth - z_wall) < 0.01 / 6.4,
              "quad wall hit at depth %.5f, expected %.5f", hits[1].pos.depth, z_wall);
    }

    /* Shadows, as in test_box. */
    points[0].u = 21.0f / 64.0f;
    points[1].u = 14.0f / 64.0f;
    points[2].u = 48.0f / 64.0f;
    points[3].u = 0.5f;
    points[0].v = points[1].v = points[2].v = points[3].v = 0.5f;
    points[0].depth = points[1].depth = points[2].depth = 1.0f;
    points[3].depth = 0.0f;
    memset(shadow, 7, sizeof shadow);
    if (OK(ocean_relief_quad_shadow(cones, &relaxed, points, 4, 1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                                    shadow)))
        CHECK(shadow[0] == 1 && shadow[1] == 0 && shadow[2] == 0 && shadow[3] == 0,
              "quad shadows %u %u %u %u, expected 1 0 0 0", shadow[0], shadow[1], shadow[2],
              shadow[3]);
    points[0].u = 43.0f / 64.0f;
    points[1].u = 50.0f / 64.0f;
    points[2].u = 16.0f / 64.0f;
    if (OK(ocean_relief_quad_shadow(cones, &relaxed, points, 4, -1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                                    shadow)))
        CHECK(shadow[0] == 1 && shadow[1] == 0 && shadow[2] == 0 && shadow[3] == 0,
              "mirrored quad shadows %u %u %u %u, expected 1 0 0 0", shadow[0], shadow[1],
              shadow[2], shadow[3]);

    /* Errors: every output untouched. */
    for (i = 0; i < 16 * BOX_TEXELS; i++)
        quad[i] = 7.0f;
    EXPECT_MSG(ocean_relief_quad_cones_texels(cones, quad, 4 * BOX_TEXELS),
               OCEAN_STATUS_LENGTH_MISMATCH, "len");
    EXPECT(ocean_relief_quad_cones_texels(cones, NULL, 16 * BOX_TEXELS),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_relief_quad_cones_texels(cones, (float *)((char *)quad + 2), 16 * BOX_TEXELS),
           OCEAN_STATUS_MISALIGNED_POINTER);
    EXPECT(ocean_relief_quad_cones_texels(NULL, quad, 16 * BOX_TEXELS),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_relief_quad_generate_texels(map, &p, NULL, NULL, quad, 16 * BOX_TEXELS - 1),
               OCEAN_STATUS_LENGTH_MISMATCH, "len");
    p.kind = 7;
    EXPECT_MSG(ocean_relief_quad_generate_texels(map, &p, NULL, NULL, quad, 16 * BOX_TEXELS),
               OCEAN_STATUS_INVALID_ARGUMENT, "kind");
    p.kind = OCEAN_RELIEF_CONE_KIND_RELAXED;
    memset(&prog, 0, sizeof prog);
    prog.cancel_at = 5;
    EXPECT(ocean_relief_quad_generate_texels(map, &p, on_progress, &prog, quad, 16 * BOX_TEXELS),
           OCEAN_STATUS_CANCELLED);
    CHECK(prog.calls == 5, "%d calls after cancelling on the fifth", prog.calls);
    untouched = 1;
    for (i = 0; i < 16 * BOX_TEXELS; i++)
        untouched &= quad[i] == 7.0f;
    CHECK(untouched, "quad texels written on failure");

    {
        OceanReliefQuadCones *out = sentinel;
        memset(&prog, 0, sizeof prog);
        prog.cancel_at = 2;
        EXPECT_MSG(ocean_relief_quad_cones_create(map, &p, on_progress, &prog, &out),
                   OCEAN_STATUS_CANCELLED, "cancelled");
        CHECK(prog.calls == 2, "%d calls after cancelling on the second", prog.calls);
        p.max_ratio = NAN;
        EXPECT(ocean_relief_quad_cones_create(map, &p, NULL, NULL, &out),
               OCEAN_STATUS_NON_FINITE);
        p.max_ratio = 4.0f;
        EXPECT(ocean_relief_quad_cones_create(NULL, &p, NULL, NULL, &out),
               OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_relief_quad_cones_create(map, NULL, NULL, NULL, &out),
               OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_relief_quad_cones_create(map, &p, NULL, NULL, NULL),
               OCEAN_STATUS_NULL_POINTER);
        CHECK(out == sentinel, "quad handle written on failure");
    }
    side = 99;
    EXPECT(ocean_relief_quad_cones_size(NULL, &side), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_relief_quad_cones_size(cones, NULL), OCEAN_STATUS_NULL_POINTER);
    CHECK(side == 99, "size written on failure");

    rays[1] = ray(0.2f, 0.2f, 0.1f, 0.0f, 0.0f);
    memset(hits, 0x7f, sizeof hits);
    EXPECT_MSG(ocean_relief_quad_trace(cones, &relaxed, rays, 2, hits),
               OCEAN_STATUS_INVALID_ARGUMENT, "rays[1].dir_z");
    rays[1].dir_x = NAN;
    EXPECT_MSG(ocean_relief_quad_trace(cones, &relaxed, rays, 2, hits), OCEAN_STATUS_NON_FINITE,
               "rays[1].dir_x");
    EXPECT(ocean_relief_quad_trace(cones, &relaxed, rays, 0, hits), OCEAN_STATUS_EMPTY);
    EXPECT(ocean_relief_quad_trace(NULL, &relaxed, rays, 1, hits), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_relief_quad_trace(cones, &relaxed, rays, 2, (OceanReliefHit *)&rays[1]),
               OCEAN_STATUS_INVALID_ARGUMENT, "overlap");
    {
        OceanReliefMethod m = relaxed;
        m.search = 5;
        EXPECT_MSG(ocean_relief_quad_trace(cones, &m, rays, 1, hits),
                   OCEAN_STATUS_INVALID_ARGUMENT, "search");
    }
    CHECK(hits[0].fetches == 0x7f7f7f7fu && hits[1].fetches == 0x7f7f7f7fu,
          "quad hits written on failure");

    memset(shadow, 7, sizeof shadow);
    EXPECT_MSG(ocean_relief_quad_shadow(cones, &relaxed, points, 4, 1.0f, 0.0f, 1.0f, 0.1f, 2.0f,
                                        shadow),
               OCEAN_STATUS_INVALID_ARGUMENT, "bias");
    EXPECT_MSG(ocean_relief_quad_shadow(cones, &relaxed, points, 4, 1.0f, 0.0f, 1.0f, -0.1f,
                                        0.05f, shadow),
               OCEAN_STATUS_INVALID_ARGUMENT, "depth_scale");
    EXPECT(ocean_relief_quad_shadow(cones, &relaxed, points, 4, NAN, 0.0f, 1.0f, 0.1f, 0.05f,
                                    shadow),
           OCEAN_STATUS_NON_FINITE);
    EXPECT(ocean_relief_quad_shadow(cones, &relaxed, points, 0, 1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                                    shadow),
           OCEAN_STATUS_EMPTY);
    EXPECT(ocean_relief_quad_shadow(cones, &relaxed, NULL, 4, 1.0f, 0.0f, 1.0f, 0.1f, 0.05f,
                                    shadow),
           OCEAN_STATUS_NULL_POINTER);
    CHECK(shadow[0] == 7 && shadow[1] == 7 && shadow[2] == 7 && shadow[3] == 7,
          "quad shadows written on failure");

    ocean_relief_quad_cones_destroy(cones);
    ocean_relief_quad_cones_destroy(NULL);
    ocean_relief_cones_destroy(isotropic);
    ocean_relief_map_destroy(map);
}

static void test_errors(void)
{
    static float h[FLAT_TEXELS], out[4 * FLAT_TEXELS];
    OceanReliefMap *map = NULL, *sentinel = (OceanReliefMap *)&map;
    OceanReliefCones *cones = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 1.0f);
    OceanReliefMethod good = method(OCEAN_RELIEF_TRACER_RELAXED, 15, 6, 0);
    OceanReliefRay rays[2];
    OceanReliefHit hits[2];
    float *huge;
    size_t i;
    int untouched;

    for (i = 0; i < FLAT_TEXELS; i++)
        h[i] = (float)i / FLAT_TEXELS;
    map = sentinel;
    EXPECT_MSG(ocean_relief_map_create_f32(h, 0, 0, 0, 0, 0, &map), OCEAN_STATUS_EMPTY, "empty");
    EXPECT_MSG(ocean_relief_map_create_f32(h, 128, 16, 8, 0, 0, &map),
               OCEAN_STATUS_INVALID_ARGUMENT, "square");
    EXPECT(ocean_relief_map_create_f32(h, FLAT_TEXELS - 1, FLAT, FLAT, 0, 0, &map),
           OCEAN_STATUS_LENGTH_MISMATCH);
    EXPECT_MSG(ocean_relief_map_create_f32(h, FLAT_TEXELS, FLAT, FLAT, 5, 0, &map),
               OCEAN_STATUS_INVALID_ARGUMENT, "edge");
    EXPECT(ocean_relief_map_create_f32(NULL, FLAT_TEXELS, FLAT, FLAT, 0, 0, &map),
           OCEAN_STATUS_NULL_POINTER);
    h[3] = NAN;
    EXPECT_MSG(ocean_relief_map_create_f32(h, FLAT_TEXELS, FLAT, FLAT, 0, 0, &map),
               OCEAN_STATUS_NON_FINITE, "(3, 0)");
    h[3] = 2.0f;
    EXPECT_MSG(ocean_relief_map_create_f32(h, FLAT_TEXELS, FLAT, FLAT, 0,
                                           OCEAN_RELIEF_RANGE_REFUSE, &map),
               OCEAN_STATUS_INVALID_ARGUMENT, "outside [0, 1]");
    CHECK(map == sentinel, "map handle written on failure");
    /* The documented cap: 4096 per side. */
    huge = calloc((size_t)4097 * 4097, sizeof *huge);
    if (huge) {
        EXPECT_MSG(ocean_relief_map_create_f32(huge, (size_t)4097 * 4097, 4097, 4097, 0, 0, &map),
                   OCEAN_STATUS_INVALID_ARGUMENT, "4096");
        free(huge);
    }
    CHECK(map == sentinel, "map handle written on failure");
    /* Normalised instead: 2.0 becomes height 1, depth 0. */
    map = NULL;
    if (!OK(ocean_relief_map_create_f32(h, FLAT_TEXELS, FLAT, FLAT, OCEAN_RELIEF_EDGE_WRAP,
                                        OCEAN_RELIEF_RANGE_NORMALIZE, &map)))
        return;
    if (OK(ocean_relief_map_depths(map, out, FLAT_TEXELS)))
        CHECK(out[3] == 0.0f && out[0] == 1.0f, "normalised depths %g %g, expected 0 and 1",
              out[3], out[0]);

    p.max_ratio = NAN;
    EXPECT(ocean_relief_cones_create(map, &p, NULL, NULL, &cones), OCEAN_STATUS_NON_FINITE);
    p.max_ratio = 100.0f;
    EXPECT_MSG(ocean_relief_cones_create(map, &p, NULL, NULL, &cones),
               OCEAN_STATUS_INVALID_ARGUMENT, "max_ratio");
    p.max_ratio = 1.0f;
    p.kind = 7;
    EXPECT_MSG(ocean_relief_cones_create(map, &p, NULL, NULL, &cones),
               OCEAN_STATUS_INVALID_ARGUMENT, "kind");
    CHECK(cones == NULL, "cones handle written on failure");
    p.kind = OCEAN_RELIEF_CONE_KIND_RELAXED;
    for (i = 0; i < 4 * FLAT_TEXELS; i++)
        out[i] = 7.0f;
    EXPECT(ocean_relief_generate_texels(map, &p, NULL, NULL, out, 4 * FLAT_TEXELS - 4),
           OCEAN_STATUS_LENGTH_MISMATCH);
    EXPECT_MSG(ocean_relief_generate_encoded(map, &p, NULL, NULL, 9, out, 3 * FLAT_TEXELS),
               OCEAN_STATUS_INVALID_ARGUMENT, "encoding");
    EXPECT(ocean_relief_generate_encoded(map, &p, NULL, NULL, OCEAN_RELIEF_ENCODING_F32,
                                         (char *)out + 2, 3 * FLAT_TEXELS),
           OCEAN_STATUS_MISALIGNED_POINTER);
    untouched = 1;
    for (i = 0; i < 4 * FLAT_TEXELS; i++)
        untouched &= out[i] == 7.0f;
    CHECK(untouched, "output written on failure");

    if (OK(ocean_relief_cones_create(map, &p, NULL, NULL, &cones))) {
        OceanReliefMethod m = good;
        rays[0] = ray(0.2f, 0.2f, 0.1f, 0.0f, 1.0f);
        rays[1] = ray(0.2f, 0.2f, 0.1f, 0.0f, 0.0f);
        memset(hits, 0x7f, sizeof hits);
        EXPECT_MSG(ocean_relief_trace(cones, &good, rays, 2, hits), OCEAN_STATUS_INVALID_ARGUMENT,
                   "rays[1].dir_z");
        rays[1].dir_z = INFINITY;
        EXPECT_MSG(ocean_relief_trace(cones, &good, rays, 2, hits), OCEAN_STATUS_NON_FINITE,
                   "rays[1].dir_z");
        EXPECT(ocean_relief_trace(cones, &good, rays, 0, hits), OCEAN_STATUS_EMPTY);
        m.steps = 0;
        EXPECT_MSG(ocean_relief_trace(cones, &m, rays, 1, hits), OCEAN_STATUS_INVALID_ARGUMENT,
                   "steps");
        m = good;
        m.method = 9;
        EXPECT_MSG(ocean_relief_trace(cones, &m, rays, 1, hits), OCEAN_STATUS_INVALID_ARGUMENT,
                   "method");
        EXPECT(ocean_relief_trace(cones, &good, rays, 1, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(hits[0].fetches == 0x7f7f7f7fu, "hits written on failure");
        EXPECT(ocean_relief_mips_create(cones, 3, NULL), OCEAN_STATUS_NULL_POINTER);
    }
    ocean_relief_cones_destroy(cones);
    ocean_relief_map_destroy(map);
    ocean_relief_map_destroy(NULL);
    ocean_relief_cones_destroy(NULL);
    ocean_relief_mips_destroy(NULL);
}

static void test_uniforms(void)
{
    OceanReliefScene scene;
    OceanCamera camera;
    unsigned char block[OCEAN_RELIEF_UNIFORMS_SIZE];
    unsigned char small[OCEAN_RELIEF_UNIFORMS_SIZE - 1];
    float origin[4];
    uint32_t words[8];
    size_t i;

    if (!OK(ocean_relief_scene_default(&scene)))
        return;
    CHECK(scene.method.method == OCEAN_RELIEF_TRACER_RELAXED && scene.method.steps == 15 &&
          scene.method.binary == 6 && scene.shadows == 1 && scene.light_color[0] == 1.0f &&
              scene.light_color[1] == 1.0f && scene.light_color[2] == 1.0f,
          "default scene");
    /* At (0.5, 2, -0.5) looking along -z: OpenGL's [-1, 1] depth. */
    camera = check_camera_at(0.5, 2.0, -0.5, 1.0, 16.0 / 9.0, 0.1, 100.0,
                             OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
    /* A sky: its coefficients reach the block as E / pi, a Lambertian surface's radiance. */
    scene.sky.k[2].g = 3.0;
    if (!OK(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 8, 1, block,
                                  sizeof block)))
        return;
    {
        float row[4];
        memcpy(row, block + 256 + 2 * 16, sizeof row);
        CHECK(row[0] == 0.0f && row[1] == (float)(3.0 / 3.14159265358979323846) &&
                  row[2] == 0.0f && row[3] == 0.0f,
              "sky row 2: %g %g %g %g", row[0], row[1], row[2], row[3]);
    }
    /* Offsets of the std140 block: quad_origin at 64, trace at 208, steps at 224. */
    memcpy(origin, block + 64, sizeof origin);
    CHECK(origin[0] == -0.5f && origin[1] == -2.0f && origin[2] == 0.5f && origin[3] == 0.0f,
          "quad origin relative to the eye: %g %g %g %g", origin[0], origin[1], origin[2],
          origin[3]);
    memcpy(words, block + 208, sizeof words);
    CHECK(words[0] == 256 && words[1] == OCEAN_RELIEF_EDGE_WRAP &&
          words[2] == OCEAN_RELIEF_TRACER_RELAXED && words[3] == OCEAN_RELIEF_SEARCH_LAST_STEP,
          "trace words %u %u %u %u", words[0], words[1], words[2], words[3]);
    /* 15 cone steps, 6 bisections, shadows (1) and sRGB encoding (2). */
    CHECK(words[4] == 15 && words[5] == 6 && words[6] == 3, "step words %u %u %u", words[4],
          words[5], words[6]);
    /* shading at 240: depth scale, bias, 0, mip levels (256 down to 2: 8). */
    memcpy(origin, block + 240, sizeof origin);
    CHECK(origin[2] == 0.0f && origin[3] == 8.0f, "shading %g %g", origin[2], origin[3]);
    /* The polygon at 416: the default draws the whole quad, (0,0) (1,0) (1,1) (0,1). */
    {
        float corners[8];
        memcpy(corners, block + 416, sizeof corners);
        CHECK(corners[0] == 0.0f && corners[1] == 0.0f && corners[2] == 1.0f &&
                  corners[3] == 0.0f && corners[4] == 1.0f && corners[5] == 1.0f &&
                  corners[6] == 0.0f && corners[7] == 1.0f,
              "default polygon %g %g %g %g %g %g %g %g", corners[0], corners[1], corners[2],
              corners[3], corners[4], corners[5], corners[6], corners[7]);
    }
    /* A zeroed polygon encloses nothing: refused, not drawn as nothing. */
    {
        OceanReliefScene zeroed = scene;
        memset(zeroed.corners, 0, sizeof zeroed.corners);
        EXPECT(ocean_relief_uniforms(&camera, &zeroed, 256, OCEAN_RELIEF_EDGE_WRAP, 8, 1, block,
                                     sizeof block),
               OCEAN_STATUS_INVALID_ARGUMENT);
    }
    EXPECT(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 9, 1, block,
                                 sizeof block),
           OCEAN_STATUS_INVALID_ARGUMENT);

    memset(small, 0x5A, sizeof small);
    EXPECT_MSG(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 1, 1, small,
                                     sizeof small),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 448");
    EXPECT_MSG(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 1, 1, small,
                                     sizeof small + 2),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 448");
    scene.sky.k[8].b = NAN;
    EXPECT(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 1, 1, block,
                                 sizeof block),
           OCEAN_STATUS_NON_FINITE);
    scene.sky.k[8].b = 0.0;
    scene.tiles_u = 0.0;
    EXPECT(ocean_relief_uniforms(&camera, &scene, 256, OCEAN_RELIEF_EDGE_WRAP, 1, 1, small,
                                 sizeof block),
           OCEAN_STATUS_INVALID_ARGUMENT);
    for (i = 0; i < sizeof small; i++)
        if (small[i] != 0x5A)
            break;
    CHECK(i == sizeof small, "the block was written on failure");
}

/*
 * Level of detail on the box map: the next level's depths are the 2x2 means (at a box corner,
 * the mean of one box texel and three floor texels is depth 3/4), the coarser map takes its
 * own cones, and the level a fragment reads grows with its footprint: 3 texels a pixel is
 * level 2 (2^1.5 <= 3 < 2^2.5), clamped to the levels present.
 */
static void test_lod(void)
{
    static float h[BOX_TEXELS], depths[BOX_TEXELS / 4];
    OceanReliefMap *map = NULL, *half = NULL, *none = NULL;
    OceanReliefCones *cones = NULL;
    OceanReliefConeParams p = cone_params(OCEAN_RELIEF_CONE_KIND_RELAXED, 1.0f);
    uint32_t side = 0, level = 99;
    const float t = 1.0f / BOX;
    size_t i, bad = 0;

    /* The box over texels 25..40, one texel off the 2 x 2 grid, so groups straddle its edges. */
    for (i = 0; i < BOX_TEXELS; i++) {
        size_t x = i % BOX, y = i / BOX;
        h[i] = (x >= 25 && x < 41 && y >= 25 && y < 41) ? 1.0f : 0.0f;
    }
    if (!OK(ocean_relief_map_create_f32(h, BOX_TEXELS, BOX, BOX, OCEAN_RELIEF_EDGE_CLAMP,
                                        OCEAN_RELIEF_RANGE_REFUSE, &map)))
        return;
    if (OK(ocean_relief_map_downsample(map, &half))) {
        OK(ocean_relief_map_size(half, &side));
        CHECK(side == BOX / 2, "downsampled side %u", side);
        if (OK(ocean_relief_map_depths(half, depths, BOX_TEXELS / 4))) {
            /* Group (12, 12) covers texels 24..25: one box texel (25, 25), three floor. */
            CHECK(depths[12 * (BOX / 2) + 12] == 0.75f, "corner depth %g",
                  depths[12 * (BOX / 2) + 12]);
            /* Group (13, 13) lies inside the box; (0, 0) on the floor. */
            CHECK(depths[13 * (BOX / 2) + 13] == 0.0f && depths[0] == 1.0f, "depths %g %g",
                  depths[13 * (BOX / 2) + 13], depths[0]);
            for (i = 0; i < BOX_TEXELS / 4; i++)
                bad += depths[i] != 0.0f && depths[i] != 0.5f && depths[i] != 0.75f &&
                       depths[i] != 1.0f;
            CHECK(bad == 0, "%zu means are not 0, 1/2, 3/4 or 1", bad);
        }
        CHECK(OK(ocean_relief_cones_create(half, &p, NULL, NULL, &cones)),
              "cones of the coarse map");
        ocean_relief_cones_destroy(cones);
        ocean_relief_map_destroy(half);
    }
    OK(ocean_relief_mip_level(3.0f * t, 0.0f, 0.0f, t, BOX, 6, &level));
    CHECK(level == 2, "3 texels a pixel: level %u", level);
    OK(ocean_relief_mip_level(3.0f * t, 0.0f, 0.0f, t, BOX, 2, &level));
    CHECK(level == 1, "clamped to 2 levels: level %u", level);
    OK(ocean_relief_mip_level(0.5f * t, 0.0f, 0.0f, 0.5f * t, BOX, 6, &level));
    CHECK(level == 0, "magnified: level %u", level);
    level = 99;
    EXPECT(ocean_relief_mip_level(t, 0.0f, 0.0f, t, BOX, 7, &level),
           OCEAN_STATUS_INVALID_ARGUMENT);
    CHECK(level == 99, "level written on failure");
    EXPECT(ocean_relief_mip_level(t, 0.0f, 0.0f, t, BOX, 1, NULL), OCEAN_STATUS_NULL_POINTER);
    /* The atlas of 6 levels of 64 texels: 96 x 64, level 1 at (64, 0), level 5 at (64, 60). */
    {
        uint32_t w = 0, hh = 0, x = 0, y = 0;
        OK(ocean_relief_mip_atlas_size(BOX, 6, &w, &hh));
        CHECK(w == 96 && hh == 64, "atlas %u x %u", w, hh);
        OK(ocean_relief_mip_atlas_origin(BOX, 1, &x, &y));
        CHECK(x == 64 && y == 0, "level 1 at (%u, %u)", x, y);
        OK(ocean_relief_mip_atlas_origin(BOX, 5, &x, &y));
        CHECK(x == 64 && y == 60, "level 5 at (%u, %u)", x, y);
        EXPECT(ocean_relief_mip_atlas_origin(BOX, 6, &x, &y), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_relief_mip_atlas_size(BOX, 7, &w, &hh), OCEAN_STATUS_INVALID_ARGUMENT);
    }
    EXPECT(ocean_relief_map_downsample(map, NULL), OCEAN_STATUS_NULL_POINTER);
    ocean_relief_map_destroy(map);
    /* A 2 x 2 map has no coarser level; nothing is written. */
    if (OK(ocean_relief_map_create_f32(h, 4, 2, 2, OCEAN_RELIEF_EDGE_WRAP,
                                       OCEAN_RELIEF_RANGE_REFUSE, &map))) {
        EXPECT(ocean_relief_map_downsample(map, &none), OCEAN_STATUS_INVALID_ARGUMENT);
        CHECK(none == NULL, "handle written on failure");
        ocean_relief_map_destroy(map);
    }
}

int main(void)
{
    test_flat_top();
    test_flat_half();
    test_box();
    test_uniforms();
    test_progress_and_cancel();
    test_quad();
    test_lod();
    test_errors();
    printf("test_relief.c: library %s, %d checks, %d failures\n", ocean_version(), checks,
           failures);
    return failures == 0 ? 0 : 1;
}
