#include "fragment_inputs.h"

#include "glrenderer/color_convert.h"

namespace glrenderer {

void FragmentInputs::setFlatColor(const glm::vec4& c, const glm::vec3& secondary) {
    flatColor = fragmentRgba8(c);
    const FragmentKey& key = this->key();  // (the path is set)
    // Fog, the texture environment and the colour sum mix in float before the conversion: the
    // planes a * 0 + c give c at every pixel.
    if (key.fog != FogMode::Off || key.textureEnv != TextureEnv::Off || key.colorSum) {
        for (int i = 0; i < 4; ++i) color.set(i, {c[i], 0.0f, 0.0f});
    }
    if (key.colorSum) {
        for (int i = 0; i < 3; ++i) secondaryColor[i] = {secondary[i], 0.0f, 0.0f};
    }
}

}  // namespace glrenderer
