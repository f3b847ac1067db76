#include "reference/osmesa_context.h"

// glad first: it defines GL's include guard, so the <GL/gl.h> that osmesa.h pulls in adds nothing.
#include <glad/gl.h>
#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace reference {

struct OsmesaContext::Handle {
    OSMesaContext context = nullptr;
};

OsmesaContext::OsmesaContext(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0) throw std::runtime_error("OSMesa context size must be positive");
    handle_ = new Handle;
    handle_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
    if (!handle_->context) {
        delete handle_;
        throw std::runtime_error("OSMesaCreateContextExt failed");
    }
    buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
}

OsmesaContext::~OsmesaContext() {
    OSMesaDestroyContext(handle_->context);
    delete handle_;
}

void OsmesaContext::makeCurrent() {
    if (!OSMesaMakeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
        throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
        throw std::runtime_error("could not load the GL table from OSMesa");
    }
}

void OsmesaContext::resize(int width, int height) {
    if (width <= 0 || height <= 0) throw std::runtime_error("OSMesa context size must be positive");
    width_ = width;
    height_ = height;
    buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
    if (!OSMesaMakeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
        throw std::runtime_error("OSMesaMakeCurrent failed");
    }
}

std::vector<std::uint8_t> OsmesaContext::readPixels() {
    // Reached through OSMesa itself so that the GL table keeps pointing where the caller left it.
    if (!OSMesaMakeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
        throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    const auto finish = reinterpret_cast<PFNGLFINISHPROC>(OSMesaGetProcAddress("glFinish"));
    finish();
    return buffer_;
}

ProcAddress OsmesaContext::getProcAddress(const char* name) {
    return reinterpret_cast<ProcAddress>(OSMesaGetProcAddress(name));
}

}  // namespace reference
