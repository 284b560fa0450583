// A C++17 client of an installed ocean library (tests/package/CMakeLists.txt, .ci/package):
// the checks of client.c through the installed C++ wrapper, ocean.hpp (owning handles,
// exceptions, spans).
#include <ocean.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

int main()
{
    try {
        ocean::check_version();
        OceanWaveDesc desc{};
        desc.amplitude = 1.0;
        desc.wavelength = 100.0;
        desc.direction_x = 1.0;
        desc.depth = INFINITY;
        const ocean::waves waves = ocean::waves::create(std::vector<OceanWaveDesc>{desc});
        const std::vector<OceanDVec2> xz{{0.0, 0.0}};
        std::vector<OceanDVec3> pos(1);
        std::vector<OceanVec3> normal(1);
        waves.evaluate(xz, 0.0, pos, normal);
        if (std::fabs(pos[0].y - 1.0) > 1e-6) {
            std::fprintf(stderr, "crest at y = %g (want 1)\n", pos[0].y);
            return 1;
        }
#if defined(OCEAN_GPU)
        std::printf("ocean %s (full, C++): crest at %g m, %zu shaders\n", ocean::version().c_str(),
                    pos[0].y, ocean_shader_count());
#else
        std::printf("ocean %s (CPU-only, C++): crest at %g m\n", ocean::version().c_str(),
                    pos[0].y);
#endif
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
