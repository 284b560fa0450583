// A minimal OpenGL 4.3 core loader: the functions this example calls, resolved at run time
// with glfwGetProcAddress (no generated loader). Types and constants come from the system's
// <GL/glcorearb.h> (Khronos' core-profile header, shipped with libgl-dev), which declares no
// functions unless GL_GLEXT_PROTOTYPES is defined; the pointers live in namespace gl, named
// without their "gl" prefix (gl::CreateShader for glCreateShader).
#pragma once

#include <GL/glcorearb.h>

#include <string>

#define OCEAN_GL_FUNCTIONS(X)                                                                  \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                   \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                                     \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                         \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                                 \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                               \
    X(PFNGLBINDIMAGETEXTUREPROC, BindImageTexture)                                             \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                                       \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                               \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                               \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                         \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                                   \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                 \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                                   \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                                   \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                   \
    X(PFNGLCREATESHADERPROC, CreateShader)                                                     \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                         \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                   \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                                     \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                 \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                         \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                           \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                           \
    X(PFNGLDISABLEPROC, Disable)                                                               \
    X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                                               \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                         \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                       \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                     \
    X(PFNGLENABLEPROC, Enable)                                                                 \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                               \
    X(PFNGLFINISHPROC, Finish)                                                                 \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                     \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                         \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                               \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                                       \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                               \
    X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform)                                             \
    X(PFNGLGETERRORPROC, GetError)                                                             \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                           \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                     \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                             \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                       \
    X(PFNGLGETSTRINGPROC, GetString)                                                           \
    X(PFNGLGETTEXIMAGEPROC, GetTexImage)                                                       \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                         \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                       \
    X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                                   \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                       \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                         \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                         \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                     \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                         \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                         \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                   \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                                   \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                                           \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                                       \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                         \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                       \
    X(PFNGLVIEWPORTPROC, Viewport)

namespace gl {

#define OCEAN_GL_DECLARE(type, name) extern type name;
OCEAN_GL_FUNCTIONS(OCEAN_GL_DECLARE)
#undef OCEAN_GL_DECLARE

// A function's address by its full name ("glCreateShader"), or null.
using GetProcAddress = void (*(*)(const char *))();

// Resolves every function with `get`; on failure returns false and names the missing ones in
// `missing`. Call with a current context.
bool load(GetProcAddress get, std::string &missing);

} // namespace gl
