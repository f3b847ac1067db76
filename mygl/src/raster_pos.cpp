// glRasterPos and glBitmap: the current raster position and the bitmaps drawn at it, computed
// as the reference's fixed-function path computes them (Mesa's rastpos.c and _mesa_Bitmap).
#include <array>
#include <algorithm>
#include <cmath>

#include "compiled.h"
#include "textures.h"
#include "vertex_input.h"

namespace mygl {
namespace {

// Whether a clip-space point is inside the view volume, boundaries included. Asked as the
// reference asks, "is it outside?", so that a NaN coordinate counts as inside.
bool insideViewVolume(const glm::vec4& clip) {
    return !(clip.z < -clip.w || clip.z > clip.w || clip.x < -clip.w || clip.x > clip.w || clip.y < -clip.w ||
             clip.y > clip.w);
}

// Whether a clip-space point is on the inner side of every enabled user clip plane (their
// clip-space equations): the reference's draw module culls the raster position's point when a
// distance is below 0, so a NaN distance keeps it.
bool insideClipPlanes(const glrenderer::UserClipPlanes& planes, const glm::vec4& clip) {
    for (std::size_t i = 0; i < planes.planes.size(); ++i) {
        if (!(planes.enabled >> i & 1u)) continue;
        const glm::vec4& p = planes.planes[i];
        if (clip.x * p.x + clip.y * p.y + clip.z * p.z + clip.w * p.w < 0.0f) return false;
    }
    return true;
}

// The reference transforms by the modelview, then the projection (two steps, not their
// product), divides, and maps to the viewport in float; an invalid position leaves every
// raster value as it was.
void rasterPos(const glm::vec4& object) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    const glm::vec4 eye = transform(s->modelview.top().matrix(), object);
    const glm::vec4 clip = transform(s->projection.top().matrix(), eye);
    if (s->clipPlanesStale) {
        s->clipPlanesStale = false;
        updateClipPlanes(*s);
    }
    s->rasterValid = insideViewVolume(clip) && insideClipPlanes(s->draw->clipPlanes, clip);
    if (!s->rasterValid) return;
    const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
    const auto& v = s->draw->viewport;
    const float halfWidth = static_cast<float>(v.width) * 0.5f, halfHeight = static_cast<float>(v.height) * 0.5f;
    s->rasterPosition = {clip.x * d * halfWidth + (halfWidth + static_cast<float>(v.x)),
                         clip.y * d * halfHeight + (halfHeight + static_cast<float>(v.y)),
                         clip.z * d * s->draw->depthScale() + s->draw->depthTranslate(), clip.w};
    s->rasterDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
    s->rasterColor = s->color;
    if (s->lightingEnabled) {  // lit by the same vertex program as a vertex (the draw module's)
        glrenderer::Vertex lit;
        lit.position = object, lit.normal = s->normal, lit.color = s->color;
        lightVertex(*s, lit, nullptr);
        s->rasterColor = lit.color;
    }
    s->rasterTexCoord = transform(s->texture.top().matrix(), s->texCoord);
    if (s->renderMode == GL_SELECT) s->selection.rasterHits.add(s->rasterPosition.z);
}

template <class T>
void rasterPosv(const T* v, int n) {
    if (!v) return;
    rasterPos({static_cast<float>(v[0]), static_cast<float>(v[1]), n > 2 ? static_cast<float>(v[2]) : 0.0f,
               n > 3 ? static_cast<float>(v[3]) : 1.0f});
}

// Bytes from one row of a bitmap to the next under the unpack alignment.
std::size_t bitmapRowStride(GLsizei width, int alignment) {
    const std::size_t bytes = (static_cast<std::size_t>(width) + 7) / 8;
    const std::size_t a = static_cast<std::size_t>(alignment);
    return (bytes + a - 1) / a * a;
}

// The texture coordinates the reference's bitmap fragments take (BitmapTexCoords).
glrenderer::BitmapTexCoords bitmapTexCoords(const Context::State& s) {
    const glrenderer::TextureState& texture = s.draw->texture;
    return {!texture.identityMatrix || texture.gen.enabled != 0 || s.pipeline.drawsTexCoords(), s.texCoord};
}

// `stride`: bytes from one row to the next (the unpack alignment's when the program calls it,
// 1-aligned rows when a display list replays it).
void bitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
            const GLubyte* bits, std::size_t stride) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (width < 0 || height < 0) return setError(*s, GL_INVALID_VALUE);
    if (s->renderMode == GL_FEEDBACK) writeFeedbackRasterPosition(*s, GL_BITMAP_TOKEN);
    if (!s->rasterValid) return;
    // Beyond 2^29 pixels away nothing can be on screen (and position - origin must fit an int).
    constexpr float kFarAway = 1 << 29;
    const bool nearWindow = std::fabs(s->rasterPosition.x) < kFarAway && std::fabs(s->rasterPosition.y) < kFarAway &&
                            std::fabs(xorig) < kFarAway && std::fabs(yorig) < kFarAway;
    if (width > 0 && height > 0 && bits && nearWindow && s->renderMode == GL_RENDER) {
        // The reference truncates position - origin after adding 1e-4 (SGI's rule, for
        // conformance): a raster position a hair below an integer still lands on it.
        constexpr float kEpsilon = 0.0001f;
        const int x = static_cast<int>(std::floor(s->rasterPosition.x + kEpsilon - xorig));
        const int y = static_cast<int>(std::floor(s->rasterPosition.y + kEpsilon - yorig));
        const float z = s->rasterPosition.z;
        updateTexturing(*s);
        s->bitmapCache.setDrawState(*s->draw, bitmapTexCoords(*s));
        if (BitmapCache::cacheable(width, height)) {
            if (!s->bitmapCache.accepts(x, y, width, height, s->rasterColor, z)) drawCachedBitmaps(*s);
            s->bitmapCache.add(x, y, width, height, bits, stride, s->rasterColor, z);
        } else {  // drawn at once, while the cache stays pending (as the reference does)
            glrenderer::Bitmap b;
            b.x = x;
            b.y = y;
            b.width = width;
            b.height = height;
            b.rows = {bits, stride * static_cast<std::size_t>(height)};
            b.rowStride = stride;
            b.color = s->rasterColor;
            b.z = z;
            b.texCoords = bitmapTexCoords(*s);
            endBatch(*s);
            s->pipeline.drawBitmap(*s->draw, b);
        }
    }
    s->rasterPosition.x += xmove;
    s->rasterPosition.y += ymove;
}

// glBitmap compiled into a list: its rows are copied under the unpack state of the moment (as
// the reference unpacks them when it compiles the call), 1-aligned.
CompiledCall keptBitmap(const Context::State& s, GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym,
                        const GLubyte* bits) {
    std::vector<GLubyte> rows;
    const std::size_t packed = w > 0 ? bitmapRowStride(w, 1) : 0;
    if (bits && w > 0 && h > 0) {
        const std::size_t stride = bitmapRowStride(w, s.unpack.alignment);
        rows.resize(packed * static_cast<std::size_t>(h));
        for (std::size_t row = 0; row < static_cast<std::size_t>(h); ++row) {
            std::copy_n(bits + row * stride, packed, rows.begin() + static_cast<std::ptrdiff_t>(row * packed));
        }
    }
    return [=, rows = std::move(rows)] { bitmap(w, h, xo, yo, xm, ym, rows.empty() ? nullptr : rows.data(), packed); };
}

const EntryPoint kEntryPoints[] = {
    MYGL_POSITION_ENTRIES(glRasterPos, s, GLshort, rasterPosv),
    MYGL_POSITION_ENTRIES(glRasterPos, i, GLint, rasterPosv),
    MYGL_POSITION_ENTRIES(glRasterPos, f, GLfloat, rasterPosv),
    MYGL_POSITION_ENTRIES(glRasterPos, d, GLdouble, rasterPosv),
    listed<gl::glBitmap,
           +[](GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym, const GLubyte* bits) {
               Context::State* s = currentState();
               if (!s) return;
               if (s->lists.compiling()) {
                   s->lists.add(keptBitmap(*s, w, h, xo, yo, xm, ym, bits));
                   if (!s->lists.executingWhileCompiling()) return;
               }
               bitmap(w, h, xo, yo, xm, ym, bits, w > 0 ? bitmapRowStride(w, s->unpack.alignment) : 0);
           }>(),
};

}  // namespace

void drawCachedBitmaps(Context::State& state) {
    if (state.bitmapCache.empty()) return;
    endBatch(state);
    state.pipeline.drawBitmap(state.bitmapCache.drawState(), state.bitmapCache.bitmap());
    state.bitmapCache.clear();
}

std::span<const EntryPoint> rasterPosEntryPoints() { return kEntryPoints; }

}  // namespace mygl
