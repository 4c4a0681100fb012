#pragma once
// RAII owners of OpenGL names (buffers, textures, framebuffers, vertex arrays, programs). Each is
// movable, not copyable, and deletes its name when destroyed; the context must be current then
// (the Preview destroys them inside its own ScopedCurrent).

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <string>
#include <utility>

namespace lucerna::gl {

template <void (*Delete)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
inline void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
inline void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }

using Buffer = Handle<deleteBuffer>;
using Texture = Handle<deleteTexture>;
using Framebuffer = Handle<deleteFramebuffer>;
using VertexArray = Handle<deleteVertexArray>;
using Program = Handle<deleteProgram>;
using Query = Handle<deleteQuery>;
using Sampler = Handle<deleteSampler>;

inline Buffer makeBuffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
inline Texture makeTexture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
inline Framebuffer makeFramebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
inline Sampler makeSampler() { GLuint id = 0; glCreateSamplers(1, &id); return Sampler(id); }
inline VertexArray makeVertexArray() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }

// A 2D texture of the given internal format with nearest filtering (all preview passes fetch
// texels exactly).
Texture makeTexture2D(GLenum internalFormat, int width, int height);
// A framebuffer with these colour textures as attachments 0.. and an optional depth texture;
// throws std::runtime_error when incomplete.
Framebuffer makeFramebuffer(std::initializer_list<GLuint> colour, GLuint depth = 0);

// Compiles and links a program from shader files under `dir` (vertex + fragment, or a geometry
// stage too when `geometry` is non-empty). `defines` is inserted after the #version line.
// Throws std::runtime_error with the file name and the compiler's log.
Program loadProgram(const std::string& dir, const std::string& vertex, const std::string& fragment,
                    const std::string& geometry = {}, const std::string& defines = {});

// Throws std::runtime_error naming `where` when glGetError reports anything.
void checkErrors(const char* where);

}  // namespace lucerna::gl
