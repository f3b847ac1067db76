#include "tess_triangulate.h"

#include <algorithm>
#include <limits>

namespace mygl::glu::tess {
namespace {

bool same(const Point& a, const Point& b) { return a.s == b.s && a.t == b.t; }

// Whether segments pq and ab share any point.
bool touches(const Point& p, const Point& q, const Point& a, const Point& b) {
    const double o1 = orient(p, q, a), o2 = orient(p, q, b), o3 = orient(a, b, p), o4 = orient(a, b, q);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
    auto within = [](const Point& x, const Point& y, const Point& z) {  // z on segment xy, given collinear
        return std::min(x.s, y.s) <= z.s && z.s <= std::max(x.s, y.s) && std::min(x.t, y.t) <= z.t &&
               z.t <= std::max(x.t, y.t);
    };
    return (o1 == 0 && within(p, q, a)) || (o2 == 0 && within(p, q, b)) || (o3 == 0 && within(a, b, p)) ||
           (o4 == 0 && within(a, b, q));
}

// Whether direction `to` leaves vertex `at` into the interior angle between the edges from `before`
// and to `after` of a counter-clockwise polygon.
bool insideCorner(const Point& before, const Point& at, const Point& after, const Point& to) {
    if (orient(before, at, after) >= 0.0) return orient(at, after, to) > 0.0 && orient(before, at, to) > 0.0;
    return !(orient(at, after, to) <= 0.0 && orient(before, at, to) <= 0.0);
}

class FaceTriangulator {
public:
    explicit FaceTriangulator(const std::vector<Vertex>& vertices) : vertices_(vertices) {}

    const Point& at(int v) const { return vertices_[v].p; }

    // Joins `hole` into `polygon` by a bridge from the hole's rightmost vertex to the nearest
    // polygon vertex it can see, walking the hole from there and back over the bridge.
    void bridge(std::vector<int>& polygon, const std::vector<int>& hole,
                const std::vector<std::vector<int>>& others) const {
        std::size_t m = 0;
        for (std::size_t k = 1; k < hole.size(); ++k) {
            const Point &p = at(hole[k]), &best = at(hole[m]);
            if (p.s > best.s || (p.s == best.s && p.t > best.t)) m = k;
        }
        const Point& from = at(hole[m]);
        std::size_t chosen = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < polygon.size(); ++k) {
            const Point& to = at(polygon[k]);
            const double distance = (to.s - from.s) * (to.s - from.s) + (to.t - from.t) * (to.t - from.t);
            if (!(distance < nearest)) continue;
            const Point& before = at(polygon[(k + polygon.size() - 1) % polygon.size()]);
            const Point& after = at(polygon[(k + 1) % polygon.size()]);
            if (!insideCorner(before, to, after, from) || blocked(from, to, polygon) || blocked(from, to, hole))
                continue;
            if (std::any_of(others.begin(), others.end(), [&](const auto& other) { return blocked(from, to, other); }))
                continue;
            nearest = distance;
            chosen = k;
        }
        std::vector<int> joined(polygon.begin(), polygon.begin() + static_cast<long>(chosen) + 1);
        for (std::size_t k = 0; k <= hole.size(); ++k) joined.push_back(hole[(m + k) % hole.size()]);
        joined.insert(joined.end(), polygon.begin() + static_cast<long>(chosen), polygon.end());
        polygon = std::move(joined);
    }

    std::vector<Triangle> clipEars(std::vector<int> polygon) const {
        std::vector<Triangle> triangles;
        std::size_t k = 0;
        while (polygon.size() > 3) {
            const std::size_t n = polygon.size();
            std::size_t clipped = n;
            for (std::size_t step = 0; step < n && clipped == n; ++step) {
                const std::size_t i = (k + step) % n;
                if (isEar(polygon, i)) clipped = i;
            }
            if (clipped == n) clipped = fallbackCorner(polygon);
            const std::size_t n1 = polygon.size();
            const Triangle t{polygon[(clipped + n1 - 1) % n1], polygon[clipped], polygon[(clipped + 1) % n1]};
            if (orient(at(t[0]), at(t[1]), at(t[2])) > 0.0) triangles.push_back(t);
            polygon.erase(polygon.begin() + static_cast<long>(clipped));
            k = clipped == 0 ? 0 : clipped - 1;
        }
        if (polygon.size() == 3 && orient(at(polygon[0]), at(polygon[1]), at(polygon[2])) > 0.0) {
            triangles.push_back({polygon[0], polygon[1], polygon[2]});
        }
        return triangles;
    }

private:
    bool blocked(const Point& from, const Point& to, const std::vector<int>& ring) const {
        for (std::size_t k = 0; k < ring.size(); ++k) {
            const Point &a = at(ring[k]), &b = at(ring[(k + 1) % ring.size()]);
            if (same(a, from) || same(b, from) || same(a, to) || same(b, to)) continue;
            if (touches(from, to, a, b)) return true;
        }
        return false;
    }

    // A convex corner whose triangle holds no other vertex of the polygon (on its border counts).
    bool isEar(const std::vector<int>& polygon, std::size_t i) const {
        const std::size_t n = polygon.size();
        const Point &a = at(polygon[(i + n - 1) % n]), &b = at(polygon[i]), &c = at(polygon[(i + 1) % n]);
        if (!(orient(a, b, c) > 0.0)) return false;
        for (const int v : polygon) {
            const Point& p = at(v);
            if (same(p, a) || same(p, b) || same(p, c)) continue;
            if (orient(a, b, p) >= 0.0 && orient(b, c, p) >= 0.0 && orient(c, a, p) >= 0.0) return false;
        }
        return true;
    }

    // No ear (only rounding makes that happen): drop a flat corner if there is one, which adds no
    // area, otherwise the most convex corner.
    std::size_t fallbackCorner(const std::vector<int>& polygon) const {
        const std::size_t n = polygon.size();
        std::size_t best = 0;
        double largest = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
            const double area = orient(at(polygon[(i + n - 1) % n]), at(polygon[i]), at(polygon[(i + 1) % n]));
            if (area == 0.0) return i;
            if (area > largest) {
                largest = area;
                best = i;
            }
        }
        return best;
    }

    const std::vector<Vertex>& vertices_;
};

}  // namespace

std::vector<Triangle> triangulateFace(const std::vector<Vertex>& vertices, std::vector<int> outer,
                                      std::vector<std::vector<int>> holes) {
    const FaceTriangulator triangulator(vertices);
    auto rightmost = [&](const std::vector<int>& ring) {
        double s = -std::numeric_limits<double>::infinity();
        for (const int v : ring) s = std::max(s, vertices[v].p.s);
        return s;
    };
    std::sort(holes.begin(), holes.end(), [&](const auto& a, const auto& b) { return rightmost(a) > rightmost(b); });
    for (std::size_t k = 0; k < holes.size(); ++k) {
        const std::vector<std::vector<int>> later(holes.begin() + static_cast<long>(k) + 1, holes.end());
        triangulator.bridge(outer, holes[k], later);
    }
    return triangulator.clipEars(std::move(outer));
}

}  // namespace mygl::glu::tess
