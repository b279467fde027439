// The OpenGL entry points the renderer uses, loaded through the backend's
// GetProcAddress. Nothing links libGL: a libGL ahead of OSMesa makes every GL call a
// silent no-op (toolchain-facts §4), and EGL needs its own dispatch anyway.
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace shaderport::render {

#define SHADERPORT_GL_FUNCTIONS(X)                             \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLCLEARCOLORPROC, ClearColor)                           \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
  X(PFNGLGENTEXTURESPROC, GenTextures)                         \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
  X(PFNGLTEXIMAGE3DPROC, TexImage3D)                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                   \
  X(PFNGLGENSAMPLERSPROC, GenSamplers)                         \
  X(PFNGLBINDSAMPLERPROC, BindSampler)                         \
  X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)             \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)       \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform)               \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv)                           \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv)                           \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                           \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                           \
  X(PFNGLUNIFORM1IVPROC, Uniform1iv)                           \
  X(PFNGLUNIFORM2IVPROC, Uniform2iv)                           \
  X(PFNGLUNIFORM3IVPROC, Uniform3iv)                           \
  X(PFNGLUNIFORM4IVPROC, Uniform4iv)                           \
  X(PFNGLUNIFORM1UIVPROC, Uniform1uiv)                         \
  X(PFNGLUNIFORM2UIVPROC, Uniform2uiv)                         \
  X(PFNGLUNIFORM3UIVPROC, Uniform3uiv)                         \
  X(PFNGLUNIFORM4UIVPROC, Uniform4uiv)                         \
  X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv)               \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)               \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
  X(PFNGLGETACTIVEATTRIBPROC, GetActiveAttrib)                 \
  X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)             \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                       \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                         \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                           \
  X(PFNGLGETFRAGDATALOCATIONPROC, GetFragDataLocation)         \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
  X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)         \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLISPROGRAMPROC, IsProgram)                             \
  X(PFNGLISSHADERPROC, IsShader)                               \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLDELETESHADERPROC, DeleteShader)

struct GlFunctions {
#define SHADERPORT_GL_MEMBER(type, name) type name = nullptr;
  SHADERPORT_GL_FUNCTIONS(SHADERPORT_GL_MEMBER)
#undef SHADERPORT_GL_MEMBER
};

using GetProcFunction = void* (*)(const char* name);

// Fills `gl`; false (with the first missing name in `missing`) when one is absent.
bool LoadGlFunctions(GetProcFunction get_proc, GlFunctions& gl, std::string& missing);

// "GL_INVALID_OPERATION" etc.
const char* GlErrorName(GLenum error);

}  // namespace shaderport::render
