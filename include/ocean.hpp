/// \file ocean.hpp
/// A header-only C++17 wrapper over the ocean C ABI (ocean.h). It adds no behaviour of its own:
/// every call is the C function of the same name without its `ocean_` prefix, with the same
/// units and conventions (metres, seconds, radians; right-handed, y up, the sea at rest on
/// y = 0; matrices column-major, element [4 * column + row], as `glm::value_ptr` gives them).
///
/// Errors: exceptions, one style throughout.
/// - A failing library call throws `ocean::error` (a `std::runtime_error`): `status()` is the
///   C function's `OceanStatus`, `what()` the thread's `ocean_last_error_message()` copied at
///   the failing call (it names the function, the argument and the value). `ocean::check`
///   does this for every call here.
/// - A buffer the caller passes to an overload taking `ocean::span` whose size does not match
///   what the call writes (or reads, as stated) throws `std::invalid_argument` before the
///   library is called; so does a relief element type that does not match its encoding.
/// - Allocation failures of the overloads that return `std::vector` are `std::bad_alloc` (or
///   `std::length_error` for a size that overflows `size_t`).
/// - The cone map generators also take any callable `bool(std::size_t done, std::size_t total)`
///   as their progress report (true goes on; false cancels: `ocean::error`
///   OCEAN_STATUS_CANCELLED). What it throws cancels the work, never unwinds through the
///   library, and is rethrown unchanged from the generating call.
///
/// Handles: every opaque handle of ocean.h has a move-only owner here (`ocean::waves` owns an
/// `OceanWaves *`, ...) that destroys it; `get()` gives the raw handle, `release()` gives it up.
/// Create them with their static `create` factories, which throw instead of returning null.
/// Query methods are `const` where the C function takes a const handle.
///
/// The GPU part (OCEAN_GPU defined: the full library `libocean`, not `libocean-cpu`) is
/// declared exactly where ocean.h declares its GPU entry points.
///
/// Layout: this file holds the common part (errors, version, span, the handle owner, defaults);
/// the wrappers are in include/ocean/*.hpp by module (waves, lighting, relief, sao, gpu),
/// included at its end. Include ocean.hpp only.
#ifndef OCEAN_HPP
#define OCEAN_HPP

#include "ocean.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace ocean {

// ---------------------------------------------------------------------------------------------
// Errors and version

/// A failed library call: its status and the library's message for it.
class error : public std::runtime_error {
public:
    /// An error of `status` described by `message` (`ocean_status_message` of the status when
    /// `message` is empty).
    error(OceanStatus status, const std::string &message)
        : std::runtime_error(message.empty() ? std::string(ocean_status_message(status))
                                             : message),
          status_(status)
    {
    }
    /// The C function's status (never `OCEAN_STATUS_OK`).
    OceanStatus status() const noexcept { return status_; }

private:
    OceanStatus status_;
};

/// Throws `ocean::error` with `status` and a copy of the thread's last-error message unless
/// `status` is `OCEAN_STATUS_OK`.
inline void check(OceanStatus status)
{
    if (status != OCEAN_STATUS_OK)
        throw error(status, std::string(ocean_last_error_message()));
}

/// The linked library's version, "MAJOR.MINOR.PATCH" (`ocean_version`).
inline std::string version() { return ocean_version(); }

/// The version of the ocean.h this file was compiled with (`OCEAN_VERSION_*`).
inline std::string header_version()
{
    return std::to_string(OCEAN_VERSION_MAJOR) + "." + std::to_string(OCEAN_VERSION_MINOR) +
           "." + std::to_string(OCEAN_VERSION_PATCH);
}

/// Throws `ocean::error` (`OCEAN_STATUS_VERSION_MISMATCH`, both versions in the message)
/// unless the linked library provides the ABI of the header this file was compiled with
/// (`ocean_check_version(OCEAN_VERSION)`). Call it once at start-up.
inline void check_version()
{
    check(ocean_check_version(OCEAN_VERSION));
}

// ---------------------------------------------------------------------------------------------
// span

template <typename T>
class span;

namespace detail {
// C is a contiguous container (std::data and std::size apply) whose elements convert to T
// without more than a qualification conversion (no derived-to-base).
template <typename C, typename T, typename = void>
struct is_container : std::false_type {};
template <typename C, typename T>
struct is_container<C, T,
                    std::void_t<decltype(std::data(std::declval<C &>())),
                                decltype(std::size(std::declval<C &>()))>>
    : std::is_convertible<std::remove_pointer_t<decltype(std::data(std::declval<C &>()))> (*)[],
                          T (*)[]> {};
} // namespace detail

/// A view of `size()` contiguous elements (C++20's std::span, reduced): from a pointer and a
/// size, a C array, std::array, std::vector or any container with data() and size(). It never
/// owns its elements.
template <typename T>
class span {
public:
    /// An empty view.
    constexpr span() noexcept = default;
    /// `size` elements from `data`.
    constexpr span(T *data, std::size_t size) noexcept : data_(data), size_(size) {}
    /// The elements of a contiguous container (or a C array).
    template <typename C, typename = std::enable_if_t<detail::is_container<C, T>::value>>
    constexpr span(C &&c) noexcept(noexcept(std::data(c)) && noexcept(std::size(c)))
        : data_(std::data(c)), size_(std::size(c))
    {
    }
    /// The first element (may be null when empty).
    constexpr T *data() const noexcept { return data_; }
    /// The number of elements.
    constexpr std::size_t size() const noexcept { return size_; }
    /// Whether there are none.
    constexpr bool empty() const noexcept { return size_ == 0; }
    /// Element `i` (unchecked).
    constexpr T &operator[](std::size_t i) const noexcept { return data_[i]; }
    /// Iterators.
    constexpr T *begin() const noexcept { return data_; }
    /// Iterators.
    constexpr T *end() const noexcept { return data_ + size_; }

private:
    T *data_ = nullptr;
    std::size_t size_ = 0;
};

namespace detail {

// A buffer of the wrong size for the call.
inline void check_size(const char *what, std::size_t got, std::size_t want)
{
    if (got != want)
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(got) +
                                    " elements where the call needs " + std::to_string(want));
}

// a * b, or std::length_error when it overflows.
inline std::size_t mul(std::size_t a, std::size_t b)
{
    if (b != 0 && a > std::numeric_limits<std::size_t>::max() / b)
        throw std::length_error("ocean: a size overflows size_t");
    return a * b;
}

// The pointer of a batch argument. An empty std::vector may have a null data(), which the
// library reports as OCEAN_STATUS_NULL_POINTER before the count; an empty batch must give
// OCEAN_STATUS_EMPTY, so it gets a dummy (never read nor written: the count is checked first).
template <typename T>
T *ptr(span<T> s) noexcept
{
    static std::remove_const_t<T> none{};
    return s.data() != nullptr ? s.data() : &none;
}

// The owner of a handle: move-only, destroyed with Destroy.
template <typename T, void (*Destroy)(T *)>
class handle {
public:
    /// No handle.
    handle() noexcept = default;
    /// Takes ownership of `raw` (from the C API; may be null).
    explicit handle(T *raw) noexcept : raw_(raw) {}
    handle(handle &&other) noexcept : raw_(other.release()) {}
    handle &operator=(handle &&other) noexcept
    {
        if (this != &other)
            reset(other.release());
        return *this;
    }
    handle(const handle &) = delete;
    handle &operator=(const handle &) = delete;
    ~handle() { reset(); }

    /// The raw handle, still owned (null after a move or release()).
    T *get() const noexcept { return raw_; }
    /// Gives up ownership: the caller destroys the returned handle.
    T *release() noexcept { return std::exchange(raw_, nullptr); }
    /// Destroys the owned handle and takes `raw` instead.
    void reset(T *raw = nullptr) noexcept
    {
        T *old = std::exchange(raw_, raw);
        if (old != nullptr)
            Destroy(old);
    }
    /// Whether a handle is owned.
    explicit operator bool() const noexcept { return raw_ != nullptr; }

private:
    T *raw_ = nullptr;
};

// Calls f(&value) for one output value and returns it.
template <typename V, typename F>
V out(F &&f)
{
    V value{};
    check(f(&value));
    return value;
}

} // namespace detail

// ---------------------------------------------------------------------------------------------
// Defaults

namespace detail {
inline OceanStatus fill_default(OceanSkyParams *o) { return ocean_sky_params_default(o); }
inline OceanStatus fill_default(OceanSeaParams *o) { return ocean_sea_params_default(o); }
inline OceanStatus fill_default(OceanSpectrumParams *o) { return ocean_spectrum_params_default(o); }
inline OceanStatus fill_default(OceanEffects *o) { return ocean_wtb_effects_default(o); }
inline OceanStatus fill_default(OceanWindDesc *o) { return ocean_wtb_wind_desc_default(o); }
inline OceanStatus fill_default(OceanBoxDesc *o) { return ocean_wtb_box_desc_default(o); }
inline OceanStatus fill_default(OceanReliefMethod *o) { return ocean_relief_method_default(o); }
inline OceanStatus fill_default(OceanReliefConeParams *o)
{
    return ocean_relief_cone_params_default(o);
}
inline OceanStatus fill_default(OceanSaoParams *o) { return ocean_sao_params_default(o); }
#if defined(OCEAN_GPU)
inline OceanStatus fill_default(OceanRendererOptions *o) { return ocean_renderer_options_default(o); }
inline OceanStatus fill_default(OceanSurfaceDrawParams *o)
{
    return ocean_surface_draw_params_default(o);
}
inline OceanStatus fill_default(OceanReliefScene *o) { return ocean_relief_scene_default(o); }
inline OceanStatus fill_default(OceanSceneOptions *o) { return ocean_scene_options_default(o); }
#endif
} // namespace detail

/// The library's defaults of a parameter struct (its `ocean_*_default` function):
/// OceanSkyParams, OceanSeaParams, OceanSpectrumParams, OceanEffects, OceanWindDesc and
/// OceanBoxDesc (of a wave train box scene), OceanReliefConeParams, OceanReliefMethod,
/// OceanSaoParams, and with OCEAN_GPU OceanRendererOptions, OceanSurfaceDrawParams,
/// OceanReliefScene and OceanSceneOptions.
template <typename T>
T defaults()
{
    return detail::out<T>([](T *o) { return detail::fill_default(o); });
}

// ---------------------------------------------------------------------------------------------
// Camera

/// The library's one camera (`OceanCamera`, see ocean.h) from an engine's matrices: the view
/// and projection it draws with, column-major 4x4 (16 floats or doubles, as `glm::value_ptr`
/// gives them), and the depth convention the projection was built for (GLM: [-1, 1],
/// `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, unless GLM_FORCE_DEPTH_ZERO_TO_ONE). The library
/// checks the matrices when a function takes the camera.
template <typename T>
OceanCamera make_camera(const T *view, const T *projection, OceanDepthConvention depth)
{
    static_assert(std::is_floating_point<T>::value, "ocean::make_camera: float or double");
    if (view == nullptr || projection == nullptr)
        throw std::invalid_argument("ocean::make_camera: a null matrix");
    OceanCamera c{};
    for (int i = 0; i < 16; ++i) {
        c.view[i] = double(view[i]);
        c.projection[i] = double(projection[i]);
    }
    c.depth_convention = depth;
    return c;
}

/// make_camera from two arrays of 16 column-major elements.
template <typename T>
OceanCamera make_camera(const std::array<T, 16> &view, const std::array<T, 16> &projection,
                        OceanDepthConvention depth)
{
    return make_camera(view.data(), projection.data(), depth);
}

#if defined(GLM_VERSION)
/// make_camera from GLM matrices (available when GLM is included before ocean.hpp).
template <typename T, glm::qualifier Q>
OceanCamera make_camera(const glm::mat<4, 4, T, Q> &view, const glm::mat<4, 4, T, Q> &projection,
                        OceanDepthConvention depth)
{
    return make_camera(&view[0][0], &projection[0][0], depth);
}
#endif

} // namespace ocean

// The wrappers, by module (each part needs the ones before it).
#include "ocean/waves.hpp"
#include "ocean/lighting.hpp"
#include "ocean/relief.hpp"
#include "ocean/sao.hpp"
#include "ocean/gpu.hpp"

#endif // OCEAN_HPP
