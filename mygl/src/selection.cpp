// Selection (GL_SELECT, for picking): glRenderMode, glSelectBuffer and the name stack. What a
// draw hits comes from the pipeline (DrawState::selection); a hit record is written whenever
// the name stack changes or selection ends, as the reference writes it. (glRenderMode also
// enters and leaves GL_FEEDBACK: feedback.cpp writes its tokens.)
#include <cstdint>

#include "compiled.h"

namespace mygl {
namespace {

// A window depth in [0, 1] as the reference stores it: multiplied by (float)0xFFFFFFFF, which is
// 2^32, and converted through a 64-bit integer, so that a depth of 1 wraps to 0.
GLuint hitDepth(float z) {
    const float scaled = z * 4294967296.0f;
    if (!(scaled >= 0.0f && scaled <= 4294967296.0f)) return 0;
    return static_cast<GLuint>(static_cast<std::int64_t>(scaled));
}

// Writes a hit record of what was hit since the last one (draws and raster positions), if
// anything was, under the current names.
void writeHitRecord(Context::State& s) {
    glrenderer::HitRange range = s.pipeline.takeHits();
    range.add(s.selection.rasterHits);
    s.selection.rasterHits = {};
    if (!range.hit) return;
    Selection& sel = s.selection;
    sel.write(static_cast<GLuint>(sel.names.size()));
    sel.write(hitDepth(range.minZ));
    sel.write(hitDepth(range.maxZ));
    for (GLuint name : sel.names) sel.write(name);
    ++sel.hits;
}

// The name stack calls: ignored outside GL_SELECT; otherwise `change` runs after the record of
// what was hit under the old names (unless it reports an error first: it returns false).
template <class Check, class Change>
void changeNames(Check&& check, Change&& change) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s || s->renderMode != GL_SELECT) return;
    if (!check(*s)) return;
    writeHitRecord(*s);
    change(s->selection.names);
}

// As the reference: selection or feedback ends (its records written, its counts reset) before
// the new mode is checked, and a mode without a buffer is entered with GL_INVALID_OPERATION.
GLint renderMode(GLenum mode) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return 0;
    GLint result = 0;
    if (s->renderMode == GL_SELECT) {
        writeHitRecord(*s);
        Selection& sel = s->selection;
        result = sel.count > static_cast<std::size_t>(sel.size) ? -1 : sel.hits;
        sel.count = 0;
        sel.hits = 0;
        sel.names.clear();
    }
    if (s->renderMode == GL_FEEDBACK) result = endFeedback(*s);
    if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
        setError(*s, GL_INVALID_ENUM);
        return 0;
    }
    if ((mode == GL_SELECT && s->selection.size == 0) || (mode == GL_FEEDBACK && s->feedback.size == 0))
        setError(*s, GL_INVALID_OPERATION);
    if (mode != s->renderMode) endBatch(*s);
    s->renderMode = mode;
    s->draw.edit().selection = mode == GL_SELECT;
    s->draw.edit().feedback = mode == GL_FEEDBACK;
    return result;
}

void selectBuffer(GLsizei size, GLuint* buffer) {
    Context::State* s = stateOutsideBeginEnd();
    if (!s) return;
    if (size < 0) return setError(*s, GL_INVALID_VALUE);
    if (s->renderMode == GL_SELECT) return setError(*s, GL_INVALID_OPERATION);
    s->selection.buffer = buffer;
    s->selection.size = size;
    s->selection.count = 0;
}

bool always(Context::State&) { return true; }

// Records `error` if `fails`; returns whether the call goes on.
bool unless(Context::State& s, bool fails, GLenum error) {
    if (fails) setError(s, error);
    return !fails;
}

const EntryPoint kEntryPoints[] = {
    listed<gl::glRenderMode, +[](GLenum mode) -> GLint { return renderMode(mode); }>(),
    listed<gl::glSelectBuffer, +[](GLsizei size, GLuint* buffer) { selectBuffer(size, buffer); }>(),
    listed<gl::glInitNames, +[] { changeNames(always, [](std::vector<GLuint>& names) { names.clear(); }); }>(),
    listed<gl::glLoadName,
           +[](GLuint name) {
               changeNames([](Context::State& s) { return unless(s, s.selection.names.empty(), GL_INVALID_OPERATION); },
                           [name](std::vector<GLuint>& names) { names.back() = name; });
           }>(),
    listed<gl::glPushName,
           +[](GLuint name) {
               changeNames(
                   [](Context::State& s) {
                       return unless(s, s.selection.names.size() >= Selection::kMaxNameStackDepth, GL_STACK_OVERFLOW);
                   },
                   [name](std::vector<GLuint>& names) { names.push_back(name); });
           }>(),
    listed<gl::glPopName,
           +[] {
               changeNames([](Context::State& s) { return unless(s, s.selection.names.empty(), GL_STACK_UNDERFLOW); },
                           [](std::vector<GLuint>& names) { names.pop_back(); });
           }>(),
};

}  // namespace

std::span<const EntryPoint> selectionEntryPoints() { return kEntryPoints; }

}  // namespace mygl
