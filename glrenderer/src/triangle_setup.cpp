#include "triangle_setup.h"

namespace glrenderer {

PlaneBuilder::PlaneBuilder(const WindowVertex& v0, const WindowVertex& v1, const WindowVertex& v2)
    : dx01_(v0.x - v1.x), dy01_(v0.y - v1.y), dx20_(v2.x - v0.x), dy20_(v2.y - v0.y),
      oneOverArea_(1.0f / (dx01_ * dy20_ - dy01_ * dx20_)),
      x0Center_(v0.x - 0.5f), y0Center_(v0.y - 0.5f) {}

AttributePlane PlaneBuilder::plane(float a0, float a1, float a2) const {
    const float da01 = a0 - a1;
    const float da20 = a2 - a0;
    AttributePlane p;
    p.dadx = da01 * (dy20_ * oneOverArea_) - da20 * (dy01_ * oneOverArea_);
    p.dady = da20 * (dx01_ * oneOverArea_) - da01 * (dx20_ * oneOverArea_);
    p.a0 = a0 - (p.dadx * x0Center_ + p.dady * y0Center_);
    return p;
}

}  // namespace glrenderer
