#pragma once
// An OpenGL 4.5 core context without any window or display server (DESIGN.md, "Facts verified
// on these machines"): EGL's surfaceless platform on Mesa (llvmpipe in CI and on the command
// line), or EGL_EXT_platform_device on a machine with a GPU. Rendering goes to FBOs only.
//
// A context is current on one thread at a time: the preview is driven from task threads, so
// every entry point makes it current with a ScopedCurrent and releases it afterwards.

#include <string>

namespace lucerna {

class EglContext {
public:
    // Throws std::runtime_error with a one-line reason when no 4.5 core context can be made.
    EglContext();
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    void makeCurrent() const;
    void release() const;
    // "surfaceless" or "device", and the GL_RENDERER string.
    const std::string& platform() const { return platform_; }
    const std::string& renderer() const { return renderer_; }

    class ScopedCurrent {
    public:
        explicit ScopedCurrent(const EglContext& c) : c_(c) { c_.makeCurrent(); }
        ~ScopedCurrent() { c_.release(); }
        ScopedCurrent(const ScopedCurrent&) = delete;
        ScopedCurrent& operator=(const ScopedCurrent&) = delete;

    private:
        const EglContext& c_;
    };

private:
    void* display_ = nullptr;  // EGLDisplay
    void* context_ = nullptr;  // EGLContext
    std::string platform_, renderer_;
};

}  // namespace lucerna
