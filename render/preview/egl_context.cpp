#include "render/preview/egl_context.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <vector>

namespace lucerna {

namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Tries the device platform first when a GPU is there (its devices other than the software
// one), then Mesa's surfaceless platform. Both need only the client extensions.
EGLDisplay openDisplay(std::string& platform) {
    const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(clientExts, "EGL_EXT_platform_device")) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        EGLint count = 0;
        if (queryDevices && queryDevices(0, nullptr, &count) && count > 0) {
            std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count), EGLDeviceEXT{});
            queryDevices(count, devices.data(), &count);
            for (EGLDeviceEXT d : devices) {
                // Mesa lists its software device too; that one is what surfaceless gives anyway.
                const char* exts = queryDeviceString ? queryDeviceString(d, EGL_EXTENSIONS) : nullptr;
                if (hasExtension(exts, "EGL_MESA_device_software")) continue;
                EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, d, nullptr);
                EGLint major = 0, minor = 0;
                if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
                    platform = "device";
                    return dpy;
                }
            }
        }
    }
    if (hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
            platform = "surfaceless";
            return dpy;
        }
    }
    throw std::runtime_error("EGL: neither the device nor the surfaceless platform gives a display");
}

}  // namespace

EglContext::EglContext() {
    EGLDisplay dpy = openDisplay(platform_);
    display_ = dpy;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        throw std::runtime_error("EGL: eglBindAPI(EGL_OPENGL_API) failed");
    }
    // No surface at all: configless context (EGL_KHR_no_config_context) where available.
    EGLConfig config = nullptr;
    if (!hasExtension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(dpy, attribs, &config, 1, &n) || n < 1) {
                throw std::runtime_error("EGL: no OpenGL config");
        }
    }
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) {
        throw std::runtime_error("EGL: no OpenGL 4.5 core context (error " + std::to_string(eglGetError()) + ")");
    }
    context_ = ctx;
    makeCurrent();
    const GLubyte* r = glGetString(GL_RENDERER);
    renderer_ = r ? reinterpret_cast<const char*>(r) : "unknown";
    release();
}

EglContext::~EglContext() {
    EGLDisplay dpy = display_;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, static_cast<EGLContext>(context_));
    // No eglTerminate: EGL displays are per-process singletons, and another context (a second
    // preview, a test's) may still be using this one.
}

void EglContext::makeCurrent() const {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)))
        throw std::runtime_error("EGL: eglMakeCurrent failed");
}

void EglContext::release() const { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

}  // namespace lucerna
