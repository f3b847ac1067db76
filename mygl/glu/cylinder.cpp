// gluCylinder: around the z axis from z = 0 (radius `base`) to z = height (radius `top`), slices
// around (x = r sin(angle), y = r cos(angle)) and stacks along z, as GLU builds it: FILL is one quad
// strip per stack; LINE draws every circle and the vertical lines, SILHOUETTE the two end circles
// and the vertical lines, POINT the vertices. Lines and points carry smooth normals.
#include <algorithm>
#include <cmath>

#include "quadric.h"

namespace {

using mygl::glu::AngleTable;
using mygl::glu::fraction;
using mygl::glu::QuadricAttributes;

class CylinderGrid {
public:
    CylinderGrid(const GLUquadric& quadric, double base, double top, double height, int slices, int stacks)
        : attributes_(quadric),
          flat_(quadric.normals == GLU_FLAT),
          slices_(slices),
          stacks_(stacks),
          base_(static_cast<float>(base)),
          deltaRadius_(static_cast<float>(base - top)),
          height_(static_cast<float>(height)),
          angle_(slices, 0.0, 2.0 * M_PI / slices, true),
          facetAngle_(slices, -M_PI / slices, 2.0 * M_PI / slices, true) {
        // The surface normal leans along z by the slope of the side.
        const double length = std::hypot(base - top, height);
        normalZ_ = static_cast<float>((base - top) / length);
        normalXY_ = static_cast<float>(height / length);
    }

    // Vertex (slice i, ring j); GLU_FLAT gives it the normal of the facet between slices i-1 and i.
    void vertex(int i, int j) const {
        const AngleTable& normalAngle = flat_ ? facetAngle_ : angle_;
        attributes_.normal(normalXY_ * normalAngle.sin[i], normalXY_ * normalAngle.cos[i], normalZ_);
        const float t = fraction(j, stacks_);
        attributes_.texCoord(1.0f - fraction(i, slices_), t);
        const float radius = base_ - deltaRadius_ * t;
        glVertex3f(radius * angle_.sin[i], radius * angle_.cos[i], height_ * t);
    }

    void fill(bool inside) const {
        for (int j = 0; j < stacks_; ++j) {
            glBegin(GL_QUAD_STRIP);
            for (int i = 0; i <= slices_; ++i) {
                vertex(i, inside ? j + 1 : j);
                vertex(i, inside ? j : j + 1);
            }
            glEnd();
        }
    }

    // The circles at rings 0, step, 2 step, ... up to the top, then the vertical lines.
    void lines(int step) const {
        mygl::glu::gridLines(slices_, stacks_, 0, stacks_, step, [this](int i, int j) { vertex(i, j); });
    }

    void points() const {
        mygl::glu::gridPoints(slices_, stacks_, [this](int i, int j) { vertex(i, j); });
    }

private:
    QuadricAttributes attributes_;
    bool flat_;
    int slices_, stacks_;
    float base_, deltaRadius_, height_, normalZ_ = 0.0f, normalXY_ = 0.0f;
    AngleTable angle_, facetAngle_;
};

}  // namespace

extern "C" void gluCylinder(GLUquadric* quad, GLdouble base, GLdouble top, GLdouble height, GLint slices,
                            GLint stacks) {
    if (!quad) return;
    slices = std::min(slices, mygl::glu::kMaxQuadricDivisions);
    const bool finite = std::isfinite(base) && std::isfinite(top) && std::isfinite(height);
    if (slices < 2 || stacks < 1 || !finite || base < 0.0 || top < 0.0 || height < 0.0 ||
        std::hypot(base - top, height) == 0.0) {
        mygl::glu::quadricError(*quad, GLU_INVALID_VALUE);
        return;
    }
    const CylinderGrid grid(*quad, base, top, height, slices, stacks);
    switch (quad->drawStyle) {
    case GLU_FILL: grid.fill(quad->orientation == GLU_INSIDE); break;
    case GLU_LINE: grid.lines(1); break;
    case GLU_SILHOUETTE: grid.lines(stacks); break;
    default: grid.points(); break;
    }
}
