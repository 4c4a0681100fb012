#include "render/preview/luminaire_textures.h"

#include <algorithm>

namespace lucerna::preview_detail {

gl::Texture makeLuminaireTables(const std::vector<const GoniometricDistribution*>& distributions) {
    const int layers = std::max(1, int(distributions.size()));
    std::vector<float> texels(size_t(kLuminaireTableC) * kLuminaireTableGamma * size_t(layers), 0.0f);
    for (size_t k = 0; k < distributions.size(); ++k) {
        float* layer = texels.data() + k * size_t(kLuminaireTableC) * kLuminaireTableGamma;
        for (int g = 0; g < kLuminaireTableGamma; ++g)
            for (int c = 0; c < kLuminaireTableC; ++c) {
                const double cDeg = 360.0 * c / (kLuminaireTableC - 1);
                const double gDeg = 180.0 * g / (kLuminaireTableGamma - 1);
                layer[size_t(g) * kLuminaireTableC + size_t(c)] = float(distributions[k]->intensity(cDeg, gDeg));
            }
    }
    gl::Texture t = gl::makeTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.id(), 1, GL_R32F, kLuminaireTableC, kLuminaireTableGamma, layers);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, kLuminaireTableC, kLuminaireTableGamma, layers, GL_RED, GL_FLOAT,
                        texels.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace lucerna::preview_detail
