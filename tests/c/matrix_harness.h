/*
 * The fixed half of the bad-input matrix: tests/tests/c_matrix.rs generates the other half (one
 * base call and one call per bad value for every function of include/ocean.h) and includes this
 * file first. It holds the scratch buffers, the live and destroyed handles, the plausible inputs
 * the generator cannot derive from the header, the checks every call gets, and the reporting of
 * failures, crashes and hangs.
 *
 * Before it is included the generated program defines `matrix_status_names` (the OceanStatus
 * values of the header, dense from 0) and MATRIX_STATUS_COUNT.
 *
 * Output format (stdout, line-buffered, read by c_matrix.rs):
 *   FAIL <function> <parameter>=<value>: <what>; status <n> <NAME>; message: <text>
 *   BASE <function> -> <NAME>: <message>          (a base call that failed: information)
 *   CRASH <id> <function> <parameter>=<value> (signal <n>)   then exit 3
 *   HANG <id> <function> <parameter>=<value>                 then exit 4
 *   c_matrix: <N> functions, <M> calls, <F> failures
 *   c_matrix: next id <I>; ...
 * A crash or hang ends the program; the test reruns it from the next variant id (argv[1]).
 */
#ifndef OCEAN_MATRIX_HARNESS_H
#define OCEAN_MATRIX_HARNESS_H

#include "ocean.h"

#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Every pointer argument gets its own scratch buffer of this size (slot = parameter index):
 * big enough for any base call, so a length of 0 or 1 with a real pointer is always in bounds. */
#define MATRIX_BUF ((size_t)1 << 20)
#define MATRIX_SLOTS 12
/* Elements of an input array filled with plausible values (the rest stays zero). */
#define MATRIX_FILL 4096
/* Elements of an output without a length parameter whose floats are checked after success. */
#define MATRIX_FEW 64
/* Byte written over every output before a call; as float or double it is a finite number, so
 * elements a successful call did not write never fail the finiteness check. */
#define MATRIX_SENTINEL 0xA5
/* A single call taking longer than this is reported as a hang. */
#define MATRIX_CALL_SECONDS 30

#define MATRIX_BIT(s) (1u << (unsigned)(s))

struct matrix_kind {
    const char *name;
    void *(*make)(void);
    void (*destroy)(void *);
    /* 1 if the handle is a live handle of this kind (a successful query). */
    int (*alive)(const void *);
};

static unsigned char *slot[MATRIX_SLOTS];
/* A copy of each input slot taken before the call: a const input must come back unchanged. */
static unsigned char *shadow[MATRIX_SLOTS];
static unsigned char *sentinel_bytes;
/* Memory no function of the library returned: a handle argument pointing here must be refused
 * without being read or written. */
static _Alignas(64) unsigned char foreign_memory[64];
/* The head of an extension of a type no version of the library defines (s_type 0xFFFF), and
 * 8-aligned bytes whose address + 4 is a misaligned link. */
static const OceanChain matrix_unknown_extension = {NULL, 0xFFFFu, 0u};
static _Alignas(8) const unsigned char matrix_chain_bytes[32];

static struct {
    long start;    /* first variant id to run (argv[1]); earlier ones are skipped */
    long id;       /* id of the next variant */
    const char *fn;
    const char *param;
    const char *value;
    unsigned allowed; /* statuses the variant may return; 0: any known status */
    int in_base;
    long base_status; /* status of this function's base call, -1 when it did not run */
    long calls, failures, functions, base_ok, base_failed, skipped_lengths;
    OceanStatus status;
    char message[1024];  /* copy of the last-error message after the call */
    char provoked[512];  /* the message set before every call */
    long callback_calls;
    int null_variant;        /* the pointer parameter this variant makes NULL alone, or -1 */
    int null_refused[MATRIX_SLOTS]; /* 1: that variant gave OCEAN_STATUS_NULL_POINTER */
    const struct matrix_kind *kinds;
    int nkinds;
    void *live[32];
    void *dead[32];
} M;

/* "<id> <function> <parameter>=<value>", kept ready for the signal handlers. */
static char current_line[640];

static void on_signal(int sig)
{
    /* Only async-signal-safe calls here: write(2) and _exit(2). */
    char buf[720];
    size_t n = 0;
    const char *head = sig == SIGALRM ? "HANG " : "CRASH ";
    const char *p;
    char digits[16];
    int d = 0, s = sig;
    for (p = head; *p && n < sizeof buf - 1; p++)
        buf[n++] = *p;
    for (p = current_line; *p && n < sizeof buf - 40; p++)
        buf[n++] = *p;
    if (sig != SIGALRM) {
        for (p = " (signal "; *p; p++)
            buf[n++] = *p;
        do {
            digits[d++] = (char)('0' + s % 10);
            s /= 10;
        } while (s > 0);
        while (d > 0)
            buf[n++] = digits[--d];
        buf[n++] = ')';
    }
    buf[n++] = '\n';
    if (write(STDOUT_FILENO, buf, n) < 0) {
        /* Nothing left to report it to. */
    }
    _exit(sig == SIGALRM ? 4 : 3);
}

static inline const char *matrix_status_name(long s)
{
    return s >= 0 && s < MATRIX_STATUS_COUNT ? matrix_status_names[s] : "(unknown status)";
}

static inline void matrix_fail(const char *fmt, ...)
{
    va_list ap;
    M.failures++;
    printf("FAIL %s %s=%s: ", M.fn, M.param, M.value);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("; status %u %s; message: %s\n", (unsigned)M.status, matrix_status_name(M.status),
           M.message);
}

/* Sets a known failure message, so that a call that fails to set or clear it shows. */
static inline void matrix_provoke(void)
{
    double d = 0.0;
    const char *m;
    if (ocean_schlick(NAN, 0.0, &d) == OCEAN_STATUS_OK)
        matrix_fail("ocean_schlick(NAN) succeeded: cannot provoke a message");
    m = ocean_last_error_message();
    snprintf(M.provoked, sizeof M.provoked, "%s", m ? m : "");
}

static inline void matrix_init(int argc, char **argv)
{
    size_t i;
    struct sigaction sa;
    int sigs[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM};
    setvbuf(stdout, NULL, _IOLBF, 0);
    M.start = argc > 1 ? atol(argv[1]) : 0;
    M.base_status = -1;
    for (i = 0; i < MATRIX_SLOTS; i++) {
        slot[i] = aligned_alloc(64, MATRIX_BUF);
        shadow[i] = aligned_alloc(64, MATRIX_BUF);
        if (!slot[i] || !shadow[i]) {
            printf("c_matrix: out of memory\n");
            exit(2);
        }
        memset(slot[i], 0, MATRIX_BUF);
    }
    sentinel_bytes = aligned_alloc(64, MATRIX_BUF);
    if (!sentinel_bytes) {
        printf("c_matrix: out of memory\n");
        exit(2);
    }
    memset(sentinel_bytes, MATRIX_SENTINEL, MATRIX_BUF);
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (i = 0; i < sizeof sigs / sizeof sigs[0]; i++)
        sigaction(sigs[i], &sa, NULL);
}

/* ---- handles ---------------------------------------------------------------------------- */

static inline void matrix_setup_kinds(const struct matrix_kind *kinds, int n)
{
    int k;
    M.kinds = kinds;
    M.nkinds = n;
    for (k = 0; k < n; k++) {
        M.live[k] = kinds[k].make();
        M.dead[k] = kinds[k].make();
        if (!M.live[k] || !M.dead[k]) {
            printf("c_matrix: cannot make an %s: %s\n", kinds[k].name,
                   ocean_last_error_message());
            exit(2);
        }
        kinds[k].destroy(M.dead[k]);
    }
}

static inline void *matrix_live(int k) { return M.live[k]; }
static inline void *matrix_dead(int k) { return M.dead[k]; }
/* A live handle of another kind than k. */
static inline void *matrix_other(int k) { return M.live[(k + 1) % M.nkinds]; }

/* A fresh handle for a kind that calls mutate (a scene), so that what one function's variants
 * changed does not leak into the next function. */
static inline void matrix_refresh(int k)
{
    M.kinds[k].destroy(M.live[k]);
    M.live[k] = M.kinds[k].make();
    if (!M.live[k]) {
        printf("c_matrix: cannot remake an %s: %s\n", M.kinds[k].name,
               ocean_last_error_message());
        exit(2);
    }
}

/* ---- variants ----------------------------------------------------------------------------- */

static inline void matrix_function(const char *name)
{
    M.fn = name;
    M.functions++;
    M.base_status = -1;
    memset(M.null_refused, 0, sizeof M.null_refused);
}

/* Starts variant (param, value); 0 when it is skipped (before argv[1]'s start id). */
static inline int matrix_begin(const char *param, const char *value)
{
    long id = M.id++;
    if (id < M.start)
        return 0;
    M.param = param;
    M.value = value;
    M.allowed = 0;
    M.in_base = strcmp(param, "(base)") == 0;
    M.null_variant = -1;
    M.status = 0;
    M.message[0] = '\0';
    snprintf(current_line, sizeof current_line, "%ld %s %s=%s", id, M.fn, param, value);
    return 1;
}

/* Whether a length variant may run: never a length beyond the real buffer unless its byte size
 * overflows PTRDIFF_MAX (the library cannot know a caller's buffer; a huge length that fits is
 * the caller's bug, not a test case). `max_elem` is the largest element size of the function's
 * pointer parameters. */
static inline int matrix_length_ok(size_t v, size_t max_elem)
{
    if (v <= MATRIX_BUF / max_elem || v > (size_t)PTRDIFF_MAX)
        return 1;
    if (M.id >= M.start)
        M.skipped_lengths++;
    return 0;
}

static inline void matrix_expect(unsigned mask) { M.allowed = mask; }

static inline void matrix_expect_if_base_ok(OceanStatus s)
{
    if (M.base_status == OCEAN_STATUS_OK)
        M.allowed = MATRIX_BIT(s);
}

/* This variant makes pointer parameter i NULL and nothing else. */
static inline void matrix_mark_null(int i) { M.null_variant = i; }

static inline void matrix_expect_if_null_refused(int i)
{
    if (M.null_refused[i])
        M.allowed = MATRIX_BIT(OCEAN_STATUS_NULL_POINTER);
}

static inline void matrix_expect_same_as_base(void)
{
    if (M.base_status >= 0)
        M.allowed = MATRIX_BIT(M.base_status);
}

static inline void matrix_sentinel(int i) { memset(slot[i], MATRIX_SENTINEL, MATRIX_BUF); }

static inline void matrix_snapshot(int i) { memcpy(shadow[i], slot[i], MATRIX_BUF); }

/* A const input came back as it went in. */
static inline void matrix_input_kept(int i, const char *name)
{
    size_t at;
    if (memcmp(slot[i], shadow[i], MATRIX_BUF) == 0)
        return;
    for (at = 0; slot[i][at] == shadow[i][at]; at++) {
    }
    matrix_fail("const input `%s` written at byte %zu", name, at);
}

static inline void matrix_pre_call(void)
{
    matrix_provoke();
    M.callback_calls = 0;
    alarm(MATRIX_CALL_SECONDS);
}

/* The checks of every status-returning call. */
static inline void matrix_post_call(OceanStatus s)
{
    const char *m;
    size_t fn_len = strlen(M.fn);
    alarm(0);
    M.calls++;
    M.status = s;
    m = ocean_last_error_message();
    snprintf(M.message, sizeof M.message, "%s", m ? m : "(NULL)");
    if (!m)
        matrix_fail("ocean_last_error_message() returned NULL");
    if ((long)s >= MATRIX_STATUS_COUNT)
        matrix_fail("unknown status");
    if (s == OCEAN_STATUS_PANIC)
        matrix_fail("the library panicked");
    if (s == OCEAN_STATUS_OK) {
        if (M.message[0] != '\0')
            matrix_fail("success left a message");
    } else if (M.message[0] == '\0') {
        matrix_fail("failure with an empty message");
    } else if (strncmp(M.message, M.fn, fn_len) != 0 || M.message[fn_len] != ':') {
        matrix_fail("the message does not start with \"%s:\" (the previous one left?)", M.fn);
    }
    if (M.allowed != 0 && (M.allowed & MATRIX_BIT(s)) == 0) {
        char want[256] = "";
        long i;
        for (i = 0; i < MATRIX_STATUS_COUNT; i++)
            if (M.allowed & MATRIX_BIT(i)) {
                strncat(want, want[0] ? " or " : "", sizeof want - strlen(want) - 1);
                strncat(want, matrix_status_names[i], sizeof want - strlen(want) - 1);
            }
        matrix_fail("expected %s", want);
    }
    if (M.null_variant >= 0)
        M.null_refused[M.null_variant] = s == OCEAN_STATUS_NULL_POINTER;
    if (M.in_base) {
        M.base_status = (long)s;
        if (s == OCEAN_STATUS_OK) {
            M.base_ok++;
        } else {
            M.base_failed++;
            printf("BASE %s -> %s: %s\n", M.fn, matrix_status_name(s), M.message);
        }
    }
}

/* A failed call left output buffer i as it was. */
static inline void matrix_untouched(int i, const char *name)
{
    size_t at;
    if (memcmp(slot[i], sentinel_bytes, MATRIX_BUF) == 0)
        return;
    for (at = 0; slot[i][at] == MATRIX_SENTINEL; at++) {
    }
    matrix_fail("output `%s` written at byte %zu on failure", name, at);
}

/* A successful call wrote output slot i only within its first `len` elements of `elem` bytes
 * (`len` from the parameter that sizes it). */
static inline void matrix_written_within(int i, size_t len, size_t elem, const char *name)
{
    size_t from, at;
    if (len > MATRIX_BUF / elem)
        return;
    from = len * elem;
    if (memcmp(slot[i] + from, sentinel_bytes, MATRIX_BUF - from) == 0)
        return;
    for (at = from; slot[i][at] == MATRIX_SENTINEL; at++) {
    }
    matrix_fail("output `%s` written at byte %zu, beyond its %zu elements of %zu bytes", name, at,
                len, elem);
}

static inline size_t matrix_count(size_t len, size_t elem)
{
    return len < MATRIX_BUF / elem ? len : MATRIX_BUF / elem;
}

static inline void matrix_nonfinite(const char *name, size_t i, const char *leaf, double v)
{
    matrix_fail("output `%s`[%zu]%s is %g after success", name, i, leaf, v);
}

static inline void matrix_finite_f32(const unsigned char *p, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float v;
        memcpy(&v, p + i * sizeof v, sizeof v);
        if (!isfinite(v)) {
            matrix_nonfinite(name, i, "", v);
            return;
        }
    }
}

static inline void matrix_finite_f64(const unsigned char *p, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double v;
        memcpy(&v, p + i * sizeof v, sizeof v);
        if (!isfinite(v)) {
            matrix_nonfinite(name, i, "", v);
            return;
        }
    }
}

/* A member documented to take INFINITY may be +INFINITY; NaN never. */
static inline int matrix_ok_value(double v, int infinity_ok)
{
    return isfinite(v) || (infinity_ok && isinf(v) && v > 0);
}

/* The handle a successful call stored in output slot i: live, of kind k; then destroyed. */
static inline void matrix_got_handle(int k, int i, const char *name)
{
    void *h;
    memcpy(&h, slot[i], sizeof h);
    if (!h) {
        matrix_fail("success stored NULL in `%s`", name);
        return;
    }
    if (!M.kinds[k].alive(h))
        matrix_fail("`%s` is not a live %s after success", name, M.kinds[k].name);
    M.kinds[k].destroy(h);
}

/* ---- destroy functions and functions without a status ------------------------------------- */

static inline void matrix_pre_plain(void)
{
    matrix_provoke();
    alarm(MATRIX_CALL_SECONDS);
}

static inline void matrix_post_plain(void)
{
    const char *m = ocean_last_error_message();
    alarm(0);
    M.calls++;
    M.status = 0;
    snprintf(M.message, sizeof M.message, "%s", m ? m : "(NULL)");
}

/* The call left the last-error message alone. */
static inline void matrix_message_kept(void)
{
    if (strcmp(M.message, M.provoked) != 0)
        matrix_fail("the last-error message changed (it was \"%s\")", M.provoked);
}

/* The call refused its argument and said so in the last-error message. */
static inline void matrix_message_set(void)
{
    size_t n = strlen(M.fn);
    if (strncmp(M.message, M.fn, n) != 0 || M.message[n] != ':')
        matrix_fail("misuse not described in the last-error message");
}

static inline void matrix_expect_alive(int k, const void *h, int want)
{
    if (M.kinds[k].alive(h) != want)
        matrix_fail(want ? "the %s handle no longer works" : "the %s handle still works",
                    M.kinds[k].name);
}

static inline void matrix_foreign_untouched(void)
{
    size_t i;
    for (i = 0; i < sizeof foreign_memory; i++)
        if (foreign_memory[i] != 0) {
            matrix_fail("memory passed as a handle was written at byte %zu", i);
            memset(foreign_memory, 0, sizeof foreign_memory);
            return;
        }
}

static inline int matrix_summary(const char *gpu_skipped)
{
    printf("c_matrix: %ld functions, %ld calls, %ld failures\n", M.functions, M.calls,
           M.failures);
    printf("c_matrix: next id %ld; library %s; %ld base calls succeeded, %ld failed; %ld length "
           "variants skipped (a length beyond the buffer that does not overflow); skipped (GPU "
           "handles): %s\n",
           M.id, ocean_version(), M.base_ok, M.base_failed, M.skipped_lengths, gpu_skipped);
    return M.failures != 0;
}

/* ---- plausible inputs the header cannot give --------------------------------------------
 * The generator fills an input struct with the library's `ocean_*_default` where one exists,
 * else with `plausible_<Struct>` below when defined here, else with zeros. */

static inline void plausible_OceanDVec3(OceanDVec3 *p)
{
    /* A unit vector with y > 0 (above the sea) and z > 0 (above a tangent plane). */
    p->x = 0.0;
    p->y = 0.6;
    p->z = 0.8;
}

static inline void plausible_OceanDVec2(OceanDVec2 *p)
{
    p->x = 3.0;
    p->z = 5.0;
}

static inline void plausible_OceanRgb(OceanRgb *p)
{
    p->r = 0.5;
    p->g = 0.4;
    p->b = 0.3;
}

static inline void plausible_OceanWaveDesc(OceanWaveDesc *p)
{
    p->amplitude = 0.5;
    p->wavelength = 20.0;
    p->direction_x = 1.0;
    p->direction_z = 0.5;
    p->phase = 0.25;
    p->depth = INFINITY;
}

static inline void plausible_OceanGrid(OceanGrid *p)
{
    p->origin_x = -2.0;
    p->origin_z = 3.0;
    p->spacing_x = 1.0;
    p->spacing_z = 0.5;
    p->nx = 4;
    p->nz = 4;
}

static inline void plausible_OceanWaterGridDesc(OceanWaterGridDesc *p)
{
    /* The grid of the scene handle (make_OceanWtbScene). */
    p->origin_x = 0.0;
    p->origin_z = 0.0;
    p->spacing = 1.0;
    p->nx = 16;
    p->nz = 16;
}

static inline void plausible_OceanCamera(OceanCamera *p)
{
    /* The eye 4 m above the sea looking along -z (view = a translation by (0, -4, 0)), a GL
     * perspective of 90 degrees, square, near 0.1 m, far 100 m (column-major). */
    int i;
    memset(p, 0, sizeof *p);
    for (i = 0; i < 4; i++)
        p->view[5 * i] = 1.0;
    p->view[13] = -4.0;
    p->projection[0] = 1.0;
    p->projection[5] = 1.0;
    p->projection[10] = -100.1 / 99.9;
    p->projection[11] = -1.0;
    p->projection[14] = -20.0 / 99.9;
    p->depth_convention = OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE;
}

static inline void plausible_OceanBoxDesc(OceanBoxDesc *p)
{
    /* A 10 m box on the scene's 16 x 16 m grid, its wind blowing along +x for ever. */
    memset(p, 0, sizeof *p);
    p->wind.speed = 8.0;
    p->wind.direction_x = 1.0;
    p->wind.direction_z = 0.0;
    p->wind.origin_x = 2.0;
    p->wind.origin_z = 2.0;
    p->wind.width = 10.0;
    p->wind.fetch = 10.0;
    p->wind.start = 0.0;
    p->wind.build_up = 1.0;
    p->wind.sustain = INFINITY;
    p->wind.decay = 1.0;
    p->wind.seed = 7;
    p->wind.trains = 2;
    p->smoothing = 1.0;
    p->has_recovery = 1;
    p->recovery = 2.0;
}

static inline void plausible_OceanReliefMethod(OceanReliefMethod *p)
{
    p->method = OCEAN_RELIEF_TRACER_RELAXED;
    p->steps = 15;
    p->binary = 6;
    p->search = OCEAN_RELIEF_SEARCH_LAST_STEP;
}

static inline void plausible_OceanReliefRay(OceanReliefRay *p)
{
    p->start_u = 0.3f;
    p->start_v = 0.6f;
    p->dir_x = 0.2f;
    p->dir_y = -0.1f;
    p->dir_z = 1.0f;
}

static inline void plausible_OceanReliefPoint(OceanReliefPoint *p)
{
    p->u = 0.3f;
    p->v = 0.6f;
    p->depth = 0.5f;
}

static inline void plausible_OceanSeaColorInput(OceanSeaColorInput *p)
{
    plausible_OceanDVec3(&p->v);
    p->n.x = 0.0;
    p->n.y = 1.0;
    p->n.z = 0.0;
    p->wind.x = 1.0;
    p->wind.z = 0.0;
    p->sigma_x2 = 0.01;
    p->sigma_y2 = 0.005;
}

/* Input arrays of primitives: a pattern in [0, 1] unless a function's override says otherwise. */
static inline void matrix_fill_f32(unsigned char *buf, size_t n, float offset, float scale)
{
    size_t i;
    for (i = 0; i < n; i++) {
        float v = offset + scale * (float)((i * 7) % 16) / 15.0f;
        memcpy(buf + i * sizeof v, &v, sizeof v);
    }
}

static inline void matrix_fill_f64(unsigned char *buf, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double v = (double)((i * 7) % 16) / 15.0;
        memcpy(buf + i * sizeof v, &v, sizeof v);
    }
}

static inline void matrix_fill_u8(unsigned char *buf, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        buf[i] = (unsigned char)((i * 37) % 256);
}

static inline void matrix_fill_u16(unsigned char *buf, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        uint16_t v = (uint16_t)((i * 9973) % 65536);
        memcpy(buf + i * sizeof v, &v, sizeof v);
    }
}

/* ---- progress callbacks --------------------------------------------------------------- */

static int matrix_cookie;

static int count_OceanReliefProgress(void *user, size_t done, size_t total)
{
    M.callback_calls++;
    if (user != &matrix_cookie)
        matrix_fail("the callback got user %p, not the one passed", user);
    if (done > total)
        matrix_fail("the callback got done %zu > total %zu", done, total);
    return 0;
}

static int cancel_OceanReliefProgress(void *user, size_t done, size_t total)
{
    (void)user;
    (void)done;
    (void)total;
    M.callback_calls++;
    return 1;
}

/* ---- the handles: one maker per CPU kind ------------------------------------------------- */

static uint32_t matrix_box_a, matrix_box_b;

static inline void *make_OceanWaves(void)
{
    OceanWaveDesc w[3];
    OceanWaves *h = NULL;
    int i;
    for (i = 0; i < 3; i++) {
        plausible_OceanWaveDesc(&w[i]);
        w[i].wavelength = 10.0 * (i + 1);
        w[i].amplitude = 0.1 * (i + 1);
    }
    return ocean_waves_create(w, 3, &h) == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanWtbScene(void)
{
    /* A 16 x 16 grid (1 m spacing) over a sloping sea floor, two boxes, evaluated once so that
     * the drawn height queries have a frame to answer for. */
    OceanWaterGridDesc grid;
    OceanBoxDesc box;
    OceanWtbScene *h = NULL;
    float terrain[16 * 16];
    static OceanVec3 pos[16 * 16], nrm[16 * 16];
    int i;
    plausible_OceanWaterGridDesc(&grid);
    for (i = 0; i < 16 * 16; i++)
        terrain[i] = -20.0f + (float)(i % 16);
    if (ocean_wtb_scene_create(&grid, terrain, 16 * 16, &h) != OCEAN_STATUS_OK)
        return NULL;
    plausible_OceanBoxDesc(&box);
    if (ocean_wtb_scene_add_box(h, &box, NULL, 0, &matrix_box_a) != OCEAN_STATUS_OK ||
        ocean_wtb_scene_add_box(h, &box, NULL, 0, &matrix_box_b) != OCEAN_STATUS_OK ||
        ocean_wtb_scene_evaluate(h, 2.0, NULL, pos, nrm, 16 * 16, NULL) != OCEAN_STATUS_OK) {
        ocean_wtb_scene_destroy(h);
        return NULL;
    }
    return h;
}

static inline void *make_OceanSpectrum(void)
{
    OceanSpectrumParams p;
    OceanSpectrum *h = NULL;
    if (ocean_spectrum_params_default(&p) != OCEAN_STATUS_OK)
        return NULL;
    return ocean_spectrum_create(&p, &h) == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanLighting(void)
{
    OceanSkyParams sky;
    OceanSeaParams sea;
    OceanLighting *h = NULL;
    if (ocean_sky_params_default(&sky) != OCEAN_STATUS_OK ||
        ocean_sea_params_default(&sea) != OCEAN_STATUS_OK)
        return NULL;
    return ocean_lighting_create(&sky, &sea, &h) == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanSkyMap(void)
{
    /* Of a default lighting (ocean_sea_color accepts a map of any lighting with equal
     * parameters). Sky maps outlive their lighting. */
    OceanLighting *l = make_OceanLighting();
    OceanSkyMap *h = NULL;
    OceanStatus s;
    if (!l)
        return NULL;
    s = ocean_lighting_sky_map_create(l, 8, &h);
    ocean_lighting_destroy(l);
    return s == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanReliefMap(void)
{
    /* 16 x 16, wrapping: cone generation stays fast. */
    static float heights[16 * 16];
    OceanReliefMap *h = NULL;
    matrix_fill_f32((unsigned char *)heights, 16 * 16, 0.0f, 1.0f);
    return ocean_relief_map_create_f32(heights, 16 * 16, 16, 16, OCEAN_RELIEF_EDGE_WRAP,
                                       OCEAN_RELIEF_RANGE_REFUSE, &h) == OCEAN_STATUS_OK
               ? (void *)h
               : NULL;
}

static inline void *make_OceanReliefCones(void)
{
    OceanReliefMap *map = make_OceanReliefMap();
    OceanReliefConeParams cp;
    OceanReliefCones *h = NULL;
    OceanStatus s = OCEAN_STATUS_NULL_POINTER;
    if (map && ocean_relief_cone_params_default(&cp) == OCEAN_STATUS_OK)
        s = ocean_relief_cones_create(map, &cp, NULL, NULL, &h);
    ocean_relief_map_destroy(map);
    return s == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanReliefMips(void)
{
    OceanReliefCones *cones = make_OceanReliefCones();
    OceanReliefMips *h = NULL;
    OceanStatus s = OCEAN_STATUS_NULL_POINTER;
    if (cones)
        s = ocean_relief_mips_create(cones, OCEAN_RELIEF_MIP_WINDOW, &h);
    ocean_relief_cones_destroy(cones);
    return s == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanReliefQuadCones(void)
{
    OceanReliefMap *map = make_OceanReliefMap();
    OceanReliefConeParams cp;
    OceanReliefQuadCones *h = NULL;
    OceanStatus s = OCEAN_STATUS_NULL_POINTER;
    if (map && ocean_relief_cone_params_default(&cp) == OCEAN_STATUS_OK)
        s = ocean_relief_quad_cones_create(map, &cp, NULL, NULL, &h);
    ocean_relief_map_destroy(map);
    return s == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanSao(void)
{
    /* 32 x 32 with a guard band of 2: a 28 x 28 AO image. */
    OceanCamera cam;
    OceanSaoParams p;
    OceanSao *h = NULL;
    plausible_OceanCamera(&cam);
    if (ocean_sao_params_default(&p) != OCEAN_STATUS_OK)
        return NULL;
    return ocean_sao_create(32, 32, 2, &cam, OCEAN_SAO_DEPTH_WINDOW, &p, &h) == OCEAN_STATUS_OK ? (void *)h : NULL;
}

static inline void *make_OceanShaderExport(void)
{
    OceanShaderExport *h = NULL;
    return ocean_shader_export("trochoid", OCEAN_SHADER_LANGUAGE_GLSL, &h) == OCEAN_STATUS_OK
               ? (void *)h
               : NULL;
}

#endif
