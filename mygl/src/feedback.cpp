// GL_FEEDBACK: glFeedbackBuffer, glPassThrough, and the tokens written for what the pipeline
// hands back (points, lines, triangles after clipping and culling) and for glBitmap, as the
// reference writes them (docs/reference-rules.md, "Feedback").
#include "compiled.h"

namespace mygl {
namespace {

using glrenderer::FeedbackPrimitive;

// What a vertex carries in each feedback type.
struct VertexLayout {
    bool z = false, w = false, color = false, texture = false;
};

std::optional<VertexLayout> layoutOf(GLenum type) {
    switch (type) {
    case GL_2D: return VertexLayout{};
    case GL_3D: return VertexLayout{true};
    case GL_3D_COLOR: return VertexLayout{true, false, true};
    case GL_3D_COLOR_TEXTURE: return VertexLayout{true, false, true, true};
    case GL_4D_COLOR_TEXTURE: return VertexLayout{true, true, true, true};
    default: return std::nullopt;
    }
}

void writeVertex(Feedback& f, const glm::vec4& window, const glm::vec4& color, const glm::vec4& texture) {
    const VertexLayout layout = *layoutOf(f.type);
    f.write(window.x);
    f.write(window.y);
    if (layout.z) f.write(window.z);
    if (layout.w) f.write(window.w);
    if (layout.color) {
        for (int i = 0; i < 4; ++i) f.write(color[i]);
    }
    if (layout.texture) {
        for (int i = 0; i < 4; ++i) f.write(texture[i]);
    }
}

GLfloat token(GLenum value) { return static_cast<GLfloat>(value); }

void feedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    Feedback& f = s->feedback;
    if (s->renderMode == GL_FEEDBACK) return setError(*s, GL_INVALID_OPERATION);
    if (size < 0) return setError(*s, GL_INVALID_VALUE);
    if (!buffer && size > 0) {
        f.size = 0;
        return setError(*s, GL_INVALID_VALUE);
    }
    if (!layoutOf(type)) return setError(*s, GL_INVALID_ENUM);
    f = {buffer, size, type, 0};
}

void passThrough(GLfloat value) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || s->renderMode != GL_FEEDBACK) return;
    writeFeedbackPrimitives(*s);
    s->feedback.write(token(GL_PASS_THROUGH_TOKEN));
    s->feedback.write(value);
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glFeedbackBuffer,
           +[](GLsizei size, GLenum type, GLfloat* buffer) { feedbackBuffer(size, type, buffer); }>(),
    listed<gl::glPassThrough, +[](GLfloat value) { passThrough(value); }>(),
};

}  // namespace

// The primitive's texture coordinates are the current ones: the reference's vertex program
// writes none without texturing, and its feedback stage falls back on the current value.
void writeFeedbackPrimitives(Context::State& s) {
    Feedback& f = s.feedback;
    for (const FeedbackPrimitive& p : s.pipeline.takeFeedback()) {
        switch (p.kind) {
        case FeedbackPrimitive::Kind::Point: f.write(token(GL_POINT_TOKEN)); break;
        case FeedbackPrimitive::Kind::Line: f.write(token(GL_LINE_TOKEN)); break;
        case FeedbackPrimitive::Kind::LineReset: f.write(token(GL_LINE_RESET_TOKEN)); break;
        case FeedbackPrimitive::Kind::Polygon:
            f.write(token(GL_POLYGON_TOKEN));
            f.write(3.0f);
            break;
        }
        for (int i = 0; i < p.vertexCount(); ++i) {
            const glrenderer::FeedbackVertex& v = p.vertices[static_cast<std::size_t>(i)];
            writeVertex(f, {v.x, v.y, v.z, v.w}, v.color, s.texCoord);
        }
    }
}

void writeFeedbackRasterPosition(Context::State& s, GLenum rasterToken) {
    writeFeedbackPrimitives(s);
    if (!s.rasterValid) return;
    s.feedback.write(token(rasterToken));
    writeVertex(s.feedback, s.rasterPosition, s.rasterColor, s.rasterTexCoord);
}

GLint endFeedback(Context::State& s) {
    writeFeedbackPrimitives(s);
    Feedback& f = s.feedback;
    const GLint result = f.count > static_cast<std::size_t>(f.size) ? -1 : static_cast<GLint>(f.count);
    f.count = 0;
    return result;
}

std::span<const EntryPoint> feedbackEntryPoints() { return kEntryPoints; }

}  // namespace mygl
