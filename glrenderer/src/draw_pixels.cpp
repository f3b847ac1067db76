// glDrawPixels as the reference draws it (Mesa's st_DrawPixels): a triangle fan over the zoomed
// image, its corners given in clip coordinates computed from window pixels, textured with the
// image (nearest texel, clamped, replacing the colour), through the same vertex stage, clipping
// and rasterization as any fan, so that coverage, the texel each pixel takes (a centre on a
// texel boundary falls by the planes' rounding) and depth come out as the reference's.
#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <optional>

#include "batch.h"
#include "batch_drawer.h"
#include "image_texturing.h"
#include "glrenderer/color_convert.h"
#include "glrenderer/pipeline.h"

namespace glrenderer {
namespace {

// The image as the texture the reference samples: its colours as fragment colour words, taken
// through `texturing` when there is one.
std::shared_ptr<const Texture> imageTexture(const PixelImage& image, const ImageTexturing* texturing) {
    auto texture = std::make_shared<Texture>();
    texture->levelCount = 1;
    texture->width[0] = static_cast<std::uint32_t>(image.width);
    texture->height[0] = static_cast<std::uint32_t>(image.height);
    texture->powerOfTwoWidth = std::has_single_bit(texture->width[0]);
    texture->powerOfTwoHeight = std::has_single_bit(texture->height[0]);
    if (image.colors.empty()) {
        texture->texels.assign(image.words.begin(), image.words.end());
    } else {
        texture->texels.resize(image.colors.size());
        std::transform(image.colors.begin(), image.colors.end(), texture->texels.begin(), fragmentRgba8);
    }
    if (texturing) {
        for (std::uint32_t& texel : texture->texels) texel = texturing->apply(texel);
    }
    if (image.topRowFirst) {
        const auto width = static_cast<std::ptrdiff_t>(image.width);
        for (std::ptrdiff_t low = 0, high = image.height - 1; low < high; ++low, --high) {
            std::swap_ranges(texture->texels.begin() + low * width, texture->texels.begin() + (low + 1) * width,
                             texture->texels.begin() + high * width);
        }
    }
    return texture;
}

// The reference's stencil image state (st_cb_drawpixels.c, draw_textured_quad): the stencil
// test always passes and replaces the value under the write mask, no depth test, no colour
// written; only the scissor of the draw's operations stays.
FragmentOps stencilImageOps(const FragmentOps& ops) {
    FragmentOps stencilOnly;
    stencilOnly.scissor = ops.scissor;
    stencilOnly.stencil.enabled = true;
    stencilOnly.stencil.func = CompareFunc::Always;
    stencilOnly.stencil.depthPass = StencilOp::Replace;
    stencilOnly.stencil.writeMask = ops.stencil.writeMask;
    stencilOnly.colorMask = 0;
    return stencilOnly;
}

// The state of the reference's quad: the draw's fragment operations (depth, fog, scissor,
// alpha, stencil, blending, logic op, masks) with the whole window as the viewport, depth range
// [0, 1], the image replacing the colour (or giving depths or stencil values: `use`), nothing
// culled or offset. `textured`: the image's colours have been through the draw's texturing and
// fog (ImageTexturing) already.
DrawState quadState(const DrawState& state, int width, int height, std::shared_ptr<const Texture> texture, TexelUse use,
                    bool textured) {
    DrawState quad;
    quad.shadeModel = ShadeModel::Flat;
    quad.viewport = {0, 0, width, height};
    if (use == TexelUse::Stencil) {
        quad.fragmentOps = stencilImageOps(state.fragmentOps);
    } else {
        quad.depthTest = state.depthTest;
        quad.depthFunc = state.depthFunc;
        quad.depthWrite = state.depthWrite;
        quad.fragmentOps = state.fragmentOps;  // scissor, alpha test, stencil, blending, logic op, masks
        if (use == TexelUse::Color && !textured) quad.fog = state.fog;
    }
    quad.texture.use = use;
    quad.texture.env = TextureEnv::Replace;
    quad.texture.base = TextureBase::Rgba;
    quad.texture.wrapS = quad.texture.wrapT = TextureWrap::ClampToEdge;
    quad.texture.texture = std::move(texture);
    return quad;
}

// Clip coordinates pass unchanged; the eye coordinates are all zero, so that the fog
// coordinate is 0 as the reference's quad's (it carries none).
constexpr VertexTransform kQuadTransform{kIdentity, Matrix{}};

}  // namespace

void Pipeline::drawPixels(const DrawState& state, const PixelImage& image) {
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    if (image.width <= 0 || image.height <= 0 || (image.colors.size() != pixels && image.words.size() != pixels))
        return;
    const float left = static_cast<float>(image.x), bottom = static_cast<float>(image.y);
    const float right = left + static_cast<float>(image.width) * image.zoomX;
    const float top = bottom + static_cast<float>(image.height) * image.zoomY;
    if (!std::isfinite(right) || !std::isfinite(top)) return;
    const Framebuffer& fb = drawer_->framebuffer();
    const float width = static_cast<float>(fb.width()), height = static_cast<float>(fb.height());
    const auto clipX = [width](float x) { return x / width * 2.0f - 1.0f; };
    const auto clipY = [height](float y) { return y / height * 2.0f - 1.0f; };
    const float z = image.z * 2.0f - 1.0f;
    // The reference's lower left, lower right, upper right and upper left, y down (its lower
    // left is the image's top-left corner), with the image's coordinates.
    const float tTop = image.topRowFirst ? 0.0f : 1.0f, tBottom = 1.0f - tTop;
    const float corners[4][4] = {{clipX(left), clipY(top), 0.0f, tTop},
                                 {clipX(right), clipY(top), 1.0f, tTop},
                                 {clipX(right), clipY(bottom), 1.0f, tBottom},
                                 {clipX(left), clipY(bottom), 0.0f, tBottom}};
    Vertex vertices[4];
    for (int i = 0; i < 4; ++i) {
        vertices[i].position = {corners[i][0], corners[i][1], z, 1.0f};
        vertices[i].color = image.color;
        vertices[i].texCoord = {corners[i][2], corners[i][3], 0.0f, 1.0f};
    }
    // Drawn as a batch of its own between the program's, which keep their matrices, lighting
    // and counts (the quad is no primitive of the program's).
    endBatch();
    const VertexTransform transform = batch_->transform;
    const auto* lighting = batch_->lighting;
    const Stats counted = submitted_;
    setTransform(kQuadTransform);
    setUnlit();
    std::optional<ImageTexturing> texturing;
    if (image.use == TexelUse::Color && state.texture.env != TextureEnv::Off) texturing.emplace(state, image.texCoord);
    submit(intern(quadState(state, fb.width(), fb.height(), imageTexture(image, texturing ? &*texturing : nullptr),
                            image.use, texturing.has_value())),
           PrimitiveMode::TriangleFan, vertices);
    endBatch();
    setTransform(transform);
    batch_->lighting = lighting;
    submitted_ = counted;
}

}  // namespace glrenderer
