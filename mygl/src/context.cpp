#include <cstring>
#include <stdexcept>
#include <string>

#include "context_state.h"

namespace mygl {
namespace {

void requireValidSize(int width, int height) {
    if (width < 1 || height < 1 || width > Context::kMaxSize || height > Context::kMaxSize) {
        throw std::invalid_argument("MyGL context size must be between 1 and " + std::to_string(Context::kMaxSize));
    }
}

}  // namespace

constinit thread_local Context* currentContext = nullptr;

void setError(Context::State& state, GLenum error) {
    if (state.error == GL_NO_ERROR) state.error = error;
}

Context::Context(int width, int height) {
    requireValidSize(width, height);
    state_ = std::make_unique<State>(width, height);
}

Context::~Context() {
    if (currentContext == this) currentContext = nullptr;
}

void Context::makeCurrent() {
    if (currentContext && currentContext != this) currentContext->state().pipeline.endBatch();
    currentContext = this;
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress))) {
        throw std::runtime_error("could not load the GL table from MyGL");
    }
}

Context* Context::current() { return currentContext; }

void Context::resize(int width, int height) {
    requireValidSize(width, height);
    drawCachedBitmaps(*state_);
    state_->pipeline.finish();
    state_->framebuffer.resize(width, height);
}

int Context::width() const { return state_->framebuffer.width(); }
int Context::height() const { return state_->framebuffer.height(); }

std::vector<std::uint8_t> Context::readPixels() {
    drawCachedBitmaps(*state_);
    state_->pipeline.finish();
    const auto color = state_->framebuffer.color();
    std::vector<std::uint8_t> bytes(color.size() * 4);
    std::memcpy(bytes.data(), color.data(), bytes.size());
    return bytes;
}

void Context::setMethods(const glrenderer::Methods& methods) { state_->pipeline.setMethods(methods); }

Stats Context::stats() {
    drawCachedBitmaps(*state_);
    state_->pipeline.finish();
    return state_->pipeline.stats();
}
void Context::resetStats() { state_->pipeline.resetStats(); }

}  // namespace mygl
