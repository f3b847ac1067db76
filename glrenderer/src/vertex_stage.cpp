#include "vertex_stage.h"

#include <xmmintrin.h>

#include "clip.h"
#include "cpu_features.h"
#include "fog.h"

namespace glrenderer {
namespace {

// The normal in eye space as the seeds computed it: by the modelview's upper 3x3.
glm::vec3 eyeNormal(const Matrix& m, const glm::vec3& n) {
    return {at(m, 0, 0) * n.x + at(m, 0, 1) * n.y + at(m, 0, 2) * n.z,
            at(m, 1, 0) * n.x + at(m, 1, 1) * n.y + at(m, 1, 2) * n.z,
            at(m, 2, 0) * n.x + at(m, 2, 1) * n.y + at(m, 2, 2) * n.z};
}

// transform() on the four rows at once: a column times a coordinate, summed left to right, each
// product and sum rounded, as there.
class ColumnTransform {
public:
    explicit ColumnTransform(const Matrix& m)
        : c0_(_mm_loadu_ps(&m[0])), c1_(_mm_loadu_ps(&m[4])), c2_(_mm_loadu_ps(&m[8])), c3_(_mm_loadu_ps(&m[12])) {}
    void apply(const glm::vec4& v, glm::vec4& out) const {
        __m128 r = _mm_add_ps(_mm_mul_ps(c0_, _mm_set1_ps(v.x)), _mm_mul_ps(c1_, _mm_set1_ps(v.y)));
        r = _mm_add_ps(r, _mm_mul_ps(c2_, _mm_set1_ps(v.z)));
        r = _mm_add_ps(r, _mm_mul_ps(c3_, _mm_set1_ps(v.w)));
        _mm_storeu_ps(&out.x, r);
    }

private:
    __m128 c0_, c1_, c2_, c3_;
};

}  // namespace

Batch VertexStage::toClipSpace(const SubmittedBatch& batch) {
    const std::size_t count = batch.vertices.size();
    clipVertices_.resize(count);
    const VertexTransform& t = batch.transform;
    const ColumnTransform modelviewProjection(t.modelviewProjection);
    for (std::size_t i = 0; i < count; ++i) {
        const Vertex& in = batch.vertices[i];
        ClipVertex& out = clipVertices_[i];
        modelviewProjection.apply(in.position, out.position);
        out.color = in.color;
        out.edgeFlag = in.edgeFlag;
    }
    if (batch.state.twoSidedColors) {
        for (std::size_t i = 0; i < count; ++i) clipVertices_[i].backColor = batch.vertices[i].backColor;
    }
    if (batch.state.fog.mode != FogMode::Off) {
        setFogCoordinates(batch.vertices, t.modelview, batch.state.fog.distance, clipVertices_);
    }
    if (batch.methods.needsEyeSpace()) {
        for (std::size_t i = 0; i < count; ++i) {
            clipVertices_[i].eye = glm::vec3(transform(t.modelview, batch.vertices[i].position));
            clipVertices_[i].normal = eyeNormal(t.modelview, batch.vertices[i].normal);
        }
    }
    return Batch{batch, clipVertices_};
}

std::uint8_t transformVertices(std::span<const ClipVertex> vertices, const ViewportTransform& viewport,
                               std::uint8_t* outcodes, WindowVertex* windowVertices) {
    if (cpuHasFma()) return transformVerticesFma(vertices, viewport, outcodes, windowVertices);
    std::uint8_t anyOutside = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        outcodes[i] = clipOutcode(vertices[i].position);
        anyOutside |= outcodes[i];
        windowVertices[i] = viewport.apply(vertices[i]);
    }
    return anyOutside;
}

}  // namespace glrenderer
