/* A C11 client of an installed ocean library (tests/package/CMakeLists.txt, .ci/package):
 * checks that the library it runs with is the one its header describes, and evaluates one
 * wave against the closed form (Yrjola & Larsson Eq. 6: a trochoid of amplitude 1 m lifts the
 * point under its crest by exactly 1 m at t = 0). With the full library (OCEAN_GPU, defined by
 * its packages) it also reaches a GPU entry point that needs no adapter. Exits 0 on success. */
#include <ocean.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    char want[32];
    OceanWaveDesc desc;
    OceanWaves *waves = NULL;
    OceanDVec2 xz = {0.0, 0.0};
    OceanDVec3 pos;
    OceanVec3 normal;
    OceanStatus status;

    if (ocean_check_version(OCEAN_VERSION) != OCEAN_STATUS_OK) {
        fprintf(stderr, "%s\n", ocean_last_error_message());
        return 1;
    }
    snprintf(want, sizeof want, "%d.%d.%d", OCEAN_VERSION_MAJOR, OCEAN_VERSION_MINOR,
             OCEAN_VERSION_PATCH);
    if (strcmp(ocean_version(), want) != 0) {
        fprintf(stderr, "library %s, header %s\n", ocean_version(), want);
        return 1;
    }
    memset(&desc, 0, sizeof desc);
    desc.amplitude = 1.0;
    desc.wavelength = 100.0;
    desc.direction_x = 1.0;
    desc.depth = INFINITY;
    status = ocean_waves_create(&desc, 1, &waves);
    if (status != OCEAN_STATUS_OK) {
        fprintf(stderr, "ocean_waves_create: %s\n", ocean_last_error_message());
        return 1;
    }
    status = ocean_waves_evaluate(waves, &xz, 1, 0.0, &pos, &normal);
    ocean_waves_destroy(waves);
    if (status != OCEAN_STATUS_OK || fabs(pos.y - 1.0) > 1e-6) {
        fprintf(stderr, "ocean_waves_evaluate: status %d, y = %g (want 1)\n", (int)status,
                pos.y);
        return 1;
    }
#if defined(OCEAN_GPU)
    if (ocean_shader_count() == 0) {
        fprintf(stderr, "the full library registers no shader\n");
        return 1;
    }
    printf("ocean %s (full): crest at %g m, %u shaders\n", ocean_version(), pos.y,
           (unsigned)ocean_shader_count());
#else
    printf("ocean %s (CPU-only): crest at %g m\n", ocean_version(), pos.y);
#endif
    return 0;
}
