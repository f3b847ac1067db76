#include "tess_arrangement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace mygl::glu::tess {
namespace {

// A straight piece of contour from vertex a to vertex b, run `count` times in that direction.
struct Segment {
    int a, b, count;
};

// Exact lookup of vertices by position, so that coincident points become one vertex (the first).
class PointIndex {
public:
    explicit PointIndex(std::vector<Vertex>& vertices) : vertices_(vertices) {
        for (std::size_t v = 0; v < vertices.size(); ++v)
            index_.try_emplace({vertices[v].p.s, vertices[v].p.t}, static_cast<int>(v));
    }
    // The vertex at v.p if there is one, otherwise v added.
    int findOrAdd(const Vertex& v) {
        const auto [it, added] = index_.try_emplace({v.p.s, v.p.t}, static_cast<int>(vertices_.size()));
        if (added) vertices_.push_back(v);
        return it->second;
    }
    int find(const Point& p) const {
        const auto it = index_.find({p.s, p.t});
        return it == index_.end() ? -1 : it->second;
    }

private:
    std::vector<Vertex>& vertices_;
    std::map<std::pair<double, double>, int> index_;
};

double dot(const Point& origin, const Point& a, const Point& b) {
    return (a.s - origin.s) * (b.s - origin.s) + (a.t - origin.t) * (b.t - origin.t);
}

// Whether p lies on segment ab strictly between its ends.
bool insideSegment(const Point& p, const Point& a, const Point& b) {
    if (orient(a, b, p) != 0.0) return false;
    const double along = dot(a, p, b);
    return along > 0.0 && along < dot(a, b, b);
}

bool boxesOverlap(const Point& a, const Point& b, const Point& c, const Point& d) {
    return std::max(a.s, b.s) >= std::min(c.s, d.s) && std::max(c.s, d.s) >= std::min(a.s, b.s) &&
           std::max(a.t, b.t) >= std::min(c.t, d.t) && std::max(c.t, d.t) >= std::min(a.t, b.t);
}

bool oppositeSides(double x, double y) { return (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0); }

class Splitter {
public:
    Splitter(std::vector<Vertex>& vertices, PointIndex& index, const CombineVertex& combine)
        : vertices_(vertices), index_(index), combine_(combine) {}

    // Finds every crossing and every vertex lying inside another segment, and splits the segments
    // there. Returns whether anything was split.
    bool pass(std::vector<Segment>& segments) {
        std::vector<std::vector<int>> splits(segments.size());
        for (std::size_t i = 0; i < segments.size(); ++i) {
            for (std::size_t j = i + 1; j < segments.size(); ++j) intersect(segments, i, j, splits);
        }
        bool split = false;
        std::vector<Segment> pieces;
        for (std::size_t i = 0; i < segments.size(); ++i) {
            split = split || !splits[i].empty();
            appendPieces(segments[i], splits[i], pieces);
        }
        segments = std::move(pieces);
        return split;
    }

private:
    void intersect(const std::vector<Segment>& segments, std::size_t i, std::size_t j,
                   std::vector<std::vector<int>>& splits) {
        const Segment e = segments[i], f = segments[j];
        const Point a = vertices_[e.a].p, b = vertices_[e.b].p, c = vertices_[f.a].p, d = vertices_[f.b].p;
        if (!boxesOverlap(a, b, c, d)) return;
        if (f.a != e.a && f.a != e.b && insideSegment(c, a, b)) splits[i].push_back(f.a);
        if (f.b != e.a && f.b != e.b && insideSegment(d, a, b)) splits[i].push_back(f.b);
        if (e.a != f.a && e.a != f.b && insideSegment(a, c, d)) splits[j].push_back(e.a);
        if (e.b != f.a && e.b != f.b && insideSegment(b, c, d)) splits[j].push_back(e.b);
        if (e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b) return;
        const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
        if (!oppositeSides(o1, o2) || !oppositeSides(o3, o4)) return;
        const double t = o3 / (o3 - o4), u = o1 / (o1 - o2);  // along ab and along cd
        const int v = crossing(e, f, t, u);
        splits[i].push_back(v);
        splits[j].push_back(v);
    }

    // The vertex where e (at parameter t) crosses f (at u); a new one is made by the combine callback.
    int crossing(const Segment& e, const Segment& f, double t, double u) {
        const Vertex &a = vertices_[e.a], &b = vertices_[e.b], &c = vertices_[f.a], &d = vertices_[f.b];
        Vertex v{{a.p.s + t * (b.p.s - a.p.s), a.p.t + t * (b.p.t - a.p.t)}, {}, nullptr};
        if (const int existing = index_.find(v.p); existing >= 0) return existing;
        for (int k = 0; k < 3; ++k) {
            v.coords[k] = 0.5 * (a.coords[k] + t * (b.coords[k] - a.coords[k])) +
                          0.5 * (c.coords[k] + u * (d.coords[k] - c.coords[k]));
        }
        void* const sources[4] = {a.data, b.data, c.data, d.data};
        const float weights[4] = {static_cast<float>((1.0 - t) / 2), static_cast<float>(t / 2),
                                  static_cast<float>((1.0 - u) / 2), static_cast<float>(u / 2)};
        v.data = combine_(v.coords, sources, weights);
        return index_.findOrAdd(v);
    }

    // The pieces of s between its split points, in order along it.
    void appendPieces(const Segment& s, std::vector<int>& at, std::vector<Segment>& pieces) const {
        const Point a = vertices_[s.a].p, b = vertices_[s.b].p;
        std::sort(at.begin(), at.end(),
                  [&](int x, int y) { return dot(a, vertices_[x].p, b) < dot(a, vertices_[y].p, b); });
        at.erase(std::unique(at.begin(), at.end()), at.end());
        int from = s.a;
        for (const int v : at) {
            if (v == from || v == s.b) continue;
            pieces.push_back({from, v, s.count});
            from = v;
        }
        if (from != s.b) pieces.push_back({from, s.b, s.count});
    }

    std::vector<Vertex>& vertices_;
    PointIndex& index_;
    const CombineVertex& combine_;
};

// Contour edges as segments, split until no two cross (a few passes settle the rounding of
// crossings made in an earlier pass), then coincident segments merged with their counts summed.
std::vector<Segment> planarSegments(std::vector<Vertex>& vertices, const std::vector<std::vector<int>>& contours,
                                    const CombineVertex& combine) {
    PointIndex index(vertices);
    std::vector<Segment> segments;
    for (const auto& contour : contours) {
        for (std::size_t k = 0; k < contour.size(); ++k) {
            const int a = index.find(vertices[contour[k]].p);
            const int b = index.find(vertices[contour[(k + 1) % contour.size()]].p);
            if (a != b) segments.push_back({a, b, 1});
        }
    }
    Splitter splitter(vertices, index, combine);
    constexpr int kMaxPasses = 8;
    for (int pass = 0; pass < kMaxPasses && splitter.pass(segments); ++pass) {
    }
    std::map<std::pair<int, int>, int> merged;
    for (const Segment& s : segments) {
        merged[{std::min(s.a, s.b), std::max(s.a, s.b)}] += s.a < s.b ? s.count : -s.count;
    }
    std::vector<Segment> result;
    for (const auto& [ends, count] : merged) {
        if (count != 0) result.push_back({ends.first, ends.second, count});
    }
    return result;
}

// Half-edges 2k and 2k+1 for segment k; `next` links each to the following half-edge around the
// face on its left: at the target, the outgoing half-edge just clockwise of the way back.
std::vector<HalfEdge> linkHalfEdges(const std::vector<Vertex>& vertices, const std::vector<Segment>& segments) {
    std::vector<HalfEdge> halfEdges;
    std::vector<std::vector<int>> outgoing(vertices.size());
    for (const Segment& s : segments) {
        const int h = static_cast<int>(halfEdges.size());
        halfEdges.push_back({s.a, s.b, h + 1, -1, -1, s.count});
        halfEdges.push_back({s.b, s.a, h, -1, -1, -s.count});
        outgoing[s.a].push_back(h);
        outgoing[s.b].push_back(h + 1);
    }
    std::vector<int> position(halfEdges.size());
    for (auto& around : outgoing) {
        auto angle = [&](int h) {
            const Point &from = vertices[halfEdges[h].origin].p, &to = vertices[halfEdges[h].target].p;
            return std::atan2(to.t - from.t, to.s - from.s);
        };
        std::sort(around.begin(), around.end(), [&](int x, int y) { return angle(x) < angle(y); });
        for (std::size_t k = 0; k < around.size(); ++k) position[around[k]] = static_cast<int>(k);
    }
    for (HalfEdge& h : halfEdges) {
        const auto& around = outgoing[h.target];
        const int back = position[h.twin];
        h.next = around[(back + around.size() - 1) % around.size()];
    }
    return halfEdges;
}

// How many times the directed half-edges with positive winding count wind around p, skipping those
// of component `skip` (p's own).
int windingAround(const Point& p, const Arrangement& arrangement, const std::vector<int>& componentOf, int skip) {
    int winding = 0;
    for (const HalfEdge& h : arrangement.halfEdges) {
        if (h.winding <= 0 || componentOf[h.origin] == skip) continue;
        const Point &a = arrangement.vertices[h.origin].p, &b = arrangement.vertices[h.target].p;
        if (a.t <= p.t && b.t > p.t && orient(a, b, p) > 0.0) winding += h.winding;
        if (b.t <= p.t && a.t > p.t && orient(a, b, p) < 0.0) winding -= h.winding;
    }
    return winding;
}

bool cycleEncloses(const Arrangement& arrangement, int cycle, const Point& p) {
    int winding = 0;
    int h = arrangement.cycles[cycle].first;
    do {
        const HalfEdge& e = arrangement.halfEdges[h];
        const Point &a = arrangement.vertices[e.origin].p, &b = arrangement.vertices[e.target].p;
        if (a.t <= p.t && b.t > p.t && orient(a, b, p) > 0.0) ++winding;
        if (b.t <= p.t && a.t > p.t && orient(a, b, p) < 0.0) --winding;
        h = e.next;
    } while (h != arrangement.cycles[cycle].first);
    return winding != 0;
}

void traceCycles(Arrangement& arrangement) {
    for (std::size_t start = 0; start < arrangement.halfEdges.size(); ++start) {
        if (arrangement.halfEdges[start].cycle >= 0) continue;
        const int id = static_cast<int>(arrangement.cycles.size());
        const Point origin = arrangement.vertices[arrangement.halfEdges[start].origin].p;
        double area = 0.0;
        int h = static_cast<int>(start);
        do {
            HalfEdge& e = arrangement.halfEdges[h];
            e.cycle = id;
            const Point &a = arrangement.vertices[e.origin].p, &b = arrangement.vertices[e.target].p;
            area += (a.s - origin.s) * (b.t - origin.t) - (b.s - origin.s) * (a.t - origin.t);
            h = e.next;
        } while (h != static_cast<int>(start));
        arrangement.cycles.push_back({static_cast<int>(start), area / 2.0});
    }
}

// Connected components of the vertices joined by edges (union-find), numbered from 0; -1 for a
// vertex without edges.
std::vector<int> components(const Arrangement& arrangement, int& count) {
    std::vector<int> parent(arrangement.vertices.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const HalfEdge& h : arrangement.halfEdges) parent[root(h.origin)] = root(h.target);
    std::vector<int> number(parent.size(), -1), componentOf(parent.size(), -1);
    count = 0;
    for (const HalfEdge& h : arrangement.halfEdges) {
        int& n = number[root(h.origin)];
        if (n < 0) n = count++;
        componentOf[h.origin] = n;
    }
    return componentOf;
}

// Winding numbers: the face around a component winds as the other components wind around it;
// crossing a half-edge from its left face to its right one removes its winding count.
void assignWindings(Arrangement& arrangement, const std::vector<int>& componentOf, int componentCount) {
    arrangement.outerCycle.assign(componentCount, -1);
    for (std::size_t c = 0; c < arrangement.cycles.size(); ++c) {
        Cycle& cycle = arrangement.cycles[c];
        cycle.component = componentOf[arrangement.halfEdges[cycle.first].origin];
        int& outer = arrangement.outerCycle[cycle.component];
        if (outer < 0 || cycle.area < arrangement.cycles[outer].area) outer = static_cast<int>(c);
    }
    std::vector<bool> assigned(arrangement.cycles.size(), false);
    for (int k = 0; k < componentCount; ++k) {
        const int outer = arrangement.outerCycle[k];
        const Point p = arrangement.vertices[arrangement.halfEdges[arrangement.cycles[outer].first].origin].p;
        arrangement.cycles[outer].winding = windingAround(p, arrangement, componentOf, k);
        assigned[outer] = true;
        std::vector<int> pending{outer};
        while (!pending.empty()) {
            const int c = pending.back();
            pending.pop_back();
            int h = arrangement.cycles[c].first;
            do {
                const HalfEdge& e = arrangement.halfEdges[h];
                const int across = arrangement.halfEdges[e.twin].cycle;
                if (!assigned[across]) {
                    assigned[across] = true;
                    arrangement.cycles[across].winding = arrangement.cycles[c].winding - e.winding;
                    pending.push_back(across);
                }
                h = e.next;
            } while (h != arrangement.cycles[c].first);
        }
    }
}

// For each component, the smallest bounded face of another component that contains it.
void findEnclosingCycles(Arrangement& arrangement) {
    const std::size_t count = arrangement.outerCycle.size();
    arrangement.enclosingCycle.assign(count, -1);
    for (std::size_t k = 0; k < count; ++k) {
        const Point p =
            arrangement.vertices[arrangement.halfEdges[arrangement.cycles[arrangement.outerCycle[k]].first].origin].p;
        double smallest = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < arrangement.cycles.size(); ++c) {
            const Cycle& cycle = arrangement.cycles[c];
            if (cycle.component == static_cast<int>(k) || !(cycle.area > 0.0) ||
                static_cast<int>(c) == arrangement.outerCycle[cycle.component] || !(cycle.area < smallest) ||
                !cycleEncloses(arrangement, static_cast<int>(c), p)) {
                continue;
            }
            smallest = cycle.area;
            arrangement.enclosingCycle[k] = static_cast<int>(c);
        }
    }
}

}  // namespace

double orient(const Point& a, const Point& b, const Point& c) {
    return (b.s - a.s) * (c.t - a.t) - (b.t - a.t) * (c.s - a.s);
}

Arrangement buildArrangement(std::vector<Vertex> vertices, const std::vector<std::vector<int>>& contours,
                             const CombineVertex& combine) {
    Arrangement arrangement;
    const std::vector<Segment> segments = planarSegments(vertices, contours, combine);
    arrangement.vertices = std::move(vertices);
    arrangement.halfEdges = linkHalfEdges(arrangement.vertices, segments);
    traceCycles(arrangement);
    int componentCount = 0;
    const std::vector<int> componentOf = components(arrangement, componentCount);
    assignWindings(arrangement, componentOf, componentCount);
    findEnclosingCycles(arrangement);
    return arrangement;
}

}  // namespace mygl::glu::tess
