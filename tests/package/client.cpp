// A C++17 client of an installed ocean library (tests/package/CMakeLists.txt, .ci/package):
// the same checks as client.c, through the C header from C++ with an owning handle.
#include <ocean.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace {

struct WavesDeleter {
    void operator()(OceanWaves* waves) const { ocean_waves_destroy(waves); }
};
using Waves = std::unique_ptr<OceanWaves, WavesDeleter>;

}  // namespace

int main()
{
    const std::string want = std::to_string(OCEAN_VERSION_MAJOR) + "." +
                             std::to_string(OCEAN_VERSION_MINOR) + "." +
                             std::to_string(OCEAN_VERSION_PATCH);
    if (ocean_check_version(OCEAN_VERSION) != OCEAN_STATUS_OK) {
        std::fprintf(stderr, "%s\n", ocean_last_error_message());
        return 1;
    }
    if (want != ocean_version()) {
        std::fprintf(stderr, "library %s, header %s\n", ocean_version(), want.c_str());
        return 1;
    }
    OceanWaveDesc desc{};
    desc.amplitude = 1.0;
    desc.wavelength = 100.0;
    desc.direction_x = 1.0;
    desc.depth = INFINITY;
    OceanWaves* raw = nullptr;
    if (ocean_waves_create(&desc, 1, &raw) != OCEAN_STATUS_OK) {
        std::fprintf(stderr, "ocean_waves_create: %s\n", ocean_last_error_message());
        return 1;
    }
    const Waves waves(raw);
    const OceanVec2 xz{0.0f, 0.0f};
    OceanVec3 pos{}, normal{};
    if (ocean_waves_evaluate(waves.get(), &xz, 1, 0.0, &pos, &normal) != OCEAN_STATUS_OK ||
        std::fabs(pos.y - 1.0) > 1e-6) {
        std::fprintf(stderr, "ocean_waves_evaluate: y = %g (want 1): %s\n", double(pos.y),
                     ocean_last_error_message());
        return 1;
    }
#if defined(OCEAN_GPU)
    std::printf("ocean %s (full, C++): crest at %g m, %zu shaders\n", ocean_version(),
                double(pos.y), ocean_shader_count());
#else
    std::printf("ocean %s (CPU-only, C++): crest at %g m\n", ocean_version(), double(pos.y));
#endif
    return 0;
}
