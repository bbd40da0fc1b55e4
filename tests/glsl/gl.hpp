// Headless OpenGL for phong's GLSL tests and benchmark: an EGL context with no window system,
// desktop GL core or GLES 3, the GL entry points through eglGetProcAddress, and one helper that
// runs a vertex shader over N vertices with transform feedback and reads its output back.
// The display: PHONG_EGL_PLATFORM=surfaceless (Mesa's EGL_MESA_platform_surfaceless: llvmpipe, no
// GPU needed), =device (EGL_EXT_platform_device: the first device whose display initializes,
// hardware before Mesa's software device; NVIDIA's EGL offers only this one), or unset: surfaceless,
// then device.
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLES_PROTOTYPES 0
#include <GLES3/gl3.h>

#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace glt {

#define GLT_FUNCTIONS(X)                                                                                                       \
    X(glCreateShader, PFNGLCREATESHADERPROC) X(glShaderSource, PFNGLSHADERSOURCEPROC) X(glCompileShader, PFNGLCOMPILESHADERPROC) \
    X(glGetShaderiv, PFNGLGETSHADERIVPROC) X(glGetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                                     \
    X(glCreateProgram, PFNGLCREATEPROGRAMPROC) X(glAttachShader, PFNGLATTACHSHADERPROC)                                         \
    X(glTransformFeedbackVaryings, PFNGLTRANSFORMFEEDBACKVARYINGSPROC) X(glLinkProgram, PFNGLLINKPROGRAMPROC)                   \
    X(glGetProgramiv, PFNGLGETPROGRAMIVPROC) X(glGetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC) X(glUseProgram, PFNGLUSEPROGRAMPROC) \
    X(glGetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC) X(glUniform1i, PFNGLUNIFORM1IPROC) X(glUniform1f, PFNGLUNIFORM1FPROC)   \
    X(glUniform3fv, PFNGLUNIFORM3FVPROC) X(glUniform4fv, PFNGLUNIFORM4FVPROC) X(glUniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC)   \
    X(glUniformMatrix3fv, PFNGLUNIFORMMATRIX3FVPROC) X(glGenBuffers, PFNGLGENBUFFERSPROC) X(glBindBuffer, PFNGLBINDBUFFERPROC)   \
    X(glBufferData, PFNGLBUFFERDATAPROC) X(glBindBufferBase, PFNGLBINDBUFFERBASEPROC) X(glGenVertexArrays, PFNGLGENVERTEXARRAYSPROC) \
    X(glBindVertexArray, PFNGLBINDVERTEXARRAYPROC) X(glEnable, PFNGLENABLEPROC) X(glDisable, PFNGLDISABLEPROC)                   \
    X(glBeginTransformFeedback, PFNGLBEGINTRANSFORMFEEDBACKPROC) X(glEndTransformFeedback, PFNGLENDTRANSFORMFEEDBACKPROC)         \
    X(glDrawArrays, PFNGLDRAWARRAYSPROC) X(glMapBufferRange, PFNGLMAPBUFFERRANGEPROC) X(glUnmapBuffer, PFNGLUNMAPBUFFERPROC)     \
    X(glGenTextures, PFNGLGENTEXTURESPROC) X(glBindTexture, PFNGLBINDTEXTUREPROC) X(glTexImage2D, PFNGLTEXIMAGE2DPROC)           \
    X(glTexParameteri, PFNGLTEXPARAMETERIPROC) X(glActiveTexture, PFNGLACTIVETEXTUREPROC) X(glGetString, PFNGLGETSTRINGPROC)     \
    X(glGetError, PFNGLGETERRORPROC) X(glFinish, PFNGLFINISHPROC) X(glDeleteShader, PFNGLDELETESHADERPROC)                       \
    X(glDeleteProgram, PFNGLDELETEPROGRAMPROC) X(glDeleteBuffers, PFNGLDELETEBUFFERSPROC) X(glDeleteTextures, PFNGLDELETETEXTURESPROC) \
    X(glDeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC) X(glVertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC)                  \
    X(glEnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC) X(glPixelStorei, PFNGLPIXELSTOREIPROC)                        \
    X(glGetIntegerv, PFNGLGETINTEGERVPROC) X(glGenFramebuffers, PFNGLGENFRAMEBUFFERSPROC)                                       \
    X(glBindFramebuffer, PFNGLBINDFRAMEBUFFERPROC) X(glGenRenderbuffers, PFNGLGENRENDERBUFFERSPROC)                              \
    X(glBindRenderbuffer, PFNGLBINDRENDERBUFFERPROC) X(glRenderbufferStorage, PFNGLRENDERBUFFERSTORAGEPROC)                      \
    X(glFramebufferRenderbuffer, PFNGLFRAMEBUFFERRENDERBUFFERPROC) X(glDeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)          \
    X(glDeleteRenderbuffers, PFNGLDELETERENDERBUFFERSPROC) X(glReadPixels, PFNGLREADPIXELSPROC) X(glViewport, PFNGLVIEWPORTPROC) \
    X(glClear, PFNGLCLEARPROC) X(glClearColor, PFNGLCLEARCOLORPROC)

struct functions {
#define GLT_MEMBER(name, type) type name = nullptr;
    GLT_FUNCTIONS(GLT_MEMBER)
#undef GLT_MEMBER
};

/// Which API a context speaks, and the #version line of its shaders.
enum class api { gl33_core, gl41_core, gles30 };
inline const char* version_line(api a)
{
    switch (a) {
    case api::gl33_core: return "#version 330 core";
    case api::gl41_core: return "#version 410 core";
    default: return "#version 300 es";
    }
}
inline std::string api_name(api a)
{
    switch (a) {
    case api::gl33_core: return "OpenGL 3.3 core, GLSL 330";
    case api::gl41_core: return "OpenGL 4.1 core, GLSL 410";
    default: return "OpenGL ES 3.0, GLSL 300 es";
    }
}

/// One headless context, current on this thread while the object lives.
class context {
public:
    explicit context(api a) : api_(a)
    {
        display_ = open_display();
        const bool gl = a != api::gles30;
        if (!eglBindAPI(gl ? EGL_OPENGL_API : EGL_OPENGL_ES_API)) throw std::runtime_error("EGL: eglBindAPI failed");
        const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                            gl ? EGL_OPENGL_BIT : EGL_OPENGL_ES3_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        if (!eglChooseConfig(display_, config_attributes, &config, 1, &configs) || configs < 1) config = nullptr; // EGL_NO_CONFIG_KHR
        const EGLint context_major = a == api::gles30 ? 3 : (a == api::gl41_core ? 4 : 3);
        const EGLint context_minor = a == api::gl41_core ? 1 : (a == api::gl33_core ? 3 : 0);
        std::vector<EGLint> attributes{EGL_CONTEXT_MAJOR_VERSION, context_major, EGL_CONTEXT_MINOR_VERSION, context_minor};
        if (gl) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
        attributes.push_back(EGL_NONE);
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes.data());
        if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(std::string("EGL: cannot create a context for ") + api_name(a));
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("EGL: eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context)");
#define GLT_LOAD(name, type)                                                                                                   \
    gl_.name = reinterpret_cast<type>(eglGetProcAddress(#name));                                                               \
    if (!gl_.name) throw std::runtime_error("EGL: no " #name);
        GLT_FUNCTIONS(GLT_LOAD)
#undef GLT_LOAD
        // No window, so no default framebuffer: a draw needs a complete one even with the rasterizer
        // off (else GL_INVALID_FRAMEBUFFER_OPERATION). One 1x1 colour renderbuffer.
        gl_.glGenFramebuffers(1, &framebuffer_);
        gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        gl_.glGenRenderbuffers(1, &renderbuffer_);
        gl_.glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
        gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
        gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer_);
        renderer_ = reinterpret_cast<const char*>(gl_.glGetString(GL_RENDERER));
        version_ = reinterpret_cast<const char*>(gl_.glGetString(GL_VERSION));
    }
    ~context()
    {
        if (framebuffer_) gl_.glDeleteFramebuffers(1, &framebuffer_);
        if (renderbuffer_) gl_.glDeleteRenderbuffers(1, &renderbuffer_);
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    }
    context(const context&) = delete;
    context& operator=(const context&) = delete;

    const functions& gl() const { return gl_; }
    /// The EGL platform the display came from: "surfaceless" or "device".
    const std::string& platform() const { return platform_; }
    api which() const { return api_; }
    const std::string& renderer() const { return renderer_; }
    const std::string& version() const { return version_; }

private:
    /// An initialized display on the platform PHONG_EGL_PLATFORM names (see the top of this file).
    EGLDisplay open_display()
    {
        const auto get_platform_display =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!get_platform_display) throw std::runtime_error("EGL: no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
        const char* wanted = std::getenv("PHONG_EGL_PLATFORM");
        const std::string choice = wanted ? wanted : "";
        if (choice != "" && choice != "surfaceless" && choice != "device")
            throw std::runtime_error("PHONG_EGL_PLATFORM must be surfaceless or device, not '" + choice + "'");
        const auto initialized = [](EGLDisplay d) {
            EGLint major = 0, minor = 0;
            return d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor) == EGL_TRUE;
        };
        if (choice != "device") {
            const EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (initialized(d)) {
                platform_ = "surfaceless";
                return d;
            }
        }
        if (choice != "surfaceless") {
            const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
            const auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
            EGLDeviceEXT devices[16];
            EGLint count = 0;
            if (query_devices && query_devices(16, devices, &count)) {
                const auto is_software = [&](EGLDeviceEXT dev) {
                    const char* ext = query_string ? query_string(dev, EGL_EXTENSIONS) : nullptr;
                    return ext && std::strstr(ext, "EGL_MESA_device_software") != nullptr;
                };
                for (const bool software : {false, true})
                    for (EGLint i = 0; i < count; ++i) {
                        if (is_software(devices[i]) != software) continue;
                        const EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                        if (initialized(d)) {
                            platform_ = "device";
                            return d;
                        }
                    }
            }
        }
        throw std::runtime_error("EGL: no display on the " + (choice.empty() ? std::string("surfaceless or device") : choice) +
                                 " platform (Mesa: EGL_MESA_platform_surfaceless, Debian: libegl-mesa0 libgl1-mesa-dri; NVIDIA: "
                                 "EGL_EXT_platform_device), eglGetError() = " + std::to_string(eglGetError()));
    }

    api api_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    functions gl_;
    GLuint framebuffer_ = 0, renderbuffer_ = 0;
    std::string renderer_, version_, platform_;
};

/// A linked program: a vertex shader whose out variable `varying` (vec4, or vec3) is captured by
/// transform feedback, and a fragment shader that does nothing (ES needs one).
class feedback_program {
public:
    /// varying: the vertex shader's output to capture (nullptr: none, for a program that draws).
    /// fragment_source: "" for one that does nothing.
    feedback_program(const context& c, const std::string& vertex_source, const char* varying, std::string fragment_source = "") : c_(c)
    {
        const functions& gl = c.gl();
        if (fragment_source.empty())
            fragment_source = std::string(version_line(c.which())) + "\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(0.0); }\n";
        const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source), fs = compile(GL_FRAGMENT_SHADER, fragment_source);
        program_ = gl.glCreateProgram();
        gl.glAttachShader(program_, vs);
        gl.glAttachShader(program_, fs);
        if (varying) gl.glTransformFeedbackVaryings(program_, 1, &varying, GL_INTERLEAVED_ATTRIBS);
        gl.glLinkProgram(program_);
        gl.glDeleteShader(vs);
        gl.glDeleteShader(fs);
        GLint ok = 0;
        gl.glGetProgramiv(program_, GL_LINK_STATUS, &ok);
        if (!ok) {
            char log[4096] = {};
            gl.glGetProgramInfoLog(program_, sizeof log, nullptr, log);
            throw std::runtime_error(std::string("GL: link failed: ") + log);
        }
    }
    ~feedback_program() { c_.gl().glDeleteProgram(program_); }
    feedback_program(const feedback_program&) = delete;
    feedback_program& operator=(const feedback_program&) = delete;
    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return c_.gl().glGetUniformLocation(program_, name); }

    /// Runs the vertex shader on vertices 0 .. count - 1 (points, rasterizer off) and returns the
    /// captured output, `components` floats per vertex. Before the draw, `bind` may set uniforms
    /// and attributes (the program is in use, a vertex array object bound).
    template <class Bind>
    std::vector<float> run(int count, int components, Bind&& bind) const
    {
        const functions& gl = c_.gl();
        gl.glUseProgram(program_);
        GLuint vao = 0, out = 0;
        gl.glGenVertexArrays(1, &vao);
        gl.glBindVertexArray(vao);
        bind();
        gl.glGenBuffers(1, &out);
        gl.glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, out);
        gl.glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(sizeof(float)) * count * components, nullptr, GL_STREAM_READ);
        gl.glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, out);
        gl.glEnable(GL_RASTERIZER_DISCARD);
        gl.glBeginTransformFeedback(GL_POINTS);
        gl.glDrawArrays(GL_POINTS, 0, count);
        gl.glEndTransformFeedback();
        gl.glDisable(GL_RASTERIZER_DISCARD);
        std::vector<float> result(std::size_t(count) * std::size_t(components));
        const void* p = gl.glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(sizeof(float)) * count * components, GL_MAP_READ_BIT);
        if (!p) throw std::runtime_error("GL: glMapBufferRange of the feedback buffer failed");
        std::memcpy(result.data(), p, result.size() * sizeof(float));
        gl.glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
        gl.glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        gl.glDeleteBuffers(1, &out);
        gl.glBindVertexArray(0);
        gl.glDeleteVertexArrays(1, &vao);
        const GLenum e = gl.glGetError();
        if (e != GL_NO_ERROR) throw std::runtime_error("GL: error " + std::to_string(e) + " in the transform feedback draw");
        return result;
    }

private:
    GLuint compile(GLenum stage, const std::string& text) const
    {
        const functions& gl = c_.gl();
        const GLuint s = gl.glCreateShader(stage);
        const char* p = text.c_str();
        gl.glShaderSource(s, 1, &p, nullptr);
        gl.glCompileShader(s);
        GLint ok = 0;
        gl.glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[4096] = {};
            gl.glGetShaderInfoLog(s, sizeof log, nullptr, log);
            throw std::runtime_error(std::string("GL: compile failed (") + api_name(c_.which()) + "): " + log);
        }
        return s;
    }
    const context& c_;
    GLuint program_ = 0;
};

/// An RGBA32F texture of `width` x `height` texels (row y: one case), bound to unit 0.
class float_texture {
public:
    float_texture(const context& c, int width, int height, const std::vector<float>& texels) : c_(c)
    {
        const functions& gl = c.gl();
        gl.glActiveTexture(GL_TEXTURE0);
        gl.glGenTextures(1, &id_);
        gl.glBindTexture(GL_TEXTURE_2D, id_);
        gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); // texelFetch needs a complete texture
        gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, texels.data());
    }
    ~float_texture() { c_.gl().glDeleteTextures(1, &id_); }
    float_texture(const float_texture&) = delete;
    float_texture& operator=(const float_texture&) = delete;

private:
    const context& c_;
    GLuint id_ = 0;
};

/// Whether a test may skip when no EGL display or context can be made: only when the environment
/// says so (PHONG_GLSL_ALLOW_SKIP=1); CI does not set it, so a missing display fails loudly there.
inline bool skip_allowed()
{
    const char* s = std::getenv("PHONG_GLSL_ALLOW_SKIP");
    return s && std::string(s) == "1";
}

} // namespace glt
