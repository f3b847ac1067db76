#pragma once
#include <cstdint>
#include <initializer_list>
#include <vector>

#include <glrenderer/pipeline.h>

namespace testing_support {

// Draws straight into a glrenderer::Pipeline with positions given in window pixels (GL, y up):
// the viewport covers the framebuffer and clip space equals normalized device coordinates.
class PipelineFixture {
public:
    PipelineFixture(int width, int height) : framebuffer(width, height), pipeline(framebuffer) {
        state.viewport = {0, 0, width, height};
    }

    glrenderer::Vertex windowVertex(float x, float y, float z = 0.0f, glm::vec4 color = {1, 1, 1, 1}) const {
        const float w = static_cast<float>(framebuffer.width());
        const float h = static_cast<float>(framebuffer.height());
        return {{x / w * 2.0f - 1.0f, y / h * 2.0f - 1.0f, z, 1.0f}, color};
    }

    void draw(glrenderer::PrimitiveMode mode, std::vector<glrenderer::Vertex> vertices) {
        pipeline.submit(pipeline.intern(state), mode, vertices);
        pipeline.finish();
    }

    // Pixels whose color is not the cleared black.
    int coveredPixels() const {
        int count = 0;
        for (std::uint32_t c : framebuffer.color()) count += c != 0 ? 1 : 0;
        return count;
    }
    std::uint32_t pixel(int x, int y) const {
        return framebuffer.color()[static_cast<std::size_t>(y * framebuffer.width() + x)];
    }

    glrenderer::Framebuffer framebuffer;
    glrenderer::Pipeline pipeline;
    glrenderer::DrawState state;
};

}  // namespace testing_support
