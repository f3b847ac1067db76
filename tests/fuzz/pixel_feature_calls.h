#pragma once
// The fuzzer's texture, per-fragment, stipple, pixel-rectangle and accumulation calls, made
// between episodes from a random source of their own, so that the rest of each seed's stream is
// what it was before they existed.
#include <cstdint>
#include <functional>

#include <glad/gl.h>

#include "gl_call.h"
#include "random_source.h"

namespace fuzz {

class PixelFeatureCalls {
public:
    // `badness`: the rate of bad values; `invalidEnumRate`: of invalid enums (the stream's own).
    PixelFeatureCalls(std::uint64_t seed, int width, int height, double badness, double invalidEnumRate)
        : random_(seed ^ 0x7E27u),
          indexImages_(seed ^ 0x1DE7u),
          width_(width),
          height_(height),
          badness_(badness),
          invalidEnumRate_(invalidEnumRate) {}

    // Now and then a group of calls, each given to `emit`.
    void between(const std::function<void(Call)>& emit);

private:
    void textureCalls();
    void textureImageCall();
    void textureParameterCalls();
    void textureCoordinateCalls();
    void copyTextureCall();
    void textureQuery();
    void fragmentCalls();
    void stippleCalls();
    void pixelCalls();
    void pixelStateCall();
    void rasterPosition();
    void accumCalls();
    void stateQuery();

    void emit(std::string_view name, std::vector<double> args = {});
    GLenum oneOf(std::initializer_list<GLenum> valid);
    double typed(std::string_view type, double value);
    double size(std::int64_t largest);
    double dataSeed();
    void enableOrDisable(GLenum cap, double enableRate = 0.6);
    std::pair<GLenum, GLenum> imageFormatType(bool texture);

    RandomSource random_;
    RandomSource indexImages_;  // which texture images are colour-index ones (its own, so the rest stays as it was)
    int width_, height_;
    double badness_, invalidEnumRate_;
    const std::function<void(Call)>* emit_ = nullptr;
};

}  // namespace fuzz
