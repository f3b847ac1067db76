// glDrawPixels, glCopyPixels and glPixelZoom: images drawn at the current raster position
// through the fragment stage, as the reference draws them (a textured quad: see
// glrenderer::PixelImage).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include "compiled.h"
#include "pixel_unpack.h"
#include "pixel_values.h"
#include "textures.h"

namespace mygl {
namespace {

// The window pixel of the image's lower-left corner: the raster position rounded to nearest
// (halves away from zero). Nothing is drawn from beyond 2^29 pixels away.
bool imageCorner(const Context::State& s, int& x, int& y) {
    constexpr float kFarAway = 1 << 29;
    if (!(std::fabs(s.rasterPosition.x) < kFarAway && std::fabs(s.rasterPosition.y) < kFarAway)) return false;
    x = static_cast<int>(std::lround(s.rasterPosition.x));
    y = static_cast<int>(std::lround(s.rasterPosition.y));
    return true;
}

// The image's colours through the pixel transfer, as the reference's drawing program applies
// it. With GL_MAP_COLOR its blue and alpha lookup samples the image itself (the texture unit of
// the image, not of the maps: measured): blue takes the red and alpha the green of the image's
// texel at (floor(b * width), floor(a * height)), clamped, rows counted as its texture stores them.
std::vector<glm::vec4> transferredImage(const Context::State& s, int width, int height,
                                        const std::vector<glm::vec4>& colors, bool topRowFirst) {
    std::vector<glm::vec4> out(colors.size());
    std::transform(colors.begin(), colors.end(), out.begin(),
                   [&s](const glm::vec4& c) { return s.pixelModes.transferDrawnColor(c, s.pixelMaps); });
    if (!s.pixelModes.mapColor) return out;
    const auto texel = [](float c, int size) {
        return static_cast<int>(
            std::clamp(std::floor(c * static_cast<float>(size)), 0.0f, static_cast<float>(size - 1)));
    };
    for (glm::vec4& c : out) {
        const int column = texel(c.b, width), row = texel(c.a, height);
        const int storedRow = topRowFirst ? height - 1 - row : row;
        const glm::vec4& sampled = colors[static_cast<std::size_t>(storedRow) * static_cast<std::size_t>(width) +
                                          static_cast<std::size_t>(column)];
        c.b = sampled.r;
        c.a = sampled.g;
    }
    return out;
}

// Draws `image` (its size and colours or words set) at the raster position, zoomed.
void drawImage(Context::State& s, glrenderer::PixelImage image) {
    if (!s.rasterValid || s.renderMode != GL_RENDER || !imageCorner(s, image.x, image.y)) return;
    image.zoomX = s.pixelModes.zoomX;
    image.zoomY = s.pixelModes.zoomY;
    image.z = s.rasterPosition.z;
    updateTexturing(s);
    image.texCoord = s.texCoord;
    drawCachedBitmaps(s);
    endBatch(s);
    s.pipeline.drawPixels(*s.draw, image);
}

// Draws width x height colours (bottom row first) through the pixel transfer (unless they
// come from colour indices, which the reference's program draws without it).
void drawColors(Context::State& s, int width, int height, const std::vector<glm::vec4>& colors,
                bool topRowFirst = false, bool transfer = true) {
    glrenderer::PixelImage image;
    image.width = width;
    image.height = height;
    image.topRowFirst = topRowFirst;
    std::vector<glm::vec4> transferred;
    if (transfer && s.pixelModes.transfersColor())
        transferred = transferredImage(s, width, height, colors, topRowFirst);
    image.colors = transferred.empty() ? colors : transferred;
    drawImage(s, image);
}

// RGBA unsigned bytes with no transfer are the fragment colour words themselves: copied row by
// row, no colour conversion.
std::vector<std::uint32_t> rgbaWords(const void* pixels, int width, int height, const PixelStoreModes& modes) {
    const ClientLayout layout = clientLayout(width, GL_RGBA, GL_UNSIGNED_BYTE, modes);
    std::vector<std::uint32_t> words(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const auto* first = static_cast<const std::uint8_t*>(pixels) + layout.firstByte;
    for (std::size_t row = 0; row < static_cast<std::size_t>(height); ++row) {
        std::memcpy(words.data() + row * static_cast<std::size_t>(width), first + row * layout.rowStride,
                    static_cast<std::size_t>(width) * sizeof(std::uint32_t));
    }
    return words;
}

bool isValueFormat(GLenum format) {
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX || format == GL_DEPTH_COMPONENT;
}

// The GL errors of glDrawPixels' arguments (GL_NO_ERROR if it may draw).
GLenum drawPixelsError(GLsizei width, GLsizei height, GLenum format, GLenum type) {
    if (width < 0 || height < 0) return GL_INVALID_VALUE;
    if (!isPixelFormat(format) || !isPixelType(type)) return GL_INVALID_ENUM;
    const bool indexFormat = format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
    if (type == GL_BITMAP && !indexFormat) return GL_INVALID_ENUM;
    return GL_NO_ERROR;
}

// Draws width x height depth, stencil or index values (bottom row first, as extractValues
// keeps them; `values` is turned into the image's words in place).
void drawValues(Context::State& s, int width, int height, GLenum format, GLenum type,
                std::vector<std::uint32_t>& values) {
    if (format == GL_COLOR_INDEX) {
        std::vector<glm::vec4> colors(values.size());
        std::transform(values.begin(), values.end(), colors.begin(),
                       [&](std::uint32_t index) { return drawnIndexColor(index, type, s.pixelMaps); });
        return drawColors(s, width, height, colors, false, false);
    }
    glrenderer::PixelImage image;
    image.width = width;
    image.height = height;
    if (format == GL_DEPTH_COMPONENT) {
        for (std::uint32_t& v : values) v = drawnDepth24(v, type, s.pixelModes);
        image.use = glrenderer::TexelUse::Depth;
        image.color = s.rasterColor;
    } else {
        for (std::uint32_t& v : values) v = drawnStencil(v, type, s.pixelModes, s.pixelMaps);
        image.use = glrenderer::TexelUse::Stencil;
    }
    image.words = values;
    drawImage(s, image);
}

void drawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (const GLenum error = drawPixelsError(width, height, format, type)) return setError(*s, error);
    if (s->renderMode == GL_FEEDBACK) return writeFeedbackRasterPosition(*s, GL_DRAW_PIXEL_TOKEN);
    if (!pixels || width == 0 || height == 0 || !s->rasterValid || s->renderMode != GL_RENDER) return;
    if (isValueFormat(format)) {
        extractValues(pixels, width, height, type, s->unpack, s->pixelValues);
        return drawValues(*s, width, height, format, type, s->pixelValues);
    }
    if (format == GL_RGBA && type == GL_UNSIGNED_BYTE && !s->pixelModes.transfersColor()) {
        const std::vector<std::uint32_t> words = rgbaWords(pixels, width, height, s->unpack);
        glrenderer::PixelImage image;
        image.width = width;
        image.height = height;
        image.words = words;
        return drawImage(*s, image);
    }
    drawColors(*s, width, height, unpackDrawnImage(pixels, width, height, format, type, s->unpack));
}

// glDrawPixels compiled into a list: the image is unpacked under the unpack state of the
// moment (as the reference unpacks it when it compiles the call); an erroneous call is kept
// as it was, to report its error when the list runs.
CompiledCall keptDrawPixels(const Context::State& s, GLsizei width, GLsizei height, GLenum format, GLenum type,
                            const void* pixels) {
    if (drawPixelsError(width, height, format, type) != GL_NO_ERROR || !pixels) {
        return [=] { drawPixels(width, height, format, type, nullptr); };
    }
    if (isValueFormat(format)) {
        std::vector<std::uint32_t> kept;
        extractValues(pixels, width, height, type, s.unpack, kept);
        return [width, height, format, type, kept = std::move(kept)] {
            Context::State* state = stateOutsideBeginEnd();
            if (!state) return;
            if (state->renderMode == GL_FEEDBACK) return writeFeedbackRasterPosition(*state, GL_DRAW_PIXEL_TOKEN);
            if (!state->rasterValid || state->renderMode != GL_RENDER) return;
            state->pixelValues.assign(kept.begin(), kept.end());
            drawValues(*state, width, height, format, type, state->pixelValues);
        };
    }
    return [width, height, colors = unpackDrawnImage(pixels, width, height, format, type, s.unpack)] {
        Context::State* state = stateOutsideBeginEnd();
        if (!state) return;
        if (state->renderMode == GL_FEEDBACK) return writeFeedbackRasterPosition(*state, GL_DRAW_PIXEL_TOKEN);
        drawColors(*state, width, height, colors);
    };
}

// The window's colours in a rectangle, bottom row first; parts outside the window read as 0
// (the reference leaves them undefined: its new texture's zeros, measured).
std::vector<glm::vec4> windowColors(const glrenderer::Framebuffer& fb, GLint x, GLint y, GLsizei width,
                                    GLsizei height) {
    std::vector<glm::vec4> colors(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (std::int64_t row = 0; row < height; ++row) {
        const std::int64_t windowY = std::int64_t{y} + row;
        if (windowY < 0 || windowY >= fb.height()) continue;
        for (std::int64_t column = 0; column < width; ++column) {
            const std::int64_t windowX = std::int64_t{x} + column;
            if (windowX < 0 || windowX >= fb.width()) continue;
            const std::uint32_t word = fb.color()[static_cast<std::size_t>(windowY * fb.width() + windowX)];
            glm::vec4& c = colors[static_cast<std::size_t>(row * width + column)];
            for (int i = 0; i < 4; ++i) c[i] = static_cast<float>((word >> (8 * i)) & 0xFFu) * (1.0f / 255.0f);
        }
    }
    return colors;
}

// The part of [start, start + length) inside [0, limit): its first position and length.
struct Run {
    std::int64_t first, length;
};
Run insideWindow(std::int64_t start, std::int64_t length, int limit) {
    const std::int64_t first = std::max<std::int64_t>(start, 0), end = std::min<std::int64_t>(start + length, limit);
    return {first, std::max<std::int64_t>(end - first, 0)};
}

// The window's depth or stencil values in a rectangle, bottom row first, into `values`; parts
// outside the window read as 0 (as the reference's new texture, like colours).
void windowValues(std::span<const std::uint32_t> buffer, int fbWidth, int fbHeight, GLint x, GLint y, GLsizei width,
                  GLsizei height, std::vector<std::uint32_t>& values) {
    values.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0u);
    for (std::int64_t row = 0; row < height; ++row) {
        const std::int64_t windowY = std::int64_t{y} + row;
        if (windowY < 0 || windowY >= fbHeight) continue;
        for (std::int64_t column = 0; column < width; ++column) {
            const std::int64_t windowX = std::int64_t{x} + column;
            if (windowX < 0 || windowX >= fbWidth) continue;
            values[static_cast<std::size_t>(row * width + column)] =
                buffer[static_cast<std::size_t>(windowY * fbWidth + windowX)];
        }
    }
}

// Whether the reference copies colours with a blit: nothing would change them on the way, at
// zoom 1 (Mesa's blit_copy_pixels: the colour mask is not among its conditions, and a blit
// writes every channel). Depth and stencil copies never blit (llvmpipe cannot render into its
// depth-stencil format with a blit: measured, they draw).
bool blitsColors(const Context::State& s) {
    if (s.pixelModes.zoomX != 1.0f || s.pixelModes.zoomY != 1.0f) return false;
    const glrenderer::DrawState& d = *s.draw;
    const glrenderer::FragmentOps& ops = d.fragmentOps;
    const glrenderer::StencilState& stencil = ops.stencil;
    const bool stencilKeeps = !stencil.enabled || (stencil.fail == glrenderer::StencilOp::Keep &&
                                                   stencil.depthFail == glrenderer::StencilOp::Keep &&
                                                   stencil.depthPass == glrenderer::StencilOp::Keep);
    return !s.pixelModes.transfersColor() && !ops.blend && !ops.alphaTest &&
           (!ops.logicOpEnabled || ops.logicOp == glrenderer::LogicOp::Copy) &&
           (!d.depthTest || (d.depthFunc == glrenderer::CompareFunc::Always && !d.depthWrite)) &&
           d.fog.mode == glrenderer::FogMode::Off && stencilKeeps;
}

// The reference's blit of colours (no fragment operation but the scissor): the source and
// target cut to the window and the scissor box, when the cut rectangles do not overlap.
// Returns false when it would draw instead.
bool blitColors(Context::State& s, GLint x, GLint y, GLsizei width, GLsizei height, int targetX, int targetY) {
    auto& fb = s.framebuffer;
    // The source cut to the window, then the target (moving the source with it).
    Run columns = insideWindow(x, width, fb.width()), rows = insideWindow(y, height, fb.height());
    std::int64_t toX = targetX + (columns.first - x), toY = targetY + (rows.first - y);
    // The target is cut to the window, and to the scissor box when it is on.
    const auto targetRun = [](std::int64_t start, std::int64_t length, int limit, bool scissor, int boxStart,
                              int boxLength) {
        Run run = insideWindow(start, length, limit);
        if (!scissor) return run;
        const std::int64_t first = std::max<std::int64_t>(run.first, boxStart);
        const std::int64_t end = std::min<std::int64_t>(run.first + run.length, std::int64_t{boxStart} + boxLength);
        return Run{first, std::max<std::int64_t>(end - first, 0)};
    };
    const glrenderer::ScissorBox& box = s.draw->fragmentOps.scissor;
    const Run targetColumns = targetRun(toX, columns.length, fb.width(), box.enabled, box.x, box.width);
    const Run targetRows = targetRun(toY, rows.length, fb.height(), box.enabled, box.y, box.height);
    columns = {columns.first + (targetColumns.first - toX), targetColumns.length};
    rows = {rows.first + (targetRows.first - toY), targetRows.length};
    toX = targetColumns.first, toY = targetRows.first;
    const bool overlap = columns.first < toX + columns.length && toX < columns.first + columns.length &&
                         rows.first < toY + rows.length && toY < rows.first + rows.length;
    if (columns.length > 0 && rows.length > 0 && overlap) return false;
    for (std::int64_t row = 0; row < rows.length; ++row) {
        const auto from = fb.color().begin() + (rows.first + row) * fb.width() + columns.first;
        std::copy_n(from, columns.length, fb.color().begin() + (toY + row) * fb.width() + toX);
    }
    fb.markWritten();
    return true;
}

// glCopyPixels of depth or stencil drawn as the reference draws it: the values as a depth or
// stencil image (depths through its 24-bit texture), rows top first, no pixel transfer; depth
// images take the current colour (not the raster colour).
void drawCopiedValues(Context::State& s, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
    const glrenderer::Framebuffer& fb = s.framebuffer;
    const bool depth = type == GL_DEPTH;
    windowValues(depth ? fb.depth() : fb.stencil(), fb.width(), fb.height(), x, y, width, height, s.pixelValues);
    if (depth) std::transform(s.pixelValues.begin(), s.pixelValues.end(), s.pixelValues.begin(), resampledDepth24);
    glrenderer::PixelImage image;
    image.width = width;
    image.height = height;
    image.topRowFirst = true;
    image.use = depth ? glrenderer::TexelUse::Depth : glrenderer::TexelUse::Stencil;
    image.color = s.color;
    image.words = s.pixelValues;
    drawImage(s, image);
}

void copyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) return setError(*s, GL_INVALID_ENUM);
    if (s->renderMode == GL_FEEDBACK) return writeFeedbackRasterPosition(*s, GL_COPY_PIXEL_TOKEN);
    if (width == 0 || height == 0 || !s->rasterValid || s->renderMode != GL_RENDER) return;
    int targetX = 0, targetY = 0;
    if (!imageCorner(*s, targetX, targetY)) return;
    // A source wholly outside the window copies nothing.
    const auto& fb = s->framebuffer;
    if (insideWindow(x, width, fb.width()).length == 0 || insideWindow(y, height, fb.height()).length == 0) return;
    drawCachedBitmaps(*s);
    endBatch(*s);
    s->pipeline.finish();
    if (type == GL_COLOR && blitsColors(*s) && blitColors(*s, x, y, width, height, targetX, targetY)) return;
    // Else the reference draws the copy from a texture of the whole rectangle, which llvmpipe
    // cannot allocate beyond 1 GiB (LP_MAX_TEXTURE_SIZE): then it copies nothing.
    constexpr std::uint64_t kTextureBytesMax = std::uint64_t{1} << 30;
    if (std::uint64_t(width) * std::uint64_t(height) * 4 > kTextureBytesMax) return;
    // Read first, then draw: overlapping rectangles copy what was there before.
    if (type != GL_COLOR) return drawCopiedValues(*s, x, y, width, height, type);
    drawColors(*s, width, height, windowColors(fb, x, y, width, height), true);
}

void pixelZoom(GLfloat x, GLfloat y) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    s->pixelModes.zoomX = x;
    s->pixelModes.zoomY = y;
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glDrawPixels,
           +[](GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels) {
               Context::State* s = currentState();
               if (!s) return;
               if (s->lists.compiling()) {
                   s->lists.add(keptDrawPixels(*s, w, h, format, type, pixels));
                   if (!s->lists.executingWhileCompiling()) return;
               }
               drawPixels(w, h, format, type, pixels);
           }>(),
    listed<gl::glCopyPixels,
           +[](GLint x, GLint y, GLsizei w, GLsizei h, GLenum type) { copyPixels(x, y, w, h, type); }>(),
    listed<gl::glPixelZoom, +[](GLfloat x, GLfloat y) { pixelZoom(x, y); }>(),
};

}  // namespace

std::span<const EntryPoint> pixelRectangleEntryPoints() { return kEntryPoints; }

}  // namespace mygl
