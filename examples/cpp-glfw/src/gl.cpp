#include "gl.hpp"

namespace gl {

#define OCEAN_GL_DEFINE(type, name) type name = nullptr;
OCEAN_GL_FUNCTIONS(OCEAN_GL_DEFINE)
#undef OCEAN_GL_DEFINE

bool load(GetProcAddress get, std::string &missing)
{
    missing.clear();
    // The pointer returned for a name is of that function's own type (the GL ABI), so the cast
    // back from the generic function pointer is the documented use of glfwGetProcAddress.
#define OCEAN_GL_LOAD(type, fn)                                                                \
    fn = reinterpret_cast<type>(get("gl" #fn));                                                \
    if (fn == nullptr)                                                                         \
        missing += (missing.empty() ? "gl" : ", gl") + std::string(#fn);
    OCEAN_GL_FUNCTIONS(OCEAN_GL_LOAD)
#undef OCEAN_GL_LOAD
    return missing.empty();
}

} // namespace gl
