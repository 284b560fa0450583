/*
 * C11 test of the GPU part of the ocean C ABI (crate ocean-gpu): the shader export
 * (ocean_shader_*) and the ocean renderer on the library's own headless device
 * (ocean_gpu_context_*, ocean_renderer_*), linked against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_gpu.c libocean.a ...
 *
 * 1. Shader export (no GPU needed, always runs): every registered pass exports to every language
 *    with at least one file; GLSL files are NUL-terminated text with a #version line and a
 *    stage; the draw pass "ocean" has vertex and fragment stages (ocean_vs, ocean_fs); SPIR-V
 *    starts with its magic number and is 4-byte aligned; the bindings table lists every binding;
 *    GLSL 3.30 leaves binding numbers to the engine, GLSL ES numbers every non-sampler; unknown
 *    names, bad language values, bad indices and NULL pointers are refused with the outputs
 *    untouched.
 * 2. Renderer: if no adapter exists (OCEAN_STATUS_NO_ADAPTER) it prints SKIPPED and stops there,
 *    unless OCEAN_REQUIRE_GPU=1, which makes that a failure. Otherwise it renders 64 x 48 pixels
 *    from 4 m above the sea looking at the horizon with the default spectrum and lighting and
 *    checks the image (not uniform, sky brighter than sea, sea blue, alpha 255, the same bytes
 *    twice); with OCEAN_GPU_IMAGE=<path> set it writes the bytes there, for c_abi.rs to compare
 *    with the same frame rendered through ocean_gpu in Rust. Then every error path, with the
 *    output untouched.
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

static int env_is_1(const char *name)
{
    const char *v = getenv(name);
    return v != NULL && strcmp(v, "1") == 0;
}

/* ------------------------------------------------------------------------------------------ */
/* Shader export.                                                                             */

static const OceanShaderLanguage LANGUAGES[] = {
    OCEAN_SHADER_LANGUAGE_GLSL, OCEAN_SHADER_LANGUAGE_GLSL_ES, OCEAN_SHADER_LANGUAGE_HLSL,
    OCEAN_SHADER_LANGUAGE_MSL, OCEAN_SHADER_LANGUAGE_SPIRV,
};

/* Checks one export's files and bindings; returns the number of vertex and fragment files
 * whose entry points are ocean_vs and ocean_fs (for the draw pass). */
static void check_export(const char *name, OceanShaderLanguage lang, int *ocean_vs,
                         int *ocean_fs)
{
    OceanShaderExport *e = NULL;
    size_t files = 0, nb = 0, i, k;
    const char *table = NULL;
    int glsl = lang == OCEAN_SHADER_LANGUAGE_GLSL || lang == OCEAN_SHADER_LANGUAGE_GLSL_ES;

    if (!OK(ocean_shader_export(name, lang, &e)))
        return;
    CHECK(e != NULL, "%s/%u: NULL export", name, (unsigned)lang);
    OK(ocean_shader_export_file_count(e, &files));
    CHECK(files >= 1, "%s/%u: %zu files", name, (unsigned)lang, files);
    if (!glsl)
        CHECK(files == 1, "%s/%u: %zu files, expected one module", name, (unsigned)lang, files);

    for (i = 0; i < files; i++) {
        const char *file_name = NULL, *entry = NULL;
        const uint8_t *data = NULL;
        size_t len = 0;
        uint32_t stage = 99;
        if (!OK(ocean_shader_export_file(e, i, &file_name, &data, &len)) ||
            !OK(ocean_shader_export_file_stage(e, i, &stage, &entry)))
            continue;
        CHECK(file_name != NULL && strncmp(file_name, name, strlen(name)) == 0,
              "%s/%u: file name %s", name, (unsigned)lang, file_name ? file_name : "(NULL)");
        CHECK(data != NULL && len > 0, "%s/%u: empty file %zu", name, (unsigned)lang, i);
        CHECK(((uintptr_t)data & 3u) == 0, "%s/%u: data not 4-byte aligned", name,
              (unsigned)lang);
        CHECK(data[len] == 0, "%s/%u: data not followed by a NUL", name, (unsigned)lang);
        if (lang == OCEAN_SHADER_LANGUAGE_SPIRV) {
            uint32_t magic = 0;
            memcpy(&magic, data, sizeof magic);
            CHECK(magic == 0x07230203u && len % 4 == 0, "%s: SPIR-V magic 0x%08x, %zu bytes",
                  name, (unsigned)magic, len);
        } else {
            CHECK(strlen((const char *)data) == len, "%s/%u: text with a NUL inside", name,
                  (unsigned)lang);
        }
        if (glsl) {
            const char *text = (const char *)data;
            CHECK(strncmp(text, "#version ", 9) == 0, "%s: GLSL starts with %.20s", file_name,
                  text);
            CHECK(strstr(text, "void main(") != NULL, "%s: no main()", file_name);
            CHECK(stage == OCEAN_SHADER_STAGE_VERTEX || stage == OCEAN_SHADER_STAGE_FRAGMENT ||
                      stage == OCEAN_SHADER_STAGE_COMPUTE,
                  "%s: stage %u", file_name, (unsigned)stage);
            CHECK(entry[0] != '\0' && strstr(file_name, entry) != NULL,
                  "%s: entry point \"%s\"", file_name, entry);
            if (stage == OCEAN_SHADER_STAGE_VERTEX) {
                CHECK(strstr(text, "gl_Position") != NULL, "%s: vertex stage without gl_Position",
                      file_name);
                if (strcmp(entry, "ocean_vs") == 0)
                    (*ocean_vs)++;
            }
            if (stage == OCEAN_SHADER_STAGE_FRAGMENT && strcmp(entry, "ocean_fs") == 0)
                (*ocean_fs)++;
            if (lang == OCEAN_SHADER_LANGUAGE_GLSL && stage != OCEAN_SHADER_STAGE_COMPUTE)
                CHECK(strncmp(text, "#version 330 core", 17) == 0, "%s: %.20s", file_name, text);
            if (lang == OCEAN_SHADER_LANGUAGE_GLSL && stage == OCEAN_SHADER_STAGE_COMPUTE)
                CHECK(strncmp(text, "#version 430 core", 17) == 0, "%s: %.20s", file_name, text);
            if (lang == OCEAN_SHADER_LANGUAGE_GLSL_ES)
                CHECK(strncmp(text, "#version 310 es", 15) == 0, "%s: %.20s", file_name, text);
        } else {
            CHECK(stage == OCEAN_SHADER_STAGE_MODULE && entry[0] == '\0',
                  "%s/%u: stage %u, entry \"%s\"", name, (unsigned)lang, (unsigned)stage, entry);
        }
    }

    OK(ocean_shader_export_bindings(e, &table));
    OK(ocean_shader_export_binding_count(e, &nb));
    CHECK(table != NULL && table[0] == '#', "%s/%u: table starts with %.10s", name,
          (unsigned)lang, table ? table : "(NULL)");
    CHECK(nb >= 1, "%s: no bindings", name);
    for (k = 0; k < nb && table != NULL; k++) {
        OceanShaderBinding b;
        char line[256];
        memset(&b, 0, sizeof b);
        if (!OK(ocean_shader_export_binding(e, k, &b)))
            continue;
        CHECK(b.name != NULL && b.name[0] != '\0' && b.wgsl_type != NULL && b.glsl_name != NULL,
              "%s: binding %zu strings", name, k);
        if (b.name == NULL || b.wgsl_type == NULL || b.glsl_name == NULL)
            continue;
        /* "group binding name kind type": the table's line for this binding. */
        snprintf(line, sizeof line, "\n%u %u %s ", (unsigned)b.group, (unsigned)b.binding,
                 b.name);
        CHECK(strstr(table, line) != NULL, "%s/%u: the table lacks \"%s\":\n%s", name,
              (unsigned)lang, line + 1, table);
        CHECK(strstr(table, b.wgsl_type) != NULL, "%s: the table lacks type %s", name,
              b.wgsl_type);
        CHECK(b.kind <= OCEAN_BINDING_KIND_SAMPLER_COMPARISON, "%s: kind %u", name,
              (unsigned)b.kind);
        if (b.kind == OCEAN_BINDING_KIND_UNIFORM || b.kind == OCEAN_BINDING_KIND_STORAGE_READ ||
            b.kind == OCEAN_BINDING_KIND_STORAGE_READ_WRITE)
            CHECK(b.size > 0, "%s: buffer %s of size 0", name, b.name);
        if (k > 0) {
            OceanShaderBinding prev;
            OK(ocean_shader_export_binding(e, k - 1, &prev));
            CHECK(prev.group < b.group || (prev.group == b.group && prev.binding < b.binding),
                  "%s: bindings out of (group, binding) order", name);
        }
        if (glsl && b.glsl_name[0] != '\0') {
            char needle[128];
            snprintf(needle, sizeof needle, "glsl_name=%s", b.glsl_name);
            CHECK(strstr(table, needle) != NULL, "%s: the table lacks %s", name, needle);
        }
        if (!glsl)
            CHECK(b.glsl_binding == OCEAN_NO_GLSL_BINDING && b.glsl_name[0] == '\0',
                  "%s/%u: GLSL fields set in a non-GLSL export", name, (unsigned)lang);
        if (b.kind == OCEAN_BINDING_KIND_SAMPLER || b.kind == OCEAN_BINDING_KIND_SAMPLER_COMPARISON)
            CHECK(b.glsl_binding == OCEAN_NO_GLSL_BINDING, "%s: sampler with a GL binding", name);
        /* The draw pass under GLSL 3.30: numbers are the engine's, by name. */
        if (lang == OCEAN_SHADER_LANGUAGE_GLSL && strcmp(name, "ocean") == 0)
            CHECK(b.glsl_binding == OCEAN_NO_GLSL_BINDING, "ocean/glsl: binding %s has %u",
                  b.name, (unsigned)b.glsl_binding);
        if (lang == OCEAN_SHADER_LANGUAGE_GLSL_ES && b.kind != OCEAN_BINDING_KIND_SAMPLER &&
            b.kind != OCEAN_BINDING_KIND_SAMPLER_COMPARISON)
            CHECK(b.glsl_binding != OCEAN_NO_GLSL_BINDING, "%s/es: binding %s unnumbered", name,
                  b.name);
    }
    ocean_shader_export_destroy(e);
}

static void test_shader_export(void)
{
    size_t n = ocean_shader_count(), i, l;
    int found_ocean = 0;
    CHECK(n >= 4, "%zu shaders registered", n);

    for (i = 0; i < n; i++) {
        const char *name = NULL;
        if (!OK(ocean_shader_name(i, &name)))
            continue;
        CHECK(name != NULL && name[0] != '\0', "shader %zu has no name", i);
        if (name == NULL)
            continue;
        if (strcmp(name, "ocean") == 0)
            found_ocean = 1;
        for (l = 0; l < sizeof LANGUAGES / sizeof LANGUAGES[0]; l++) {
            int vs = 0, fs = 0;
            check_export(name, LANGUAGES[l], &vs, &fs);
            if (strcmp(name, "ocean") == 0 && (LANGUAGES[l] == OCEAN_SHADER_LANGUAGE_GLSL ||
                                               LANGUAGES[l] == OCEAN_SHADER_LANGUAGE_GLSL_ES))
                CHECK(vs == 1 && fs == 1, "ocean/%u: %d ocean_vs and %d ocean_fs files",
                      (unsigned)LANGUAGES[l], vs, fs);
        }
    }
    CHECK(found_ocean, "the draw pass \"ocean\" is not registered");

    /* The same name twice gives the same bytes. */
    {
        OceanShaderExport *a = NULL, *b = NULL;
        const char *fa, *fb;
        const uint8_t *da, *db;
        size_t la = 0, lb = 0;
        if (OK(ocean_shader_export("ocean", OCEAN_SHADER_LANGUAGE_GLSL, &a)) &&
            OK(ocean_shader_export("ocean", OCEAN_SHADER_LANGUAGE_GLSL, &b)) &&
            OK(ocean_shader_export_file(a, 1, &fa, &da, &la)) &&
            OK(ocean_shader_export_file(b, 1, &fb, &db, &lb))) {
            CHECK(la == lb && memcmp(da, db, la) == 0 && strcmp(fa, fb) == 0,
                  "two exports of ocean differ");
            CHECK(da != db, "two exports share their storage");
        }
        ocean_shader_export_destroy(a);
        ocean_shader_export_destroy(b);
    }

    /* Error paths: outputs untouched. */
    {
        OceanShaderExport *sentinel = (OceanShaderExport *)(uintptr_t)0x1000;
        OceanShaderExport *e = sentinel;
        const char *name = "untouched";
        const char *fname = "untouched";
        const uint8_t *data = (const uint8_t *)"x";
        size_t len = 12345, count = 12345;
        uint32_t stage = 77;
        OceanShaderBinding b;
        uint64_t storage[8] = {0};
        /* Not a handle: an address into the caller's memory (handles are ids). */
        const OceanShaderExport *foreign =
            (const OceanShaderExport *)((const char *)storage + 1);

        EXPECT_MSG(ocean_shader_export("no_such_pass", OCEAN_SHADER_LANGUAGE_GLSL, &e),
                   OCEAN_STATUS_NOT_FOUND, "ocean");
        CHECK(e == sentinel, "export written on failure");
        EXPECT_MSG(ocean_shader_export("", OCEAN_SHADER_LANGUAGE_GLSL, &e),
                   OCEAN_STATUS_NOT_FOUND, "trochoid");
        EXPECT_MSG(ocean_shader_export("ocean", 5, &e), OCEAN_STATUS_INVALID_ARGUMENT,
                   "OceanShaderLanguage");
        EXPECT(ocean_shader_export("ocean", 0xFFFFFFFFu, &e), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT_MSG(ocean_shader_export("\xff\xfe", OCEAN_SHADER_LANGUAGE_GLSL, &e),
                   OCEAN_STATUS_INVALID_ARGUMENT, "UTF-8");
        EXPECT_MSG(ocean_shader_export(NULL, OCEAN_SHADER_LANGUAGE_GLSL, &e),
                   OCEAN_STATUS_NULL_POINTER, "name");
        CHECK(e == sentinel, "export written on failure");
        EXPECT_MSG(ocean_shader_export("ocean", OCEAN_SHADER_LANGUAGE_GLSL, NULL),
                   OCEAN_STATUS_NULL_POINTER, "out");

        EXPECT(ocean_shader_name(n, &name), OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_shader_name((size_t)-1, &name), OCEAN_STATUS_INVALID_ARGUMENT);
        CHECK(strcmp(name, "untouched") == 0, "name written on failure");
        EXPECT(ocean_shader_name(0, NULL), OCEAN_STATUS_NULL_POINTER);

        EXPECT_MSG(ocean_shader_export_file_count(NULL, &count), OCEAN_STATUS_NULL_POINTER,
                   "shader_export");
        EXPECT_MSG(ocean_shader_export_file_count(foreign, &count), OCEAN_STATUS_INVALID_HANDLE,
                   "not an OceanShaderExport handle");
        CHECK(count == 12345, "count written on failure");

        if (OK(ocean_shader_export("trochoid", OCEAN_SHADER_LANGUAGE_HLSL, &e))) {
            EXPECT_MSG(ocean_shader_export_file(e, 1, &fname, &data, &len),
                       OCEAN_STATUS_INVALID_ARGUMENT, "file 1");
            EXPECT_MSG(ocean_shader_export_file(e, 0, NULL, &data, &len),
                       OCEAN_STATUS_NULL_POINTER, "file_name");
            EXPECT_MSG(ocean_shader_export_file(e, 0, &fname, NULL, &len),
                       OCEAN_STATUS_NULL_POINTER, "data");
            EXPECT_MSG(ocean_shader_export_file(e, 0, &fname, &data, NULL),
                       OCEAN_STATUS_NULL_POINTER, "len");
            CHECK(strcmp(fname, "untouched") == 0 && data[0] == 'x' && len == 12345,
                  "file outputs written on failure");
            EXPECT(ocean_shader_export_file_stage(e, 1, &stage, &fname),
                   OCEAN_STATUS_INVALID_ARGUMENT);
            EXPECT(ocean_shader_export_file_stage(e, 0, NULL, &fname), OCEAN_STATUS_NULL_POINTER);
            EXPECT(ocean_shader_export_file_stage(e, 0, &stage, NULL), OCEAN_STATUS_NULL_POINTER);
            CHECK(stage == 77 && strcmp(fname, "untouched") == 0,
                  "stage outputs written on failure");
            memset(&b, 0x5a, sizeof b);
            EXPECT_MSG(ocean_shader_export_binding(e, 1000, &b), OCEAN_STATUS_INVALID_ARGUMENT,
                       "binding 1000");
            CHECK(b.group == 0x5a5a5a5au, "binding written on failure");
            EXPECT(ocean_shader_export_binding(e, 0, NULL), OCEAN_STATUS_NULL_POINTER);
            EXPECT(ocean_shader_export_bindings(e, NULL), OCEAN_STATUS_NULL_POINTER);
            EXPECT(ocean_shader_export_binding_count(e, NULL), OCEAN_STATUS_NULL_POINTER);
            ocean_shader_export_destroy(e);
        }
        ocean_shader_export_destroy(NULL);
    }
}

/* ------------------------------------------------------------------------------------------ */
/* Renderer.                                                                                  */

enum { W = 64, H = 48 };
static const double TIME = 2.5;
static const double PI = 3.14159265358979323846;

/* 4 m above the sea at the origin, looking at the horizon along -z (towards the default Sun),
 * 60 degrees vertical field of view: the camera c_abi.rs renders through ocean_gpu. The view
 * matrix of that eye is a translation by (0, -4, 0), column-major. */
static OceanCamera horizon_camera(double eye_y)
{
    return check_camera_at(0.0, eye_y, 0.0, 60.0 * PI / 180.0, (double)W / (double)H, 0.1,
                           100000.0, OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE);
}

/* The mean of channel `ch` over rows [r0, r1). */
static double mean_channel(const uint8_t *img, int r0, int r1, int ch)
{
    double sum = 0.0;
    int x, y;
    for (y = r0; y < r1; y++)
        for (x = 0; x < W; x++)
            sum += img[(y * W + x) * 4 + ch];
    return sum / ((double)(r1 - r0) * W);
}

static int untouched(const uint8_t *buf, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++)
        if (buf[i] != 0xAB)
            return 0;
    return 1;
}

static void check_image(const uint8_t *img)
{
    size_t i, distinct = 0;
    int alpha_ok = 1;
    double sky, sea, sea_r, sea_g, sea_b;
    for (i = 0; i < (size_t)W * H; i++) {
        if (img[i * 4 + 3] != 255)
            alpha_ok = 0;
        if (memcmp(img + i * 4, img, 3) != 0)
            distinct++;
    }
    CHECK(alpha_ok, "alpha is not 255 everywhere");
    CHECK(distinct > (size_t)W * H / 4, "the image is (nearly) uniform: %zu pixels differ from "
                                        "the first",
          distinct);
    /* Top quarter: sky; bottom quarter: sea. */
    sky = (mean_channel(img, 0, H / 4, 0) + mean_channel(img, 0, H / 4, 1) +
           mean_channel(img, 0, H / 4, 2)) /
          3.0;
    sea_r = mean_channel(img, H - H / 4, H, 0);
    sea_g = mean_channel(img, H - H / 4, H, 1);
    sea_b = mean_channel(img, H - H / 4, H, 2);
    sea = (sea_r + sea_g + sea_b) / 3.0;
    printf("image: sky mean %.1f, sea mean %.1f (r %.1f, g %.1f, b %.1f)\n", sky, sea, sea_r,
           sea_g, sea_b);
    CHECK(sky > sea, "the sky (%.1f) is not brighter than the sea (%.1f)", sky, sea);
    CHECK(sea_b > sea_r && sea_b > sea_g, "the sea is not blue: r %.1f g %.1f b %.1f", sea_r,
          sea_g, sea_b);
    CHECK(sea > 1.0, "the sea is black");
}

/* Returns 0 when skipped (no adapter, not required). */
static int test_renderer(void)
{
    OceanGpuContext *ctx = NULL, *other = NULL;
    OceanRenderer *r = NULL;
    OceanSpectrum *spectrum = NULL;
    OceanLighting *lighting = NULL;
    OceanRendererOptions opts;
    OceanSpectrumParams sp;
    OceanSkyParams sky;
    OceanSeaParams sea;
    OceanCamera cam = horizon_camera(4.0);
    static uint8_t img[W * H * 4], img2[W * H * 4], buf[W * H * 4 + 8];
    const size_t len = sizeof img;
    OceanStatus s = ocean_gpu_context_create(&ctx);

    if (s == OCEAN_STATUS_NO_ADAPTER) {
        const char *m = last_error();
        CHECK(strstr(m, "mesa-vulkan-drivers") != NULL, "no-adapter message: %s", m);
        CHECK(ctx == NULL, "context written on failure");
        if (env_is_1("OCEAN_REQUIRE_GPU")) {
            CHECK(0, "OCEAN_REQUIRE_GPU=1 is set but no GPU context could be created: %s", m);
        } else {
            printf("SKIPPED: the renderer part (no usable GPU adapter: %s). Set "
                   "OCEAN_REQUIRE_GPU=1 to make this a failure.\n",
                   m);
        }
        return 0;
    }
    if (!OK(s))
        return 0;

    /* The description: owned by the context, the same pointer and text on every call. */
    {
        const char *text = NULL, *again = NULL, *kept = "kept";
        if (OK(ocean_gpu_context_describe(ctx, &text)) && OK(ocean_gpu_context_describe(ctx, &again))) {
            CHECK(text != NULL && strlen(text) > 0 && strchr(text, '\n') == NULL,
                  "description \"%s\"", text ? text : "(null)");
            CHECK(again == text, "the description moved between calls");
            printf("GPU: %s\n", text);
        }
        EXPECT(ocean_gpu_context_describe(ctx, NULL), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_gpu_context_describe(NULL, &kept), OCEAN_STATUS_NULL_POINTER);
        CHECK(strcmp(kept, "kept") == 0, "written on a NULL-handle failure");
    }

    /* Options. */
    OK(ocean_renderer_options_default(&opts));
    CHECK(opts.cell_px == 8.0 && opts.margin == 0.1 && opts.max_distance == 50000.0 &&
              opts.exposure == OCEAN_DEFAULT_EXPOSURE && opts.sky_map_size == 512 &&
              opts.draw_sky == 1,
          "default options %g %g %g %g %u %u", opts.cell_px, opts.margin, opts.max_distance,
          opts.exposure, (unsigned)opts.sky_map_size, (unsigned)opts.draw_sky);
    EXPECT(ocean_renderer_options_default(NULL), OCEAN_STATUS_NULL_POINTER);
    {
        OceanRenderer *sentinel = (OceanRenderer *)(uintptr_t)0x1000, *bad = sentinel;
        OceanRendererOptions o = opts;
        o.cell_px = 0.5;
        EXPECT_MSG(ocean_renderer_create(ctx, &o, &bad), OCEAN_STATUS_INVALID_ARGUMENT,
                   "cell_px");
        o = opts;
        o.exposure = NAN;
        EXPECT_MSG(ocean_renderer_create(ctx, &o, &bad), OCEAN_STATUS_NON_FINITE, "exposure");
        o = opts;
        o.sky_map_size = 100;
        EXPECT_MSG(ocean_renderer_create(ctx, &o, &bad), OCEAN_STATUS_INVALID_ARGUMENT,
                   "sky_map_size");
        o = opts;
        o.draw_sky = 2;
        EXPECT_MSG(ocean_renderer_create(ctx, &o, &bad), OCEAN_STATUS_INVALID_ARGUMENT,
                   "draw_sky");
        o = opts;
        o.margin = -1.0;
        EXPECT_MSG(ocean_renderer_create(ctx, &o, &bad), OCEAN_STATUS_INVALID_ARGUMENT,
                   "margin");
        EXPECT(ocean_renderer_create(NULL, &opts, &bad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_renderer_create(ctx, NULL, &bad), OCEAN_STATUS_NULL_POINTER);
        EXPECT(ocean_renderer_create(ctx, &opts, NULL), OCEAN_STATUS_NULL_POINTER);
        CHECK(bad == sentinel, "renderer written on failure");
    }
    if (!OK(ocean_renderer_create(ctx, &opts, &r)))
        goto done;

    /* Before a spectrum and a lighting: refused, nothing written. */
    memset(buf, 0xAB, sizeof buf);
    EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "ocean_renderer_set_spectrum");
    OK(ocean_spectrum_params_default(&sp));
    OK(ocean_spectrum_create(&sp, &spectrum));
    EXPECT_MSG(ocean_renderer_set_spectrum(r, ctx, spectrum, 2.5, 1.0),
               OCEAN_STATUS_INVALID_ARGUMENT, "N_");
    EXPECT_MSG(ocean_renderer_set_spectrum(r, ctx, spectrum, NAN, 2.5), OCEAN_STATUS_NON_FINITE,
               "n_min");
    EXPECT_MSG(ocean_renderer_set_spectrum(r, ctx, NULL, 1.0, 2.5), OCEAN_STATUS_NULL_POINTER,
               "spectrum");
    EXPECT(ocean_renderer_set_spectrum(NULL, ctx, spectrum, 1.0, 2.5), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "ocean_renderer_set_spectrum");
    OK(ocean_renderer_set_spectrum(r, ctx, spectrum, OCEAN_FILTER_N_MIN, OCEAN_FILTER_N_MAX));
    /* The renderer copied the waves. */
    ocean_spectrum_destroy(spectrum);
    spectrum = NULL;
    EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "ocean_renderer_set_lighting");
    CHECK(untouched(buf, sizeof buf), "the image was written before the renderer was ready");
    OK(ocean_sky_params_default(&sky));
    OK(ocean_sea_params_default(&sea));
    OK(ocean_lighting_create(&sky, &sea, &lighting));
    EXPECT(ocean_renderer_set_lighting(r, ctx, NULL), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_renderer_set_lighting(r, NULL, lighting), OCEAN_STATUS_NULL_POINTER);
    OK(ocean_renderer_set_lighting(r, ctx, lighting));
    ocean_lighting_destroy(lighting);
    lighting = NULL;

    /* The frame. */
    if (OK(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, img, len))) {
        const char *path = getenv("OCEAN_GPU_IMAGE");
        check_image(img);
        OK(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, img2, len));
        CHECK(memcmp(img, img2, len) == 0, "two renders of the same frame differ");
        OK(ocean_renderer_render_rgba8(r, ctx, &cam, TIME + 1.0, W, H, img2, len));
        CHECK(memcmp(img, img2, len) != 0, "the sea does not move in 1 s");
        if (path != NULL && path[0] != '\0') {
            FILE *f = fopen(path, "wb");
            CHECK(f != NULL, "cannot open %s", path);
            if (f != NULL) {
                CHECK(fwrite(img, 1, len, f) == len, "cannot write %s", path);
                CHECK(fclose(f) == 0, "cannot close %s", path);
            }
        }
    }

    /* Every error path: the output stays untouched. */
    memset(buf, 0xAB, sizeof buf);
    {
        OceanCamera c;
        EXPECT_MSG(ocean_renderer_render_rgba8(NULL, ctx, &cam, TIME, W, H, buf, len),
                   OCEAN_STATUS_NULL_POINTER, "renderer");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, NULL, &cam, TIME, W, H, buf, len),
                   OCEAN_STATUS_NULL_POINTER, "ctx");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, NULL, TIME, W, H, buf, len),
                   OCEAN_STATUS_NULL_POINTER, "camera");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, NULL, len),
                   OCEAN_STATUS_NULL_POINTER, "out");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, len - 1),
                   OCEAN_STATUS_LENGTH_MISMATCH, "len");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, len + 4),
                   OCEAN_STATUS_LENGTH_MISMATCH, "len");
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, H, buf, 0),
               OCEAN_STATUS_LENGTH_MISMATCH);
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, 0, H, buf, 0), OCEAN_STATUS_EMPTY);
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, W, 0, buf, 0), OCEAN_STATUS_EMPTY);
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, 0, 0, buf, len),
               OCEAN_STATUS_EMPTY);
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, 1000000, 1000000, buf,
                                           (size_t)4000000000000u),
               OCEAN_STATUS_INVALID_ARGUMENT);
        EXPECT(ocean_renderer_render_rgba8(r, ctx, &cam, TIME, 0xFFFFFFFFu, 0xFFFFFFFFu, buf,
                                           len),
               OCEAN_STATUS_LENGTH_OVERFLOW);
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, NAN, W, H, buf, len),
                   OCEAN_STATUS_NON_FINITE, "time");
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &cam, INFINITY, W, H, buf, len),
                   OCEAN_STATUS_NON_FINITE, "time");
        c = horizon_camera(-1.0);
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "above the sea");
        c = horizon_camera(0.0);
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "above the sea");
        c = cam;
        c.view[3] = NAN;
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_NON_FINITE, "view[3]");
        c = cam;
        c.projection[4] = 0.5; /* skewed */
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "projection[4]");
        c = cam;
        c.projection[8] = 0.01; /* jittered */
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "off-centre");
        c = cam; /* forward-Z declared reversed: the far plane comes before the near one */
        c.depth_convention = OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED;
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "far plane");
        c = cam;
        c.depth_convention = 7;
        EXPECT_MSG(ocean_renderer_render_rgba8(r, ctx, &c, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "depth_convention");
        CHECK(untouched(buf, sizeof buf), "the image was written on a failure");
    }

    /* Without the sky: the pixels above the horizon stay black (and opaque). */
    {
        OceanRenderer *bare = NULL;
        OceanRendererOptions o = opts;
        o.draw_sky = 0;
        o.sky_map_size = 16;
        if (OK(ocean_renderer_create(ctx, &o, &bare)) &&
            OK(ocean_spectrum_create(&sp, &spectrum)) &&
            OK(ocean_lighting_create(&sky, &sea, &lighting)) &&
            OK(ocean_renderer_set_spectrum(bare, ctx, spectrum, 1.0, 2.5)) &&
            OK(ocean_renderer_set_lighting(bare, ctx, lighting)) &&
            OK(ocean_renderer_render_rgba8(bare, ctx, &cam, TIME, W, H, img2, len))) {
            size_t i, black = 0;
            for (i = 0; i < (size_t)W * (H / 4); i++)
                black += img2[i * 4] == 0 && img2[i * 4 + 1] == 0 && img2[i * 4 + 2] == 0 &&
                         img2[i * 4 + 3] == 255;
            CHECK(black == (size_t)W * (H / 4), "%zu of the top rows' pixels are opaque black",
                  black);
            CHECK(mean_channel(img2, H - H / 4, H, 2) > 1.0, "no sea without the sky");
        }
        ocean_renderer_destroy(bare);
    }

    /* A renderer only works with its own context. */
    if (OK(ocean_gpu_context_create(&other))) {
        EXPECT_MSG(ocean_renderer_render_rgba8(r, other, &cam, TIME, W, H, buf, len),
                   OCEAN_STATUS_INVALID_ARGUMENT, "another context");
        CHECK(untouched(buf, sizeof buf), "the image was written on a failure");
        ocean_gpu_context_destroy(other);
    }

done:
    ocean_renderer_destroy(r);
    ocean_renderer_destroy(NULL);
    ocean_spectrum_destroy(spectrum);
    ocean_lighting_destroy(lighting);
    ocean_gpu_context_destroy(ctx);
    ocean_gpu_context_destroy(NULL);
    return 1;
}

int main(void)
{
    int rendered;
    test_shader_export();
    rendered = test_renderer();
    printf("test_gpu.c: library %s, %d checks, %d failures; shader export of every pass and "
           "language%s\n",
           ocean_version(), checks, failures,
           rendered ? ", the ocean renderer on the GPU" : " (renderer SKIPPED)");
    return failures == 0 ? 0 : 1;
}
