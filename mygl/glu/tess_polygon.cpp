// A finished polygon: projected onto its plane, made a planar arrangement with a winding number
// per face, and the faces the winding rule keeps sent to the callbacks: as GL_TRIANGLES (with edge
// flags marking the region's boundary when an edge-flag callback is set) or, with
// GLU_TESS_BOUNDARY_ONLY, as one GL_LINE_LOOP per boundary contour (counter-clockwise around the
// region, clockwise around its holes). GLU_TESS_TOLERANCE is kept but only exactly coincident
// vertices merge, which GLU allows.
#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>

#include "tess_triangulate.h"
#include "tessellator.h"

namespace mygl::glu::tess {
namespace {

bool keeps(GLenum rule, int winding) {
    switch (rule) {
    case GLU_TESS_WINDING_NONZERO: return winding != 0;
    case GLU_TESS_WINDING_POSITIVE: return winding > 0;
    case GLU_TESS_WINDING_NEGATIVE: return winding < 0;
    case GLU_TESS_WINDING_ABS_GEQ_TWO: return std::abs(winding) >= 2;
    default: return (winding & 1) != 0;
    }
}

// The normal the program set, or Newell's normal of all contours, which makes the polygon's total
// area positive (counter-clockwise) as GLU's computed normal does.
void polygonNormal(const GLUtesselator& tess, double n[3]) {
    for (int k = 0; k < 3; ++k) n[k] = tess.normal[k];
    if (n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0) return;
    for (const auto& contour : tess.contours) {
        for (std::size_t k = 0; k < contour.size(); ++k) {
            const double* a = tess.vertices[contour[k]].coords;
            const double* b = tess.vertices[contour[(k + 1) % contour.size()]].coords;
            n[0] += (a[1] - b[1]) * (a[2] + b[2]);
            n[1] += (a[2] - b[2]) * (a[0] + b[0]);
            n[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
    }
    if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0) n[2] = 1.0;  // no area: any plane will do
}

// Drops the normal's largest coordinate, ordered so that counter-clockwise about the normal stays
// counter-clockwise in the plane (and exact: no rotation rounds the coordinates).
void project(std::vector<Vertex>& vertices, const double n[3]) {
    int axis = 2;
    if (std::fabs(n[0]) > std::fabs(n[axis])) axis = 0;
    if (std::fabs(n[1]) > std::fabs(n[axis])) axis = 1;
    int first = (axis + 1) % 3, second = (axis + 2) % 3;
    if (n[axis] < 0.0) std::swap(first, second);
    for (Vertex& v : vertices) v.p = {v.coords[first], v.coords[second]};
}

class Emitter {
public:
    Emitter(GLUtesselator& tess, const Arrangement& arrangement) : tess_(tess), arrangement_(arrangement) {
        for (std::size_t h = 0; h < arrangement.halfEdges.size(); ++h) {
            if (isBoundary(static_cast<int>(h))) {
                boundary_.insert({arrangement.halfEdges[h].origin, arrangement.halfEdges[h].target});
            }
        }
    }

    void triangles() {
        std::vector<std::vector<int>> holes(arrangement_.cycles.size());
        for (std::size_t k = 0; k < arrangement_.outerCycle.size(); ++k) {
            if (arrangement_.enclosingCycle[k] >= 0) {
                holes[arrangement_.enclosingCycle[k]].push_back(arrangement_.outerCycle[k]);
            }
        }
        std::vector<Triangle> all;
        for (std::size_t c = 0; c < arrangement_.cycles.size(); ++c) {
            const Cycle& cycle = arrangement_.cycles[c];
            if (!(cycle.area > 0.0) || !kept(static_cast<int>(c))) continue;
            std::vector<std::vector<int>> holeRings;
            for (const int hole : holes[c]) holeRings.push_back(ring(hole));
            const auto faceTriangles =
                triangulateFace(arrangement_.vertices, ring(static_cast<int>(c)), std::move(holeRings));
            all.insert(all.end(), faceTriangles.begin(), faceTriangles.end());
        }
        if (all.empty()) return;
        const bool flags = tess_.edgeFlag || tess_.edgeFlagData;
        int lastFlag = -1;
        begin(GL_TRIANGLES);
        for (const Triangle& t : all) {
            for (int k = 0; k < 3; ++k) {
                const int flag = boundary_.count({t[k], t[(k + 1) % 3]}) ? 1 : 0;
                if (flags && flag != lastFlag) edgeFlag(flag != 0);
                lastFlag = flag;
                vertex(t[k]);
            }
        }
        end();
    }

    void boundaryLoops() {
        std::vector<bool> done(arrangement_.halfEdges.size(), false);
        for (std::size_t start = 0; start < arrangement_.halfEdges.size(); ++start) {
            if (done[start] || !isBoundary(static_cast<int>(start))) continue;
            begin(GL_LINE_LOOP);
            int h = static_cast<int>(start);
            do {
                done[h] = true;
                vertex(arrangement_.halfEdges[h].origin);
                h = nextBoundary(h);
            } while (h != static_cast<int>(start) && !done[h]);
            end();
        }
    }

private:
    bool kept(int cycle) const { return keeps(tess_.windingRule, arrangement_.cycles[cycle].winding); }
    // The kept region lies on its left, the rest on its right.
    bool isBoundary(int h) const {
        const HalfEdge& e = arrangement_.halfEdges[h];
        return kept(e.cycle) && !kept(arrangement_.halfEdges[e.twin].cycle);
    }
    // The boundary continues at h's target with the first boundary half-edge clockwise from the
    // way back (the half-edges in between lie inside the region).
    int nextBoundary(int h) const {
        int candidate = arrangement_.halfEdges[h].next;
        for (std::size_t guard = 0; !isBoundary(candidate) && guard < arrangement_.halfEdges.size(); ++guard) {
            candidate = arrangement_.halfEdges[arrangement_.halfEdges[candidate].twin].next;
        }
        return candidate;
    }
    std::vector<int> ring(int cycle) const {
        std::vector<int> vertices;
        int h = arrangement_.cycles[cycle].first;
        do {
            vertices.push_back(arrangement_.halfEdges[h].origin);
            h = arrangement_.halfEdges[h].next;
        } while (h != arrangement_.cycles[cycle].first);
        return vertices;
    }

    void begin(GLenum mode) const {
        if (tess_.beginData)
            tess_.beginData(mode, tess_.polygonData);
        else if (tess_.begin)
            tess_.begin(mode);
    }
    void vertex(int v) const {
        void* data = arrangement_.vertices[v].data;
        if (tess_.vertexData)
            tess_.vertexData(data, tess_.polygonData);
        else if (tess_.vertex)
            tess_.vertex(data);
    }
    void end() const {
        if (tess_.endData)
            tess_.endData(tess_.polygonData);
        else if (tess_.end)
            tess_.end();
    }
    void edgeFlag(bool flag) const {
        const GLboolean value = flag ? GL_TRUE : GL_FALSE;
        if (tess_.edgeFlagData)
            tess_.edgeFlagData(value, tess_.polygonData);
        else if (tess_.edgeFlag)
            tess_.edgeFlag(value);
    }

    GLUtesselator& tess_;
    const Arrangement& arrangement_;
    std::set<std::pair<int, int>> boundary_;
};

}  // namespace

void reportError(GLUtesselator& tess, GLenum error) {
    if (tess.errorData)
        tess.errorData(error, tess.polygonData);
    else if (tess.error)
        tess.error(error);
}

void tessellatePolygon(GLUtesselator& tess) {
    double n[3];
    polygonNormal(tess, n);
    project(tess.vertices, n);
    bool missingCombine = false;
    const CombineVertex combine = [&](const double coords[3], void* const sourceData[4], const float weights[4]) {
        GLdouble where[3] = {coords[0], coords[1], coords[2]};
        void* sources[4] = {sourceData[0], sourceData[1], sourceData[2], sourceData[3]};
        GLfloat shares[4] = {weights[0], weights[1], weights[2], weights[3]};
        void* made = nullptr;
        if (tess.combineData)
            tess.combineData(where, sources, shares, &made, tess.polygonData);
        else if (tess.combine)
            tess.combine(where, sources, shares, &made);
        missingCombine = missingCombine || made == nullptr;
        return made;
    };
    const Arrangement arrangement = buildArrangement(tess.vertices, tess.contours, combine);
    if (missingCombine) {
        // A crossing has no vertex data to send: GLU reports it and the polygon is not drawn.
        reportError(tess, GLU_TESS_NEED_COMBINE_CALLBACK);
        return;
    }
    Emitter emitter(tess, arrangement);
    if (tess.boundaryOnly)
        emitter.boundaryLoops();
    else
        emitter.triangles();
}

}  // namespace mygl::glu::tess
