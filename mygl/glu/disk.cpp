// gluDisk and gluPartialDisk: in the z = 0 plane, angles measured clockwise from +y
// (x = r sin(angle), y = r cos(angle)), loops from the outer radius inwards, as GLU builds them.
// FILL: a triangle fan when the inner radius is 0, then one quad strip per loop; LINE: every
// circle and every radial line; SILHOUETTE: the inner and outer arcs (and the two end radii of a
// partial disk); POINT: the vertices. The normal is +z (-z inside), set once.
#include <algorithm>
#include <cmath>

#include "quadric.h"

namespace {

using mygl::glu::AngleTable;
using mygl::glu::fraction;
using mygl::glu::QuadricAttributes;

class DiskGrid {
public:
    DiskGrid(const GLUquadric& quadric, double inner, double outer, int slices, int loops, double startDegrees,
             double sweepDegrees)
        : attributes_(quadric),
          slices_(slices),
          loops_(loops),
          full_(sweepDegrees == 360.0),
          inner_(static_cast<float>(inner)),
          outer_(static_cast<float>(outer)),
          angle_(slices, startDegrees * M_PI / 180.0, sweepDegrees * M_PI / 180.0 / slices, full_) {}

    float radius(int loop) const { return outer_ - (outer_ - inner_) * fraction(loop, loops_); }
    void vertex(int i, float r) const {
        const float t = r / outer_ / 2.0f;
        attributes_.texCoord(t * angle_.sin[i] + 0.5f, t * angle_.cos[i] + 0.5f);
        glVertex3f(r * angle_.sin[i], r * angle_.cos[i], 0.0f);
    }

    void fill(bool inside) const {
        int bands = loops_;
        if (inner_ == 0.0f) {
            bands = loops_ - 1;
            glBegin(GL_TRIANGLE_FAN);
            attributes_.texCoord(0.5f, 0.5f);
            glVertex3f(0.0f, 0.0f, 0.0f);
            for (int k = 0; k <= slices_; ++k) vertex(inside ? k : slices_ - k, radius(loops_ - 1));
            glEnd();
        }
        for (int j = 0; j < bands; ++j) {
            glBegin(GL_QUAD_STRIP);
            for (int i = 0; i <= slices_; ++i) {
                vertex(i, radius(inside ? j + 1 : j));
                vertex(i, radius(inside ? j : j + 1));
            }
            glEnd();
        }
    }

    void lines() const {
        if (inner_ == outer_) {
            arc(loops_);
            return;
        }
        for (int j = 0; j <= loops_; ++j) arc(j);
        for (int i = 0; i < spokes(); ++i) spoke(i);
    }

    void silhouette() const {
        if (!full_) {
            spoke(0);
            spoke(slices_);
        }
        arc(0);
        if (inner_ != outer_) arc(loops_);
    }

    void points() const {
        glBegin(GL_POINTS);
        for (int i = 0; i < spokes(); ++i) {
            for (int j = 0; j <= loops_; ++j) vertex(i, radius(j));
        }
        glEnd();
    }

private:
    // A full disk repeats its first radius at the end; a partial one has slices + 1 radii.
    int spokes() const { return full_ ? slices_ : slices_ + 1; }
    void arc(int loop) const {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices_; ++i) vertex(i, radius(loop));
        glEnd();
    }
    void spoke(int i) const {
        glBegin(GL_LINE_STRIP);
        for (int j = 0; j <= loops_; ++j) vertex(i, radius(j));
        glEnd();
    }

    QuadricAttributes attributes_;
    int slices_, loops_;
    bool full_;
    float inner_, outer_;
    AngleTable angle_;
};

}  // namespace

extern "C" {

void gluPartialDisk(GLUquadric* quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops, GLdouble start,
                    GLdouble sweep) {
    if (!quad) return;
    slices = std::min(slices, mygl::glu::kMaxQuadricDivisions);
    const bool finite = std::isfinite(inner) && std::isfinite(outer) && std::isfinite(start) && !std::isnan(sweep);
    if (slices < 2 || loops < 1 || !finite || outer <= 0.0 || inner < 0.0 || inner > outer) {
        mygl::glu::quadricError(*quad, GLU_INVALID_VALUE);
        return;
    }
    // GLU's rules: a sweep beyond +-360 degrees is a full turn; a negative sweep runs the other way.
    if (sweep < -360.0 || sweep > 360.0) sweep = 360.0;
    if (sweep < 0.0) {
        start += sweep;
        sweep = -sweep;
    }
    const DiskGrid grid(*quad, inner, outer, slices, loops, start, sweep);
    const QuadricAttributes attributes(*quad);
    attributes.normal(0.0f, 0.0f, 1.0f);
    switch (quad->drawStyle) {
    case GLU_FILL: grid.fill(quad->orientation == GLU_INSIDE); break;
    case GLU_LINE: grid.lines(); break;
    case GLU_SILHOUETTE: grid.silhouette(); break;
    default: grid.points(); break;
    }
}

void gluDisk(GLUquadric* quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops) {
    gluPartialDisk(quad, inner, outer, slices, loops, 0.0, 360.0);
}

}  // extern "C"
