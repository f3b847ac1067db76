#pragma once
// The fuzzer's calls whose pointer is an image (glTexImage*, glTexSubImage*, glDrawPixels,
// glBitmap, glPolygonStipple read one; glReadPixels, glGetTexImage write one). Their sizes
// follow the backend's own pixel-store state, queried before the call, so that each buffer holds
// exactly the bytes GL may read or write (AddressSanitizer sees any access beyond).
#include <string>
#include <vector>

#include "gl_call.h"

namespace fuzz {

struct ImageFunction {
    std::string_view name;
    std::size_t argumentCount;
    void (*run)(const Call&, std::uint32_t index, int width, int height, Answers& answers);
    std::string (*print)(const Call&);
};

// The image functions. An image read by GL has its bytes made from a seed, its call's last
// argument: an even seed gives floats in [0, 1] for GL_FLOAT images, an odd one any bytes
// (NaN, Inf, huge floats); other types take any bytes.
const std::vector<ImageFunction>& imageFunctions();

}  // namespace fuzz
