/*
 * C11 test of the shader side of the ocean renderer in the C ABI (ocean_surface_*): the uniform
 * block and the textures an engine uploads to draw the exported `ocean` shader in its own
 * pipeline, linked against libocean.a. No GPU is needed.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_draw.c libocean.a ...
 *
 * Expectations, each derived here:
 * - The defaults: the paper's filter (1, 2.5), a 512 sky map, sRGB encoding by the shader.
 * - The block for a camera at (10, 4, -20) looking along -z over a 96 x 64 viewport and a mesh
 *   with its point (0, 0) at (0, -100), spacing 0.5, 64 x 32 points: the mesh's origin relative
 *   to the eye is (-10, -4, -80) (offset 320) and its sides (64, 32) (offset 336); the eye
 *   height 4 (offset 128); the viewport (96, 64) and the projected grid's corner at minus 10 %
 *   of it (offset 144); the grid 16 x 11 vertices (ceil(1.2 * 96 / 8) + 1, ceil(1.2 * 64 / 8)
 *   + 1), the spectrum's wave count and the sRGB flag (offset 176); the wind +x (offset 192);
 *   a Sun (offset 224); the sky map size and OCEAN_SKY_MAP_EXTENT (offset 256). Without a
 *   mesh the last 32 bytes are zero and the rest is the same; another time gives the same
 *   block (the phases live in the wave texture).
 * - The wave texture: longest wave first; row 0's phases in [-pi, pi], changing with time
 *   while rows 1 and 2 do not; row 1's amplitude A and row 2's steepness k A with k = 2 pi /
 *   wavelength; row 2's suffix variances non-increasing along the row, their sum at column 0
 *   the spectrum's total slope variance (ocean_spectrum_total_slope_variance, to float
 *   precision).
 * - The Fresnel table: element 33 i + j is F - (1 - c)^5 for F =
 *   ocean_effective_fresnel_table(c, s, 0) at the node c = (i/32)^2, s = (j/32)^2.
 * - Every error path, with the outputs untouched.
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

#define W 96
#define H 64
#define PI 3.14159265358979323846

/* An OpenGL camera at the eye, looking along -z with y up: 60 degrees, the viewport's aspect. */
static OceanCamera camera_at(double x, double y, double z)
{
    return check_camera_at(x, y, z, 60.0 * PI / 180.0, (double)W / (double)H, 0.1, 5000.0,
                           OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE);
}

static float f32_at(const uint8_t *block, size_t offset)
{
    float f;
    memcpy(&f, block + offset, sizeof f);
    return f;
}

static uint32_t u32_at(const uint8_t *block, size_t offset)
{
    uint32_t u;
    memcpy(&u, block + offset, sizeof u);
    return u;
}

static int all_bytes(const uint8_t *p, size_t n, uint8_t v)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (p[i] != v)
            return 0;
    return 1;
}

static OceanWaterGridDesc mesh_desc(void)
{
    OceanWaterGridDesc g;
    g.origin_x = 0.0;
    g.origin_z = -100.0;
    g.spacing = 0.5;
    g.nx = 64;
    g.nz = 32;
    return g;
}

static void test_defaults(void)
{
    OceanSurfaceDrawParams p;
    OK(ocean_surface_draw_params_default(&p));
    CHECK(p.n_min == OCEAN_FILTER_N_MIN && p.n_max == OCEAN_FILTER_N_MAX, "filter %g %g",
          p.n_min, p.n_max);
    CHECK(p.sky_map_size == 512 && p.srgb_encode == 1, "sky map %u, srgb %u", p.sky_map_size,
          (unsigned)p.srgb_encode);
    CHECK(p.exposure == OCEAN_DEFAULT_EXPOSURE, "exposure %g", p.exposure);
    EXPECT(ocean_surface_draw_params_default(NULL), OCEAN_STATUS_NULL_POINTER);
}

static void test_uniforms(OceanSpectrum *spectrum, OceanLighting *lighting, size_t waves)
{
    OceanSurfaceDrawParams p;
    OceanCamera cam = camera_at(10.0, 4.0, -20.0);
    OceanWaterGridDesc mesh = mesh_desc();
    static uint8_t block[OCEAN_SURFACE_UNIFORMS_SIZE + 8], plain[OCEAN_SURFACE_UNIFORMS_SIZE],
        later[OCEAN_SURFACE_UNIFORMS_SIZE];

    OK(ocean_surface_draw_params_default(&p));
    memset(block, 0xA5, sizeof block);
    if (!OK(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 2.0, W, H, block,
                                 OCEAN_SURFACE_UNIFORMS_SIZE)))
        return;
    CHECK(all_bytes(block + OCEAN_SURFACE_UNIFORMS_SIZE, 8, 0xA5), "wrote past the block");
    /* mesh_grid: (0 - 10, -4, -100 - (-20)), spacing 0.5; mesh_counts 64 x 32. */
    CHECK(f32_at(block, 320) == -10.0f && f32_at(block, 324) == -4.0f &&
              f32_at(block, 328) == -80.0f && f32_at(block, 332) == 0.5f,
          "mesh_grid (%g, %g, %g, %g)", f32_at(block, 320), f32_at(block, 324),
          f32_at(block, 328), f32_at(block, 332));
    CHECK(u32_at(block, 336) == 64 && u32_at(block, 340) == 32, "mesh_counts %u x %u",
          u32_at(block, 336), u32_at(block, 340));
    CHECK(f32_at(block, 128) == 4.0f, "eye height %g", f32_at(block, 128));
    CHECK(f32_at(block, 144) == 96.0f && f32_at(block, 148) == 64.0f &&
              fabsf(f32_at(block, 152) + 9.6f) < 1e-5f && fabsf(f32_at(block, 156) + 6.4f) < 1e-5f,
          "viewport (%g, %g, %g, %g)", f32_at(block, 144), f32_at(block, 148),
          f32_at(block, 152), f32_at(block, 156));
    CHECK(u32_at(block, 176) == 16 && u32_at(block, 180) == 11, "grid %u x %u",
          u32_at(block, 176), u32_at(block, 180));
    CHECK(u32_at(block, 184) == waves && u32_at(block, 188) == 1, "waves %u, flags %u",
          u32_at(block, 184), u32_at(block, 188));
    CHECK(f32_at(block, 192) == 1.0f && f32_at(block, 196) == 0.0f, "wind (%g, %g)",
          f32_at(block, 192), f32_at(block, 196));
    CHECK(f32_at(block, 224) > 0.0f && f32_at(block, 228) > 0.0f && f32_at(block, 232) > 0.0f,
          "no Sun");
    CHECK(f32_at(block, 256) == 512.0f && f32_at(block, 260) == (float)OCEAN_SKY_MAP_EXTENT,
          "sky (%g, %g)", f32_at(block, 256), f32_at(block, 260));

    /* Without a mesh: the mesh fields are zero, nothing else differs. */
    OK(ocean_surface_uniforms(&cam, spectrum, lighting, &p, NULL, 2.0, W, H, plain, sizeof plain));
    CHECK(memcmp(plain, block, 320) == 0, "the block depends on the mesh beyond its fields");
    CHECK(all_bytes(plain + 320, 32, 0), "mesh fields not zero without a mesh");
    /* Another time: the same block. */
    OK(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 1.0e6, W, H, later,
                            sizeof later));
    CHECK(memcmp(later, block, OCEAN_SURFACE_UNIFORMS_SIZE) == 0, "the block depends on time");
}

static void test_wave_texels(OceanSpectrum *spectrum, size_t n)
{
    OceanCamera cam = camera_at(10.0, 4.0, -20.0);
    OceanSlopeVariance total;
    float *t0 = calloc(12 * n, sizeof(float));
    float *t1 = calloc(12 * n, sizeof(float));
    size_t i;
    int phases_differ = 0;

    if (t0 == NULL || t1 == NULL) {
        CHECK(0, "out of memory");
        free(t0);
        free(t1);
        return;
    }
    OK(ocean_surface_wave_texels(&cam, spectrum, 0.0, t0, 12 * n));
    OK(ocean_surface_wave_texels(&cam, spectrum, 1.0e6, t1, 12 * n));
    OK(ocean_spectrum_total_slope_variance(spectrum, &total));
    for (i = 0; i < n; i++) {
        const float *r0 = t0 + 4 * i, *r1 = t0 + 4 * (n + i), *r2 = t0 + 4 * (2 * n + i);
        double k = 2.0 * PI / r0[0];
        CHECK(i == 0 || r0[0] < t0[4 * (i - 1)], "wave %zu not shorter than the one before", i);
        CHECK(fabs(sqrt((double)r0[1] * r0[1] + (double)r0[2] * r0[2]) - k) < 1e-5 * k,
              "wave %zu: |k| %g, 2 pi / lambda %g", i, hypot(r0[1], r0[2]), k);
        CHECK(fabsf(r0[3]) <= (float)PI + 1e-6f && fabsf(t1[4 * i + 3]) <= (float)PI + 1e-6f,
              "wave %zu: phase %g / %g outside [-pi, pi]", i, r0[3], t1[4 * i + 3]);
        phases_differ |= r0[3] != t1[4 * i + 3];
        CHECK(fabs(r2[0] - k * r1[0]) < 1e-5 * (k * r1[0]) + 1e-7, "wave %zu: kA %g vs %g", i,
              r2[0], k * r1[0]);
        CHECK(i == 0 || (r2[2] <= t0[4 * (2 * n + i - 1) + 2] &&
                         r2[3] <= t0[4 * (2 * n + i - 1) + 3]),
              "wave %zu: suffix variance grew", i);
    }
    CHECK(phases_differ, "row 0's phases do not follow time");
    CHECK(memcmp(t0 + 4 * n, t1 + 4 * n, 8 * n * sizeof(float)) == 0,
          "rows 1 and 2 depend on time");
    CHECK(fabs(t0[4 * 2 * n + 2] - total.sigma_x2) <= 1e-6 * total.sigma_x2 &&
              fabs(t0[4 * 2 * n + 3] - total.sigma_y2) <= 1e-6 * total.sigma_y2,
          "total variance (%g, %g) vs the spectrum's (%g, %g)", t0[4 * 2 * n + 2],
          t0[4 * 2 * n + 3], total.sigma_x2, total.sigma_y2);
    free(t0);
    free(t1);
}

static void test_fresnel_texels(void)
{
    static float table[OCEAN_FRESNEL_TABLE_SIZE * OCEAN_FRESNEL_TABLE_SIZE];
    int i, j, bad = 0;
    if (!OK(ocean_surface_fresnel_texels(table, sizeof table / sizeof table[0])))
        return;
    for (i = 0; i < OCEAN_FRESNEL_TABLE_SIZE; i++) {
        for (j = 0; j < OCEAN_FRESNEL_TABLE_SIZE; j++) {
            double c = (i / 32.0) * (i / 32.0), s = (j / 32.0) * (j / 32.0), f = 0.0;
            double schlick = pow(1.0 - c, 5.0);
            OK(ocean_effective_fresnel_table(c, s, 0.0, &f));
            if (fabs(table[33 * i + j] - (f - schlick)) > 1e-6)
                bad++;
        }
    }
    CHECK(bad == 0, "%d Fresnel texels differ from ocean_effective_fresnel_table", bad);
}

static void test_errors(OceanSpectrum *spectrum, OceanLighting *lighting, size_t n)
{
    OceanSurfaceDrawParams p, q;
    OceanCamera cam = camera_at(10.0, 4.0, -20.0), below = camera_at(0.0, -1.0, 0.0);
    OceanWaterGridDesc mesh = mesh_desc(), bad_mesh = mesh_desc();
    static uint8_t block[OCEAN_SURFACE_UNIFORMS_SIZE];
    static float texels[4096];
    const size_t len = sizeof block;
    size_t i, written = 0;

    OK(ocean_surface_draw_params_default(&p));
    memset(block, 0x5A, sizeof block);
    /* The block's exact size, neither less nor more (a buffer for another version of it). */
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 0.0, W, H, block,
                                    len - 1),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 352");
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 0.0, W, H, block,
                                    len + 1),
               OCEAN_STATUS_LENGTH_MISMATCH, "holds exactly 352");
    EXPECT(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 0.0, 0, H, block, len),
           OCEAN_STATUS_EMPTY);
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, NAN, W, H, block, len),
               OCEAN_STATUS_NON_FINITE, "time");
    EXPECT_MSG(ocean_surface_uniforms(&below, spectrum, lighting, &p, &mesh, 0.0, W, H, block,
                                    len),
               OCEAN_STATUS_INVALID_ARGUMENT, "above the sea");
    q = p;
    q.srgb_encode = 2;
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &q, &mesh, 0.0, W, H, block, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "srgb_encode");
    q = p;
    q.n_max = 0.5;
    EXPECT(ocean_surface_uniforms(&cam, spectrum, lighting, &q, &mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_INVALID_ARGUMENT);
    q = p;
    q.sky_map_size = 100;
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &q, &mesh, 0.0, W, H, block, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "sky_map_size");
    bad_mesh.spacing = 0.0;
    EXPECT_MSG(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &bad_mesh, 0.0, W, H, block,
                                    len),
               OCEAN_STATUS_INVALID_ARGUMENT, "mesh");
    bad_mesh = mesh;
    bad_mesh.nz = 0;
    EXPECT(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &bad_mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_EMPTY);
    EXPECT(ocean_surface_uniforms(NULL, spectrum, lighting, &p, &mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_surface_uniforms(&cam, NULL, lighting, &p, &mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_surface_uniforms(&cam, spectrum, NULL, &p, &mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_surface_uniforms(&cam, spectrum, lighting, NULL, &mesh, 0.0, W, H, block, len),
           OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_surface_uniforms(&cam, spectrum, lighting, &p, &mesh, 0.0, W, H, NULL, len),
           OCEAN_STATUS_NULL_POINTER);
    CHECK(all_bytes(block, sizeof block, 0x5A), "the block was written on failure");

    for (i = 0; i < sizeof texels / sizeof texels[0]; i++)
        texels[i] = 7.0f;
    if (12 * n + 1 <= sizeof texels / sizeof texels[0]) {
        EXPECT_MSG(ocean_surface_wave_texels(&cam, spectrum, 0.0, texels, 12 * n + 1),
                   OCEAN_STATUS_LENGTH_MISMATCH, "exactly");
    }
    EXPECT(ocean_surface_wave_texels(&cam, spectrum, INFINITY, texels, 12 * n),
           OCEAN_STATUS_NON_FINITE);
    EXPECT(ocean_surface_wave_texels(&cam, NULL, 0.0, texels, 12 * n), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_surface_wave_texels(&cam, spectrum, 0.0, NULL, 12 * n), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_surface_fresnel_texels(texels, 33 * 32), OCEAN_STATUS_LENGTH_MISMATCH,
               "1089");
    EXPECT(ocean_surface_fresnel_texels(NULL, 33 * 33), OCEAN_STATUS_NULL_POINTER);
    for (i = 0; i < sizeof texels / sizeof texels[0]; i++)
        written += texels[i] != 7.0f;
    CHECK(written == 0, "%zu texels written on failure", written);
}

int main(void)
{
    OceanSpectrumParams sp;
    OceanSkyParams sky;
    OceanSeaParams sea;
    OceanSpectrum *spectrum = NULL;
    OceanLighting *lighting = NULL;
    size_t n = 0;

    test_defaults();
    OK(ocean_spectrum_params_default(&sp));
    OK(ocean_spectrum_create(&sp, &spectrum));
    OK(ocean_sky_params_default(&sky));
    OK(ocean_sea_params_default(&sea));
    OK(ocean_lighting_create(&sky, &sea, &lighting));
    OK(ocean_spectrum_wave_count(spectrum, &n));
    CHECK(n == 60, "the default spectrum has %zu waves", n);
    if (spectrum != NULL && lighting != NULL && n > 0) {
        test_uniforms(spectrum, lighting, n);
        test_wave_texels(spectrum, n);
        test_fresnel_texels();
        test_errors(spectrum, lighting, n);
    }
    ocean_lighting_destroy(lighting);
    ocean_spectrum_destroy(spectrum);
    printf("test_draw.c: library %s, %d checks, %d failures\n", ocean_version(), checks,
           failures);
    return failures == 0 ? 0 : 1;
}
