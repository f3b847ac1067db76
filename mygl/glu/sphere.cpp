// gluSphere: centred on the origin, slices around the z axis (x = r sin(azimuth),
// y = r cos(azimuth)), stacks from +z (stack 0) to -z, as GLU builds it. FILL draws the caps as
// triangle fans and the rest as quad strips; with texture coordinates every stack is a quad strip
// (a pole needs one texture coordinate per slice). LINE and SILHOUETTE draw the latitude circles
// and the meridians, POINT the vertices. Lines and points carry smooth normals.
#include <algorithm>
#include <cmath>

#include "quadric.h"

namespace {

using mygl::glu::AngleTable;
using mygl::glu::fraction;
using mygl::glu::QuadricAttributes;

class SphereGrid {
public:
    SphereGrid(const GLUquadric& quadric, double radius, int slices, int stacks)
        : attributes_(quadric),
          flat_(quadric.normals == GLU_FLAT),
          slices_(slices),
          stacks_(stacks),
          azimuth_(slices, 0.0, 2.0 * M_PI / slices, true),
          polar_(stacks, 0.0, M_PI / stacks, false),
          facetAzimuth_(slices, -M_PI / slices, 2.0 * M_PI / slices, true),
          facetPolar_(stacks, 0.5 * M_PI / stacks, M_PI / stacks, false),
          ringRadius_(stacks + 1),
          ringZ_(stacks + 1) {
        for (int j = 0; j <= stacks; ++j) {
            ringRadius_[j] = static_cast<float>(radius) * polar_.sin[j];
            ringZ_[j] = static_cast<float>(radius) * polar_.cos[j];
        }
        ringRadius_[0] = ringRadius_[stacks] = 0.0f;  // the poles are points
    }

    // Grid vertex (slice i, ring j) with its smooth normal, or for GLU_FLAT the normal of the facet
    // between slices facetI-1, facetI and rings facetJ, facetJ+1 (the facet it closes).
    void vertex(int i, int j, int facetI, int facetJ) const {
        if (flat_) {
            attributes_.normal(facetAzimuth_.sin[facetI] * facetPolar_.sin[facetJ],
                               facetAzimuth_.cos[facetI] * facetPolar_.sin[facetJ], facetPolar_.cos[facetJ]);
        } else {
            attributes_.normal(azimuth_.sin[i] * polar_.sin[j], azimuth_.cos[i] * polar_.sin[j], polar_.cos[j]);
        }
        attributes_.texCoord(1.0f - fraction(i, slices_), 1.0f - fraction(j, stacks_));
        glVertex3f(ringRadius_[j] * azimuth_.sin[i], ringRadius_[j] * azimuth_.cos[i], ringZ_[j]);
    }
    void vertex(int i, int j) const { vertex(i, j, std::min(i, slices_), std::min(j, stacks_ - 1)); }

    void fill(bool inside) const {
        int firstBand = 0, endBand = stacks_;
        if (!attributes_.hasTexture) {
            firstBand = 1;
            endBand = stacks_ - 1;
            cap(0, 1, 0, !inside);
            cap(stacks_, stacks_ - 1, stacks_ - 1, inside);
        }
        for (int j = firstBand; j < endBand; ++j) {
            glBegin(GL_QUAD_STRIP);
            for (int i = 0; i <= slices_; ++i) {
                vertex(i, inside ? j : j + 1, i, j);
                vertex(i, inside ? j + 1 : j, i, j);
            }
            glEnd();
        }
    }

    // The latitude circles between the poles, then the meridians.
    void lines() const {
        mygl::glu::gridLines(slices_, stacks_, 1, stacks_ - 1, 1, [this](int i, int j) { vertex(i, j); });
    }

    void points() const {
        mygl::glu::gridPoints(slices_, stacks_, [this](int i, int j) { vertex(i, j); });
    }

private:
    // A triangle fan from the pole of ring `pole` around ring `ring`; the slices run backwards
    // when `descending`, which makes the fan face outwards at the +z pole.
    void cap(int pole, int ring, int facetJ, bool descending) const {
        glBegin(GL_TRIANGLE_FAN);
        vertex(0, pole);
        for (int k = 0; k <= slices_; ++k) {
            const int i = descending ? slices_ - k : k;
            vertex(i, ring, descending ? std::min(i + 1, slices_) : i, facetJ);
        }
        glEnd();
    }

    QuadricAttributes attributes_;
    bool flat_;
    int slices_, stacks_;
    AngleTable azimuth_, polar_, facetAzimuth_, facetPolar_;
    std::vector<float> ringRadius_, ringZ_;
};

}  // namespace

extern "C" void gluSphere(GLUquadric* quad, GLdouble radius, GLint slices, GLint stacks) {
    if (!quad) return;
    slices = std::min(slices, mygl::glu::kMaxQuadricDivisions);
    stacks = std::min(stacks, mygl::glu::kMaxQuadricDivisions);
    if (slices < 2 || stacks < 1 || !(radius >= 0.0) || !std::isfinite(radius)) {
        mygl::glu::quadricError(*quad, GLU_INVALID_VALUE);
        return;
    }
    const SphereGrid grid(*quad, radius, slices, stacks);
    switch (quad->drawStyle) {
    case GLU_FILL: grid.fill(quad->orientation == GLU_INSIDE); break;
    case GLU_LINE:
    case GLU_SILHOUETTE: grid.lines(); break;
    default: grid.points(); break;
    }
}
