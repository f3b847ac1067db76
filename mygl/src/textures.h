#pragma once
// Texturing on the GL side: texture objects and images (textures.cpp), their parameters, the
// texture environment and queries (texture_parameters.cpp).
#include <optional>
#include <span>
#include <vector>

#include "entry_points.h"

namespace mygl {

// The object bound to `target` (a texture or proxy target, checked by the caller).
TextureObject& boundTexture(TextureUnit& unit, GLenum target);
const TextureObject& boundTexture(const TextureUnit& unit, GLenum target);

// Forms the pipeline's texture state (State::draw.texture) from the unit's: before each draw.
void updateTexturing(Context::State& state);

// glEnable/glDisable/glIsEnabled of GL_TEXTURE_1D and GL_TEXTURE_2D (false or nullopt for others).
bool setTextureCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> textureCapability(const Context::State& state, GLenum cap);
// glGet's values of the texture state (bindings, sizes), or nullopt for other names.
std::optional<std::vector<double>> textureQuery(const Context::State& state, GLenum name);

// The same for GL_TEXTURE_GEN_S/T/R/Q (texture_gen.cpp).
bool setTexGenCapability(Context::State& state, GLenum cap, bool enabled);
std::optional<bool> texGenCapability(const Context::State& state, GLenum cap);

}  // namespace mygl
