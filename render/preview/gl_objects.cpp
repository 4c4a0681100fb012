#include "render/preview/gl_objects.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lucerna::gl {

Texture makeTexture2D(GLenum internalFormat, int width, int height) {
    Texture t = makeTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, internalFormat, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

Framebuffer makeFramebuffer(std::initializer_list<GLuint> colour, GLuint depth) {
    Framebuffer f = makeFramebuffer();
    GLenum buffers[8];
    GLsizei n = 0;
    for (GLuint c : colour) {
        glNamedFramebufferTexture(f.id(), GL_COLOR_ATTACHMENT0 + n, c, 0);
        buffers[n] = GL_COLOR_ATTACHMENT0 + n;
        ++n;
    }
    glNamedFramebufferDrawBuffers(f.id(), n, buffers);
    if (depth) glNamedFramebufferTexture(f.id(), GL_DEPTH_ATTACHMENT, depth, 0);
    const GLenum status = glCheckNamedFramebufferStatus(f.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("GL: incomplete framebuffer (status " + std::to_string(status) + ")");
    return f;
}

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read shader " + path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

GLuint compile(GLenum stage, const std::string& path, const std::string& defines) {
    std::string src = readFile(path);
    // GLSL has no #include: a line "#include_NAME" is replaced by NAME.glsl of the same folder
    // (brdf.glsl: the BSDF; gbuffer.glsl: the G-buffer's encoding; box_blur.glsl: the blur).
    for (size_t inc; (inc = src.find("#include_")) != std::string::npos;) {
        const size_t end = src.find_first_of("\r\n", inc);
        const std::string name = src.substr(inc + 9, end == std::string::npos ? std::string::npos : end - inc - 9);
        src.replace(inc, 9 + name.size(), readFile(path.substr(0, path.find_last_of('/') + 1) + name + ".glsl"));
    }
    // Defines go right after the #version line, which must stay first.
    const size_t eol = src.find('\n');
    if (!defines.empty() && eol != std::string::npos) src.insert(eol + 1, defines + "\n#line 2\n");
    const GLuint s = glCreateShader(stage);
    const char* text = src.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error("shader " + path + ": " + log);
    }
    return s;
}

}  // namespace

Program loadProgram(const std::string& dir, const std::string& vertex, const std::string& fragment,
                    const std::string& geometry, const std::string& defines) {
    Program p(glCreateProgram());
    GLuint stages[3] = {};
    int n = 0;
    try {
        stages[n++] = compile(GL_VERTEX_SHADER, dir + "/" + vertex, defines);
        if (!geometry.empty()) stages[n++] = compile(GL_GEOMETRY_SHADER, dir + "/" + geometry, defines);
        stages[n++] = compile(GL_FRAGMENT_SHADER, dir + "/" + fragment, defines);
    } catch (...) {
        for (int i = 0; i < n; ++i) glDeleteShader(stages[i]);
        throw;
    }
    for (int i = 0; i < n; ++i) glAttachShader(p.id(), stages[i]);
    glLinkProgram(p.id());
    for (int i = 0; i < n; ++i) glDeleteShader(stages[i]);  // the program keeps them alive
    GLint ok = 0;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetProgramInfoLog(p.id(), sizeof log, nullptr, log);
        throw std::runtime_error("program " + vertex + " + " + fragment + ": " + log);
    }
    return p;
}

void checkErrors(const char* where) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) throw std::runtime_error(std::string("GL error ") + std::to_string(e) + " in " + where);
}

}  // namespace lucerna::gl
