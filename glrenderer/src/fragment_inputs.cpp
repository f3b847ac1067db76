#include "fragment_inputs.h"

#include "glrenderer/color_convert.h"

namespace glrenderer {

void FragmentInputs::setFlatColor(const glm::vec4& c) {
    flatColor = fragmentRgba8(c);
    // Fog and the texture environment mix in float before the conversion: the planes a * 0 + c give c at every pixel.
    if (key.fog != FogMode::Off || key.textureEnv != TextureEnv::Off) {
        for (int i = 0; i < 4; ++i) color[i] = {c[i], 0.0f, 0.0f};
    }
}

}  // namespace glrenderer
