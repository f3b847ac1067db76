#pragma once
// The tessellator's geometry: contours projected onto a plane become a planar arrangement. Every
// crossing of two edges becomes a vertex (made by the combine callback), every vertex lying on
// another edge splits it, coincident edges merge with their windings summed. Coincident vertices
// merge into the first of them (its data is kept; GLU allows this without a combine call). The faces of the
// arrangement are traced as cycles of half-edges (face on the left), and every face gets its
// winding number: how many times the contours wind around it.
#include <functional>
#include <vector>

namespace mygl::glu::tess {

struct Point {
    double s, t;
};

struct Vertex {
    Point p;           // in the projection plane
    double coords[3];  // in object space, as the program gave them (or as combined)
    void* data;        // the program's vertex data
};

// Makes the vertex at object coordinates `coords` where the edge between the vertices with data
// sourceData[0] and [1] crosses the edge between [2] and [3], `weights` their shares; returns the
// new vertex's data (nullptr when it cannot be made).
using CombineVertex = std::function<void*(const double coords[3], void* const sourceData[4], const float weights[4])>;

struct HalfEdge {
    int origin, target;
    int twin;
    int next;     // the next half-edge around the face on the left
    int cycle;    // the face boundary this half-edge belongs to
    int winding;  // how many contour edges run along it in its direction, minus those against it
};

struct Cycle {
    int first;           // one of its half-edges
    double area;         // signed: > 0 for the boundary of a bounded face (counter-clockwise)
    int winding = 0;     // winding number of the face on the left of its half-edges
    int component = -1;  // connected component of the arrangement it belongs to
};

struct Arrangement {
    std::vector<Vertex> vertices;
    std::vector<HalfEdge> halfEdges;
    std::vector<Cycle> cycles;
    // For each component, its outer (clockwise) cycle and the bounded cycle of another component
    // that directly encloses it (-1 when it lies in the unbounded face).
    std::vector<int> outerCycle;
    std::vector<int> enclosingCycle;
};

// contours: indices into `vertices`, each contour closed implicitly (last -> first).
Arrangement buildArrangement(std::vector<Vertex> vertices, const std::vector<std::vector<int>>& contours,
                             const CombineVertex& combine);

// Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise.
double orient(const Point& a, const Point& b, const Point& c);

}  // namespace mygl::glu::tess
