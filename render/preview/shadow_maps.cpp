#include "render/preview/shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lucerna::preview_detail {

std::array<Mat4, 6> cubeFaceMatrices(float nearZ, float farZ) {
    const V3f fwd[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const V3f up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    std::array<Mat4, 6> out;
    const float a = (farZ + nearZ) / (farZ - nearZ), b = -2.0f * farZ * nearZ / (farZ - nearZ);
    for (int i = 0; i < 6; ++i) {
        const V3f f = fwd[i], s = f.cross(up[i]).normalized(), u = s.cross(f);
        // 90 degrees, aspect 1: x_c = s.p, y_c = u.p, w_c = f.p.
        out[i].setRow(0, s, 0);
        out[i].setRow(1, u, 0);
        out[i].setRow(2, f * a, b);
        out[i].setRow(3, f, 0);
    }
    return out;
}

Mat4 directionalShadowMatrix(const V3f& direction, const V3f& centre, float radius) {
    const V3f f = direction.normalized();
    const V3f helper = std::abs(f.y) < 0.9f ? V3f(0, 1, 0) : V3f(1, 0, 0);
    const V3f side = f.cross(helper).normalized(), up = side.cross(f);
    Mat4 m;
    const float k = 1.0f / (radius * 1.01f);
    m.setRow(0, side * k, -side.dot(centre) * k);
    m.setRow(1, up * k, -up.dot(centre) * k);
    m.setRow(2, f * k, -f.dot(centre) * k);
    m.setRow(3, V3f(0, 0, 0), 1.0f);
    return m;
}

int CubeShadowSet::cubesPerArray() {
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    return std::max(1, int(maxLayers) / 6);
}

void CubeShadowSet::reserve(int cubes, int faceSize) {
    const int perArray = cubesPerArray();
    if (cubes > perArray * kMaxArrays)
        throw std::logic_error("preview: " + std::to_string(cubes) + " shadow cubes asked of a set of " +
                               std::to_string(perArray * kMaxArrays));
    cubes = std::max(cubes, 1);
    cubes_ = cubes;
    if (faceSize == size_ && cubes <= allocated_ && perArray == perArray_) return;
    drawn_.clear();
    size_ = faceSize;
    perArray_ = perArray;
    allocated_ = cubes;
    for (int a = 0; a < kMaxArrays; ++a) {
        Array& arr = arrays_[size_t(a)];
        const int inArray = std::clamp(cubes - a * perArray, 0, perArray);
        if (inArray == 0) {
            arr = Array();
            continue;
        }
        arr.distance = gl::makeTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
        glTextureStorage3D(arr.distance.id(), 1, GL_R32F, size_, size_, inArray * 6);
        glTextureParameteri(arr.distance.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(arr.distance.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        arr.depth = gl::makeTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
        glTextureStorage3D(arr.depth.id(), 1, GL_DEPTH_COMPONENT32F, size_, size_, inArray * 6);
        arr.fbo = gl::makeFramebuffer({arr.distance.id()}, arr.depth.id());
    }
}

int CubeShadowSet::draw(const gl::Program& program, const ShadowCaster& caster, const std::vector<V3f>& centres,
                        int firstIndex, float sceneRadius, gl::Buffer& scratch) {
    if (centres.empty() || caster.vertexCount == 0) return 0;
    if (firstIndex + int(centres.size()) > allocated_) throw std::logic_error("preview: shadow cube beyond the set");
    // The near plane well inside the lift of a cube's centre off its surface (1e-4 of the radius,
    // interleaved_vpls.cpp and direct_lights.cpp): at 1e-3 it clipped away a wall a few
    // millimetres from a VPL, whose light then leaked through it. The depth only orders the
    // fragments (the distance is stored exactly); at 10 m it still tells surfaces 2 cm apart.
    const auto faces = cubeFaceMatrices(sceneRadius * 1e-5f, sceneRadius * 4.0f);
    glProgramUniformMatrix4fv(program.id(), glGetUniformLocation(program.id(), "faceProj"), 6, GL_FALSE,
                              faces[0].m.data());
    glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "nearSkip"), caster.slack);
    glUseProgram(program.id());
    glBindVertexArray(caster.vao);
    glEnable(GL_DEPTH_TEST);
    glViewport(0, 0, size_, size_);
    int drawnNow = 0;
    for (int a = 0; a < kMaxArrays; ++a) {
        // The stale cubes of array a, as (centre, cube index inside the array).
        std::vector<std::array<float, 4>> stale;
        for (size_t i = 0; i < centres.size(); ++i) {
            const int cube = firstIndex + int(i);
            if (cube / perArray_ != a) continue;
            const std::array<float, 4> key{centres[i].x, centres[i].y, centres[i].z, float(caster.vao)};
            if (size_t(cube) < drawn_.size() && drawn_[size_t(cube)] == key) continue;
            if (drawn_.size() <= size_t(cube)) drawn_.resize(size_t(cube) + 1, {0, 0, 0, -1});
            drawn_[size_t(cube)] = key;
            stale.push_back({centres[i].x, centres[i].y, centres[i].z, float(cube - a * perArray_)});
        }
        if (stale.empty()) continue;
        const Array& arr = arrays_[size_t(a)];
        const float far = 1e30f, one = 1.0f;
        for (const auto& c : stale) {
            const GLint firstLayer = GLint(c[3]) * 6;
            glClearTexSubImage(arr.distance.id(), 0, 0, 0, firstLayer, size_, size_, 6, GL_RED, GL_FLOAT, &far);
            glClearTexSubImage(arr.depth.id(), 0, 0, 0, firstLayer, size_, size_, 6, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
        }
        scratch = gl::makeBuffer();
        glNamedBufferStorage(scratch.id(), GLsizeiptr(stale.size() * sizeof(stale[0])), stale.data(), 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, scratch.id());
        glBindFramebuffer(GL_FRAMEBUFFER, arr.fbo.id());
        glDrawArraysInstanced(GL_TRIANGLES, caster.firstVertex, caster.vertexCount, GLsizei(stale.size()));
        drawnNow += int(stale.size());
    }
    glDisable(GL_DEPTH_TEST);
    return drawnNow;
}

void CubeShadowSet::bind(GLuint firstUnit) const {
    for (int a = 0; a < kMaxArrays; ++a) {
        const Array& arr = arrays_[size_t(a)].distance ? arrays_[size_t(a)] : arrays_[0];
        glBindTextureUnit(firstUnit + GLuint(a), arr.distance.id());
    }
}

void DirectionalShadows::ensure(int mapSize, int layerCount, bool withPanes) {
    layerCount = std::max(layerCount, 1);  // always something bound to the sampler
    if (mapSize == size && layerCount <= layers && withPanes == panes && depth) return;
    drawn_.clear();
    size = mapSize;
    layers = layerCount;
    panes = withPanes;
    depth = gl::makeTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depth.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
    glTextureParameteri(depth.id(), GL_TEXTURE_MIN_FILTER, filtered ? GL_LINEAR : GL_NEAREST);  // 2 x 2 PCF
    glTextureParameteri(depth.id(), GL_TEXTURE_MAG_FILTER, filtered ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, filtered ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    transmittance = gl::Texture();
    if (panes) {
        // Half floats: the transmittance to 0.05%, the pane's depth to 2^-11 of the map's range.
        transmittance = gl::makeTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(transmittance.id(), 1, GL_RGBA16F, size, size, layers);
        glTextureParameteri(transmittance.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(transmittance.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureParameteri(transmittance.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(transmittance.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    fbo = gl::makeFramebuffer();
    glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
}

int DirectionalShadows::draw(const gl::Program& depthProgram, const ShadowCaster& caster, const gl::Program& paneProgram,
                             const ShadowCaster& paneCaster, int mapSize, bool withPanes) {
    ensure(mapSize, int(matrices.size()), withPanes && paneCaster.vertexCount > 0);
    if (matrices.empty()) return 0;
    glViewport(0, 0, size, size);
    int drawnNow = 0;
    for (size_t i = 0; i < matrices.size(); ++i) {
        if (i < drawn_.size() && drawn_[i] == matrices[i].m) continue;
        if (drawn_.size() <= i) drawn_.resize(i + 1);
        drawn_[i] = matrices[i].m;
        ++drawnNow;
        glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0, GLint(i));
        glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        const float one = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
        glEnable(GL_DEPTH_TEST);
        glUseProgram(depthProgram.id());
        glProgramUniformMatrix4fv(depthProgram.id(), glGetUniformLocation(depthProgram.id(), "lightViewProj"), 1,
                                  GL_FALSE, matrices[i].m.data());
        glBindVertexArray(caster.vao);
        glDrawArrays(GL_TRIANGLES, caster.firstVertex, caster.vertexCount);
        if (!panes) continue;
        // The panes in front of the opaque depth, not writing it: their transmittances
        // multiplied (any order), the nearest one's depth kept by GL_MIN.
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, transmittance.id(), 0, GLint(i));
        glNamedFramebufferDrawBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
        const float white[4] = {1, 1, 1, 1};
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, white);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE);
        glUseProgram(paneProgram.id());
        glProgramUniformMatrix4fv(paneProgram.id(), glGetUniformLocation(paneProgram.id(), "lightViewProj"), 1,
                                  GL_FALSE, matrices[i].m.data());
        glProgramUniform1i(paneProgram.id(), glGetUniformLocation(paneProgram.id(), "firstTriangle"),
                           paneCaster.firstVertex / 3);
        glBindVertexArray(paneCaster.vao);
        glDrawArrays(GL_TRIANGLES, paneCaster.firstVertex, paneCaster.vertexCount);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        glNamedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, 0, 0, 0);
    }
    glDisable(GL_DEPTH_TEST);
    return drawnNow;
}

}  // namespace lucerna::preview_detail
