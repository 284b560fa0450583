/*
 * The checking helpers shared by the C tests of the ocean C ABI: a counted CHECK, and status
 * expectations that also inspect the thread's last-error message.
 *
 * Each test program includes it once (after ocean.h) and prints `checks` and `failures` at the
 * end; the functions are `static inline`, so a program that uses only some of them compiles
 * without unused-function warnings under -Wall -Wextra -Werror -pedantic.
 */
#ifndef OCEAN_TEST_CHECK_H
#define OCEAN_TEST_CHECK_H

#include "ocean.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int checks = 0;
static int failures = 0;

#define CHECK(cond, ...)                                                                   \
    do {                                                                                   \
        checks++;                                                                          \
        if (!(cond)) {                                                                     \
            failures++;                                                                    \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);                           \
            fprintf(stderr, __VA_ARGS__);                                                  \
            fputc('\n', stderr);                                                           \
        }                                                                                  \
    } while (0)

static inline const char *last_error(void)
{
    const char *m = ocean_last_error_message();
    return m ? m : "(NULL)";
}

/* A failure with the expected status and a non-empty message. */
#define EXPECT(call, want) expect((call), (want), #call)
static inline void expect(OceanStatus got, OceanStatus want, const char *what)
{
    const char *m = last_error();
    CHECK(got == want, "%s: status %u (%s), expected %u (%s); message: %s", what,
          (unsigned)got, ocean_status_message(got), (unsigned)want, ocean_status_message(want),
          m);
    CHECK(m[0] != '\0', "%s: empty last-error message", what);
}

/* As EXPECT, and the message mentions `needle`. */
#define EXPECT_MSG(call, want, needle) expect_msg((call), (want), (needle), #call)
static inline void expect_msg(OceanStatus got, OceanStatus want, const char *needle,
                              const char *what)
{
    expect(got, want, what);
    CHECK(strstr(last_error(), needle) != NULL, "%s: message \"%s\" lacks \"%s\"", what,
          last_error(), needle);
}

/* Success, and success leaves no message behind. */
#define OK(call) expect_ok((call), #call)
static inline int expect_ok(OceanStatus s, const char *what)
{
    CHECK(s == OCEAN_STATUS_OK, "%s: status %u (%s): %s", what, (unsigned)s,
          ocean_status_message(s), last_error());
    CHECK(last_error()[0] == '\0', "%s: success left a message: %s", what, last_error());
    return s == OCEAN_STATUS_OK;
}

/* A symmetric perspective as GLM builds it (glm/ext/matrix_clip_space.inl: perspectiveRH_NO,
 * perspectiveRH_ZO, infinitePerspectiveRH and their reversed-Z form), column-major, for depth
 * `convention`; `f` = INFINITY for an infinite far plane. Written here from GLM's formulas, not
 * taken from the library, so the tests check that it reads such matrices. */
static inline void check_perspective(double fov_y, double aspect, double n, double f,
                                     OceanDepthConvention convention, double m[16])
{
    const double t = tan(fov_y / 2.0);
    const int infinite = isinf(f);
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = 1.0 / (aspect * t);
    m[5] = 1.0 / t;
    m[11] = -1.0;
    if (convention == OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE) {
        m[10] = infinite ? -1.0 : -(f + n) / (f - n);
        m[14] = infinite ? -2.0 * n : -(2.0 * f * n) / (f - n);
    } else if (convention == OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED) {
        m[10] = infinite ? 0.0 : n / (f - n);
        m[14] = infinite ? n : (f * n) / (f - n);
    } else {
        m[10] = infinite ? -1.0 : f / (n - f);
        m[14] = infinite ? -n : -(f * n) / (f - n);
    }
}

/* A camera at (x, y, z) looking along -z with y up (the view is a translation by -eye), with
 * the perspective of check_perspective. */
static inline OceanCamera check_camera_at(double x, double y, double z, double fov_y,
                                          double aspect, double n, double f,
                                          OceanDepthConvention convention)
{
    OceanCamera c;
    memset(&c, 0, sizeof c);
    c.view[0] = 1.0;
    c.view[5] = 1.0;
    c.view[10] = 1.0;
    c.view[15] = 1.0;
    c.view[12] = -x;
    c.view[13] = -y;
    c.view[14] = -z;
    check_perspective(fov_y, aspect, n, f, convention, c.projection);
    c.depth_convention = convention;
    return c;
}

#endif
