/*
 * C11 test of the scene renderer of the ocean C ABI (crate ocean-scene, ocean_scene_*): the
 * composed scene of `ocean render` built from its TOML description on the library's headless
 * device and rendered into the caller's buffer, linked against libocean.a.
 *
 * Built and run by tests/tests/c_abi.rs with
 *   cc -std=c11 -Wall -Wextra -Werror -pedantic -I include tests/c/test_scene.c libocean.a ...
 *
 * 1. Without a GPU: the built-in description (NUL-terminated TOML, the same pointer every call)
 *    and the default options (all 0, next NULL).
 * 2. If no adapter exists it prints SKIPPED and stops, unless OCEAN_REQUIRE_GPU=1, which makes
 *    that a failure. Otherwise it builds the built-in scene at 96 x 54 pixels, one sample per
 *    pixel, renders the frame at t = 1.5 s and checks it (not uniform, alpha 255, the same
 *    bytes twice, another frame at another time); with OCEAN_SCENE_IMAGE=<path> set it writes
 *    the bytes there, for c_abi.rs to compare with the same frame drawn by ocean_scene in Rust.
 * 3. Every error path: NULL and misaligned pointers, an empty text, text that is not UTF-8, a
 *    description with a syntax error and one out of range (the message names line and key),
 *    options out of range, an unknown extension, a wrong length, a NaN time, another context,
 *    a destroyed scene and a second destroy, with the outputs untouched.
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

#define W 96
#define H 54
#define TIME 1.5

static int env_is_1(const char *name)
{
    const char *v = getenv(name);
    return v != NULL && strcmp(v, "1") == 0;
}

static void test_description(void)
{
    const char *text = NULL, *again = NULL;
    OceanSceneOptions o;
    memset(&o, 0xAB, sizeof o);
    if (OK(ocean_scene_builtin_description(&text)) &&
        OK(ocean_scene_builtin_description(&again))) {
        CHECK(text != NULL && strstr(text, "[render]") != NULL && strstr(text, "[island]") != NULL,
              "the built-in description lacks its sections");
        CHECK(again == text, "the built-in description moved between calls");
    }
    EXPECT(ocean_scene_builtin_description(NULL), OCEAN_STATUS_NULL_POINTER);
    if (OK(ocean_scene_options_default(&o))) {
        CHECK(o.next == NULL && o.width == 0 && o.height == 0 && o.samples == 0 &&
                  o.camera == OCEAN_SCENE_CAMERA_DESCRIPTION,
              "default options: next %p, %u x %u, %u samples, camera %u", (const void *)o.next,
              o.width, o.height, o.samples, o.camera);
    }
    EXPECT(ocean_scene_options_default(NULL), OCEAN_STATUS_NULL_POINTER);
}

/* Not uniform, every alpha 255. */
static void check_image(const uint8_t *img)
{
    size_t i, differing = 0, opaque = 0;
    for (i = 0; i < (size_t)W * H; i++) {
        opaque += img[4 * i + 3] == 255;
        differing += memcmp(img + 4 * i, img, 3) != 0;
    }
    CHECK(opaque == (size_t)W * H, "%zu of %d pixels opaque", opaque, W * H);
    CHECK(differing > (size_t)W * H / 4, "only %zu pixels differ from the first", differing);
}

static void test_errors(OceanGpuContext *ctx, OceanGpuContext *other, const char *text,
                        OceanScene *scene)
{
    static uint8_t buf[W * H * 4 + 8];
    const size_t len = (size_t)W * H * 4;
    OceanScene *out = NULL;
    OceanSceneOptions o;
    OceanChain unknown = {NULL, 0x7fff, 0};
    uint32_t w = 7, h = 7;
    const char bad_utf8[] = "[render]\nwidth = 64 # \xff\n";
    const char bad_syntax[] = "[render]\nwidth = \n";
    const char out_of_range[] = "[render]\nwidth = 64\n\n[sun]\nelevation = 95\n";
    ocean_scene_options_default(&o);

    EXPECT(ocean_scene_create(NULL, text, strlen(text), &o, &out), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_create(ctx, NULL, strlen(text), &o, &out), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_create(ctx, text, 0, &o, &out), OCEAN_STATUS_EMPTY);
    EXPECT(ocean_scene_create(ctx, text, strlen(text), NULL, &out), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_create(ctx, text, strlen(text), &o, NULL), OCEAN_STATUS_NULL_POINTER);
    EXPECT_MSG(ocean_scene_create(ctx, bad_utf8, strlen(bad_utf8), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "UTF-8");
    EXPECT_MSG(ocean_scene_create(ctx, bad_syntax, strlen(bad_syntax), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "line 2");
    EXPECT_MSG(ocean_scene_create(ctx, out_of_range, strlen(out_of_range), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "sun.elevation");
    o.camera = 9;
    EXPECT_MSG(ocean_scene_create(ctx, text, strlen(text), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "options->camera = 9");
    ocean_scene_options_default(&o);
    o.width = 9000;
    EXPECT_MSG(ocean_scene_create(ctx, text, strlen(text), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "render.width");
    ocean_scene_options_default(&o);
    o.samples = 3;
    EXPECT_MSG(ocean_scene_create(ctx, text, strlen(text), &o, &out),
               OCEAN_STATUS_INVALID_ARGUMENT, "render.samples");
    ocean_scene_options_default(&o);
    o.next = &unknown;
    EXPECT(ocean_scene_create(ctx, text, strlen(text), &o, &out), OCEAN_STATUS_INVALID_ARGUMENT);
    CHECK(out == NULL, "a scene was written on failure");

    EXPECT(ocean_scene_size(NULL, &w, &h), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_size(scene, NULL, &h), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_size(scene, &w, NULL), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_size(scene, (uint32_t *)(void *)(buf + 1), &h),
           OCEAN_STATUS_MISALIGNED_POINTER);
    CHECK(w == 7 && h == 7, "size written on failure");

    memset(buf, 0x5A, sizeof buf);
    EXPECT(ocean_scene_render_rgba8(NULL, ctx, TIME, buf, len), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_render_rgba8(scene, NULL, TIME, buf, len), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, TIME, NULL, len), OCEAN_STATUS_NULL_POINTER);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, TIME, buf, len - 1),
           OCEAN_STATUS_LENGTH_MISMATCH);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, TIME, buf, len + 4),
           OCEAN_STATUS_LENGTH_MISMATCH);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, NAN, buf, len), OCEAN_STATUS_NON_FINITE);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, INFINITY, buf, len), OCEAN_STATUS_NON_FINITE);
    EXPECT_MSG(ocean_scene_render_rgba8(scene, other, TIME, buf, len),
               OCEAN_STATUS_INVALID_ARGUMENT, "another context");
    EXPECT(ocean_scene_render_rgba8((const OceanScene *)(const void *)ctx, ctx, TIME, buf, len),
           OCEAN_STATUS_INVALID_HANDLE);
    {
        size_t i, touched = 0;
        for (i = 0; i < sizeof buf; i++)
            touched += buf[i] != 0x5A;
        CHECK(touched == 0, "%zu output bytes written on failure", touched);
    }
}

/* Returns 1 if the GPU part ran. */
static int test_scene(void)
{
    OceanGpuContext *ctx = NULL, *other = NULL;
    OceanScene *scene = NULL;
    OceanSceneOptions o;
    const char *text = NULL;
    static uint8_t img[W * H * 4], img2[W * H * 4];
    const size_t len = sizeof img;
    uint32_t w = 0, h = 0;
    OceanStatus s = ocean_gpu_context_create(&ctx);

    if (s == OCEAN_STATUS_NO_ADAPTER) {
        if (env_is_1("OCEAN_REQUIRE_GPU")) {
            CHECK(0, "OCEAN_REQUIRE_GPU=1 is set but no GPU context could be created: %s",
                  last_error());
        } else {
            printf("SKIPPED: the scene (no usable GPU adapter: %s). Set OCEAN_REQUIRE_GPU=1 to "
                   "make this a failure.\n",
                   last_error());
        }
        return 0;
    }
    if (!OK(s) || !OK(ocean_scene_builtin_description(&text)) ||
        !OK(ocean_scene_options_default(&o)))
        return 0;
    o.width = W;
    o.height = H;
    o.samples = 1;
    if (!OK(ocean_scene_create(ctx, text, strlen(text), &o, &scene))) {
        ocean_gpu_context_destroy(ctx);
        return 0;
    }
    if (OK(ocean_scene_size(scene, &w, &h)))
        CHECK(w == W && h == H, "size %u x %u, expected %d x %d", w, h, W, H);
    if (OK(ocean_scene_render_rgba8(scene, ctx, TIME, img, len))) {
        const char *path = getenv("OCEAN_SCENE_IMAGE");
        check_image(img);
        OK(ocean_scene_render_rgba8(scene, ctx, TIME, img2, len));
        CHECK(memcmp(img, img2, len) == 0, "the same frame rendered twice differs");
        OK(ocean_scene_render_rgba8(scene, ctx, TIME + 1.0, img2, len));
        CHECK(memcmp(img, img2, len) != 0, "a frame 1 s later is the same");
        if (path != NULL) {
            FILE *f = fopen(path, "wb");
            CHECK(f != NULL && fwrite(img, 1, len, f) == len && fclose(f) == 0,
                  "cannot write %s", path);
        }
    }
    if (OK(ocean_gpu_context_create(&other))) {
        test_errors(ctx, other, text, scene);
        ocean_gpu_context_destroy(other);
    }
    ocean_scene_destroy(scene);
    EXPECT(ocean_scene_size(scene, &w, &h), OCEAN_STATUS_INVALID_HANDLE);
    EXPECT(ocean_scene_render_rgba8(scene, ctx, TIME, img, len), OCEAN_STATUS_INVALID_HANDLE);
    ocean_scene_destroy(scene);
    CHECK(strstr(last_error(), "destroyed") != NULL, "second destroy: \"%s\"", last_error());
    ocean_scene_destroy(NULL);
    ocean_gpu_context_destroy(ctx);
    return 1;
}

int main(void)
{
    int rendered;
    test_description();
    rendered = test_scene();
    printf("test_scene.c: library %s, %d checks, %d failures; the built-in scene%s\n",
           ocean_version(), checks, failures, rendered ? " on the GPU" : " (GPU part SKIPPED)");
    return failures == 0 ? 0 : 1;
}
