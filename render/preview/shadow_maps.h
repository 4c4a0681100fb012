#pragma once
// The preview's shadow maps: cube shadow maps of many centres (point, spot and luminaire lights,
// area-light samples, VPLs) spread over several cube map arrays, orthographic maps of
// directional lights, and the geometry drawn into them. Private to render/preview.

#include "core/math.h"
#include "render/preview/gl_objects.h"

#include <array>
#include <vector>

namespace lucerna::preview_detail {

// A 4x4 matrix for column vectors, stored column-major as GLSL expects.
struct Mat4 {
    std::array<float, 16> m{};
    float& at(int row, int col) { return m[size_t(col * 4 + row)]; }
    void setRow(int row, const V3f& v, float w) {
        at(row, 0) = v.x;
        at(row, 1) = v.y;
        at(row, 2) = v.z;
        at(row, 3) = w;
    }
};

// The six cube faces' view-projections for a light at the origin, in GL's cube map order and
// orientation, so that texture(samplerCubeArray, vec4(dir, i)) finds what was drawn along dir.
std::array<Mat4, 6> cubeFaceMatrices(float nearZ, float farZ);

// An orthographic view-projection along a directional light's travel direction over the scene's
// bounding sphere: clip x, y, z = the point's offsets along (side, up, direction) / radius.
Mat4 directionalShadowMatrix(const V3f& direction, const V3f& centre, float radius);

// What a shadow map draw rasterizes: a vertex array of non-indexed triangles, and how far (scene
// units) its surfaces may lie from the true ones (0 for the scene itself; a clustered proxy's
// cell size, render/preview/shadow_proxy.h): the lookups add it to their bias, and the maps
// leave out surfaces nearer their centre than that (shadow.frag).
struct ShadowCaster {
    GLuint vao = 0;
    GLsizei vertexCount = 0;
    float slack = 0;
    GLint firstVertex = 0;
};

// Cube shadow maps (distance in R32F, depth for the z-test) of up to capacity() centres, cube i
// in array i / cubesPerArray(): one cube map array holds at most GL_MAX_ARRAY_TEXTURE_LAYERS / 6
// cubes (341 on llvmpipe). The shaders index `kMaxArrays` samplers (cube_shadows.glsl).
class CubeShadowSet {
public:
    static constexpr int kMaxArrays = 4;
    static int cubesPerArray();
    static int capacity() { return cubesPerArray() * kMaxArrays; }

    // Room for `cubes` cubes (at most capacity()) of faceSize^2 texels a face. Keeps what is
    // drawn when the size is unchanged and the arrays hold enough already.
    void reserve(int cubes, int faceSize);
    // Draws the six faces of cube firstIndex + i from centres[i] for each centre whose cube was
    // not drawn from that point with that caster already (so that when one light of many moves,
    // one cube is drawn), in one instanced draw per array (the geometry shader picks layers).
    // Returns the cubes drawn.
    int draw(const gl::Program& program, const ShadowCaster& caster, const std::vector<V3f>& centres, int firstIndex,
             float sceneRadius, gl::Buffer& scratch);
    // New geometry: every cube must be drawn again.
    void forget() { drawn_.clear(); }
    // The arrays on texture units firstUnit .. firstUnit + kMaxArrays - 1 (an unused unit repeats
    // the first array, so that every sampler has a complete texture).
    void bind(GLuint firstUnit) const;
    int faceSize() const { return size_; }
    int perArray() const { return perArray_; }

private:
    struct Array {
        gl::Texture distance, depth;
        gl::Framebuffer fbo;
    };
    std::array<Array, kMaxArrays> arrays_;
    int size_ = 0, cubes_ = 0, allocated_ = 0, perArray_ = 1;
    // By cube index, where and with which caster it was last drawn ({x, y, z, vao}).
    std::vector<std::array<float, 4>> drawn_;
};

// Orthographic depth maps of directional lights (scene directional lights and the sun, or the
// sky's directions), one layer each, compared in the lookup. With panes (glazing, which casts no
// shadow), a companion layer holds, in front of the opaque depth, the product of the panes'
// transmittances (rgb) and the depth of the pane nearest the light (a): a receiver behind that
// pane takes the product. Exact for one pane, or several all in front of the receiver; a
// receiver between panes takes them all.
struct DirectionalShadows {
    static constexpr int kMaxLights = 8;  // scene directional lights with a map (the sun first)
    gl::Texture depth, transmittance;
    gl::Framebuffer fbo;
    int size = 0, layers = 0;
    bool panes = false;
    // Compared in the lookup with 2 x 2 PCF (directional lights' shadows), or read as numbers
    // at the nearest texel (the sky's many directions: lights.glsl compares them by the
    // receiver's plane).
    bool filtered = true;
    std::vector<Mat4> matrices;

    void ensure(int mapSize, int layerCount, bool withPanes);
    // Draws the layers whose matrix changed since they were last drawn (all after ensure()
    // reallocated or forget()): a depth-only draw of the opaque caster, then with panes the
    // panes' transmittance (paneProgram: glazing.frag; the caller binds the triangles' and
    // materials' buffers). Returns the layers drawn.
    int draw(const gl::Program& depthProgram, const ShadowCaster& caster, const gl::Program& paneProgram,
             const ShadowCaster& paneCaster, int mapSize, bool withPanes);
    // New geometry: every layer must be drawn again.
    void forget() { drawn_.clear(); }

private:
    std::vector<std::array<float, 16>> drawn_;  // by layer, the matrix it was drawn with
};

}  // namespace lucerna::preview_detail
