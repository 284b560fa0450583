/*
 * Handle misuse from C: every CPU handle kind passed where another kind is expected, used after
 * it was destroyed, destroyed twice or through another kind's destroy, and memory that never was
 * a handle (zeroed, a stack address). Each must give OCEAN_STATUS_INVALID_HANDLE with a message
 * naming both kinds, leave the outputs untouched, and never crash, hang or free the wrong object:
 * the handles misused stay usable afterwards.
 *
 * The calls that used to hang are here by name: a waves or SAO handle given to the scene's
 * evaluate, heights and add-box functions (which lock the scene), and a destroyed scene.
 */
#include "ocean.h"
#include "check.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

enum { WAVES, SCENE, SPECTRUM, LIGHTING, SKY_MAP, MAP, CONES, MIPS, QUAD, SAO, EXPORT, KINDS };

static const char *const NAMES[KINDS] = {
    "OceanWaves",      "OceanWtbScene",      "OceanSpectrum",        "OceanLighting",
    "OceanSkyMap",     "OceanReliefMap",  "OceanReliefCones",     "OceanReliefMips",
    "OceanReliefQuadCones", "OceanSao",   "OceanShaderExport",
};

/* One call per kind that reads the handle and writes one output (a count or a size). The
 * output is a uint64_t holding SENTINEL before the call: untouched unless the call succeeds. */
static const uint64_t SENTINEL = 0x5eed5eed5eed5eedu;

static OceanStatus query(int kind, const void *h, uint64_t *out)
{
    size_t n = 0;
    uint32_t u = 0;
    double d = 0.0;
    OceanSaoInfo info;
    OceanStatus s;
    switch (kind) {
    case WAVES: s = ocean_waves_count((const OceanWaves *)h, &n); break;
    case SCENE: s = ocean_wtb_scene_box_count((OceanWtbScene *)h, &n); break;
    case SPECTRUM: s = ocean_spectrum_wave_count((const OceanSpectrum *)h, &n); break;
    case LIGHTING:
        s = ocean_lighting_sun_solid_angle((const OceanLighting *)h, &d);
        n = (size_t)(d > 0.0);
        break;
    case SKY_MAP: s = ocean_sky_map_level_count((const OceanSkyMap *)h, &u); n = u; break;
    case MAP: s = ocean_relief_map_size((const OceanReliefMap *)h, &u); n = u; break;
    case CONES: s = ocean_relief_cones_size((const OceanReliefCones *)h, &u); n = u; break;
    case MIPS: s = ocean_relief_mips_level_count((const OceanReliefMips *)h, &u); n = u; break;
    case QUAD:
        s = ocean_relief_quad_cones_size((const OceanReliefQuadCones *)h, &u);
        n = u;
        break;
    case SAO:
        s = ocean_sao_describe((const OceanSao *)h, &info);
        n = info.output_width;
        break;
    default: s = ocean_shader_export_file_count((const OceanShaderExport *)h, &n); break;
    }
    if (s == OCEAN_STATUS_OK)
        *out = n;
    return s;
}

static void destroy(int kind, void *h)
{
    switch (kind) {
    case WAVES: ocean_waves_destroy((OceanWaves *)h); break;
    case SCENE: ocean_wtb_scene_destroy((OceanWtbScene *)h); break;
    case SPECTRUM: ocean_spectrum_destroy((OceanSpectrum *)h); break;
    case LIGHTING: ocean_lighting_destroy((OceanLighting *)h); break;
    case SKY_MAP: ocean_sky_map_destroy((OceanSkyMap *)h); break;
    case MAP: ocean_relief_map_destroy((OceanReliefMap *)h); break;
    case CONES: ocean_relief_cones_destroy((OceanReliefCones *)h); break;
    case MIPS: ocean_relief_mips_destroy((OceanReliefMips *)h); break;
    case QUAD: ocean_relief_quad_cones_destroy((OceanReliefQuadCones *)h); break;
    case SAO: ocean_sao_destroy((OceanSao *)h); break;
    default: ocean_shader_export_destroy((OceanShaderExport *)h); break;
    }
}

/* One live handle of every kind, all small. Returns 0 if one could not be made. */
static int create_all(void *h[KINDS])
{
    OceanWaveDesc wave = {0.5, 20.0, 1.0, 0.0, 0.0, INFINITY};
    OceanWaterGridDesc grid = {0.0, 0.0, 1.0, 16, 16};
    OceanSpectrumParams sp;
    OceanSkyParams sky;
    OceanSeaParams sea;
    OceanReliefConeParams cp;
    OceanCamera cam;
    OceanSaoParams sao;
    float heights[16 * 16];
    int i;
    for (i = 0; i < 16 * 16; i++)
        heights[i] = (float)((i * 7) % 16) / 15.0f;
    memset(&cam, 0, sizeof cam);
    /* A GL perspective of 90 degrees, near 0.1, far 100 (column-major). */
    cam.view[0] = cam.view[5] = cam.view[10] = cam.view[15] = 1.0;
    cam.projection[0] = 1.0;
    cam.projection[5] = 1.0;
    cam.projection[10] = -100.1 / 99.9;
    cam.projection[11] = -1.0;
    cam.projection[14] = -20.0 / 99.9;
    cam.depth_convention = OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE;
    memset(h, 0, KINDS * sizeof h[0]);
    return OK(ocean_waves_create(&wave, 1, (OceanWaves **)&h[WAVES])) &&
           OK(ocean_wtb_scene_create(&grid, NULL, 0, (OceanWtbScene **)&h[SCENE])) &&
           OK(ocean_spectrum_params_default(&sp)) &&
           OK(ocean_spectrum_create(&sp, (OceanSpectrum **)&h[SPECTRUM])) &&
           OK(ocean_sky_params_default(&sky)) && OK(ocean_sea_params_default(&sea)) &&
           OK(ocean_lighting_create(&sky, &sea, (OceanLighting **)&h[LIGHTING])) &&
           OK(ocean_lighting_sky_map_create((const OceanLighting *)h[LIGHTING], 8,
                                            (OceanSkyMap **)&h[SKY_MAP])) &&
           OK(ocean_relief_map_create_f32(heights, 16 * 16, 16, 16, OCEAN_RELIEF_EDGE_WRAP,
                                          OCEAN_RELIEF_RANGE_REFUSE,
                                          (OceanReliefMap **)&h[MAP])) &&
           OK(ocean_relief_cone_params_default(&cp)) &&
           OK(ocean_relief_cones_create((const OceanReliefMap *)h[MAP], &cp, NULL, NULL,
                                        (OceanReliefCones **)&h[CONES])) &&
           OK(ocean_relief_mips_create((const OceanReliefCones *)h[CONES],
                                       OCEAN_RELIEF_MIP_GROUP, (OceanReliefMips **)&h[MIPS])) &&
           OK(ocean_relief_quad_cones_create((const OceanReliefMap *)h[MAP], &cp, NULL, NULL,
                                             (OceanReliefQuadCones **)&h[QUAD])) &&
           OK(ocean_sao_params_default(&sao)) &&
           OK(ocean_sao_create(64, 64, 8, &cam, OCEAN_SAO_DEPTH_WINDOW, &sao, (OceanSao **)&h[SAO])) &&
           OK(ocean_shader_export("trochoid", OCEAN_SHADER_LANGUAGE_GLSL,
                                  (OceanShaderExport **)&h[EXPORT]));
}

/* A failure with OCEAN_STATUS_INVALID_HANDLE whose message holds `a` and, if not NULL, `b`. */
static void expect_invalid(OceanStatus s, const char *what, const char *a, const char *b)
{
    const char *m = last_error();
    CHECK(s == OCEAN_STATUS_INVALID_HANDLE, "%s: status %u (%s), message %s", what,
          (unsigned)s, ocean_status_message(s), m);
    CHECK(strstr(m, a) != NULL && (b == NULL || strstr(m, b) != NULL),
          "%s: message \"%s\" lacks \"%s\" / \"%s\"", what, m, a, b ? b : "");
}

static void every_kind_refuses_every_other_kind(void *h[KINDS])
{
    int want, given;
    char what[96], wrong[96], need[96];
    for (want = 0; want < KINDS; want++) {
        for (given = 0; given < KINDS; given++) {
            uint64_t out = SENTINEL;
            OceanStatus s = query(want, h[given], &out);
            snprintf(what, sizeof what, "%s call given an %s", NAMES[want], NAMES[given]);
            if (want == given) {
                CHECK(s == OCEAN_STATUS_OK && out != SENTINEL && last_error()[0] == '\0',
                      "%s: status %u, message %s", what, (unsigned)s, last_error());
                continue;
            }
            snprintf(wrong, sizeof wrong, "is an %s handle", NAMES[given]);
            snprintf(need, sizeof need, "not an %s", NAMES[want]);
            expect_invalid(s, what, wrong, need);
            CHECK(out == SENTINEL, "%s: output written", what);
        }
    }
}

static void foreign_memory_is_never_a_handle(void)
{
    /* Zeroed memory, a stack address, small integers: none was returned by the library. */
    uint64_t zeroed[16] = {0};
    const void *foreign[4];
    int kind, i;
    foreign[0] = zeroed;
    foreign[1] = &zeroed[3];
    foreign[2] = (const void *)(uintptr_t)1;
    foreign[3] = (const void *)(uintptr_t)0x10;
    for (kind = 0; kind < KINDS; kind++)
        for (i = 0; i < 4; i++) {
            uint64_t out = SENTINEL;
            char what[96];
            snprintf(what, sizeof what, "%s call given foreign pointer %d", NAMES[kind], i);
            expect_invalid(query(kind, foreign[i], &out), what,
                           "no function of this library returned it", NAMES[kind]);
            CHECK(out == SENTINEL, "%s: output written", what);
            /* Destroying it frees nothing and says why; the zeroed memory stays zero. */
            destroy(kind, (void *)(uintptr_t)foreign[i]);
            CHECK(strstr(last_error(), "no function of this library returned it") != NULL,
                  "destroy of %s: message %s", what, last_error());
        }
    for (i = 0; i < 16; i++)
        CHECK(zeroed[i] == 0, "zeroed memory written at %d", i);
}

static void wrong_destroys_free_nothing(void *h[KINDS])
{
    int kind, by;
    for (kind = 0; kind < KINDS; kind++)
        for (by = 0; by < KINDS; by++) {
            uint64_t out = SENTINEL;
            if (by == kind)
                continue;
            destroy(by, h[kind]);
            CHECK(strstr(last_error(), NAMES[kind]) != NULL,
                  "%s destroyed through the %s function: message %s", NAMES[kind], NAMES[by],
                  last_error());
            CHECK(query(kind, h[kind], &out) == OCEAN_STATUS_OK,
                  "%s unusable after a destroy through the %s function: %s", NAMES[kind],
                  NAMES[by], last_error());
        }
}

/* The calls that locked a scene's mutex inside another object and hung. */
static void scene_calls_with_other_handles_return(void *h[KINDS])
{
    static const int others[] = {WAVES, SAO, SPECTRUM};
    OceanBoxDesc box;
    OceanWaveDesc train = {0.2, 8.0, 1.0, 0.0, 0.0, INFINITY};
    OceanDVec2 xz = {1.0, 1.0};
    OceanHeightSample sample;
    OceanVec3 pos[16 * 16], nrm[16 * 16];
    uint32_t id = 77;
    size_t i;
    memset(&box, 0, sizeof box);
    memset(&sample, 0x5a, sizeof sample);
    for (i = 0; i < sizeof others / sizeof others[0]; i++) {
        OceanWtbScene *wrong = (OceanWtbScene *)h[others[i]];
        expect_invalid(ocean_wtb_scene_heights_continuous(wrong, 0.0, &xz, 1, &sample),
                       "ocean_wtb_scene_heights_continuous", NAMES[others[i]], "not an OceanWtbScene");
        expect_invalid(ocean_wtb_scene_evaluate(wrong, 0.0, NULL, pos, nrm, 16 * 16, NULL),
                       "ocean_wtb_scene_evaluate", NAMES[others[i]], "not an OceanWtbScene");
        expect_invalid(ocean_wtb_scene_add_box(wrong, &box, &train, 1, &id), "ocean_wtb_scene_add_box",
                       NAMES[others[i]], "not an OceanWtbScene");
    }
    CHECK(id == 77, "box id written on failure");
    /* A spectrum where a lighting is wanted, mips where cones are wanted. */
    {
        OceanRgb rgb = {-1.0, -1.0, -1.0};
        uint32_t size = 12345;
        expect_invalid(
            ocean_lighting_sun_radiance((const OceanLighting *)h[SPECTRUM], &rgb),
            "ocean_lighting_sun_radiance", "is an OceanSpectrum handle", "not an OceanLighting");
        CHECK(rgb.r == -1.0, "radiance written on failure");
        expect_invalid(ocean_relief_cones_size((const OceanReliefCones *)h[MIPS], &size),
                       "ocean_relief_cones_size", "is an OceanReliefMips handle",
                       "not an OceanReliefCones");
        CHECK(size == 12345, "size written on failure");
    }
}

static void destroyed_handles_are_refused(void *h[KINDS])
{
    int kind;
    for (kind = 0; kind < KINDS; kind++) {
        uint64_t out = SENTINEL;
        char what[96];
        destroy(kind, h[kind]);
        snprintf(what, sizeof what, "%s used after destroy", NAMES[kind]);
        expect_invalid(query(kind, h[kind], &out), what, "was destroyed", NAMES[kind]);
        CHECK(out == SENTINEL, "%s: output written", what);
        /* The second destroy is a no-op that says so. */
        snprintf(what, sizeof what, "second destroy of an %s", NAMES[kind]);
        destroy(kind, h[kind]);
        CHECK(strstr(last_error(), "was destroyed") != NULL, "%s: message %s", what,
              last_error());
    }
    /* A destroyed scene no longer blocks anything. */
    {
        OceanDVec2 xz = {1.0, 1.0};
        OceanHeightSample sample;
        expect_invalid(ocean_wtb_scene_heights_continuous((OceanWtbScene *)h[SCENE], 0.0, &xz, 1,
                                                      &sample),
                       "heights of a destroyed scene", "was destroyed", "OceanWtbScene");
    }
}

int main(void)
{
    void *h[KINDS];
    if (create_all(h)) {
        every_kind_refuses_every_other_kind(h);
        foreign_memory_is_never_a_handle();
        wrong_destroys_free_nothing(h);
        scene_calls_with_other_handles_return(h);
        /* NULL is still NULL_POINTER, and destroying NULL leaves the message alone. */
        {
            uint64_t out = SENTINEL;
            EXPECT_MSG(query(WAVES, NULL, &out), OCEAN_STATUS_NULL_POINTER, "waves");
            ocean_waves_destroy(NULL);
            CHECK(strstr(last_error(), "waves") != NULL, "NULL destroy changed the message: %s",
                  last_error());
        }
        destroyed_handles_are_refused(h);
    }
    printf("test_misuse.c: library %s, %d checks, %d failures; %d handle kinds misused\n",
           ocean_version(), checks, failures, KINDS);
    return failures != 0;
}
