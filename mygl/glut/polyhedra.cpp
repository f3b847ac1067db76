// GLUT's polyhedra with flat faces: cube, tetrahedron, octahedron, dodecahedron, icosahedron,
// rhombic dodecahedron and the Sierpinski sponge, in freeglut's sizes (radius 1, the
// dodecahedron sqrt(3); the cube by its edge). Each is given by its corners; the faces are found
// once as the planes through corners that have every other corner behind them, wound
// counter-clockwise seen from outside, with the plane's normal.
#include <mygl/glut.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec normalized(const Vec& v) {
    const double length = std::sqrt(dot(v, v));
    return {v[0] / length, v[1] / length, v[2] / length};
}

struct Face {
    Vec normal;
    std::vector<int> corners;  // counter-clockwise seen from outside
};

struct Polyhedron {
    std::vector<Vec> corners;
    std::vector<Face> faces;
};

constexpr double kEpsilon = 1e-9;

// The faces of the convex hull of `corners` (every corner a vertex of it).
Polyhedron withFaces(std::vector<Vec> corners) {
    Polyhedron p{std::move(corners), {}};
    const int n = static_cast<int>(p.corners.size());
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            for (int c = b + 1; c < n; ++c) {
                Vec normal = cross(sub(p.corners[b], p.corners[a]), sub(p.corners[c], p.corners[a]));
                if (dot(normal, normal) < kEpsilon) continue;
                normal = normalized(normal);
                const double d = dot(normal, p.corners[a]);
                int above = 0, below = 0;
                std::vector<int> onPlane;
                for (int i = 0; i < n; ++i) {
                    const double side = dot(normal, p.corners[i]) - d;
                    if (side > kEpsilon)
                        ++above;
                    else if (side < -kEpsilon)
                        ++below;
                    else
                        onPlane.push_back(i);
                }
                if (above && below) continue;
                if (above) normal = {-normal[0], -normal[1], -normal[2]};
                if (onPlane[0] != a || onPlane[1] != b || onPlane[2] != c) continue;  // found once, by its first three
                // Counter-clockwise around the normal, from the first corner.
                Vec centre{0, 0, 0};
                for (int i : onPlane)
                    for (int k = 0; k < 3; ++k) centre[k] += p.corners[i][k] / static_cast<double>(onPlane.size());
                const Vec x = normalized(sub(p.corners[onPlane[0]], centre)), y = cross(normal, x);
                std::sort(onPlane.begin(), onPlane.end(), [&](int i, int j) {
                    const Vec ri = sub(p.corners[i], centre), rj = sub(p.corners[j], centre);
                    return std::atan2(dot(ri, y), dot(ri, x)) < std::atan2(dot(rj, y), dot(rj, x));
                });
                p.faces.push_back({normal, onPlane});
            }
    return p;
}

const Polyhedron& cube() {
    static const Polyhedron p = withFaces({{-0.5, -0.5, -0.5},
                                           {0.5, -0.5, -0.5},
                                           {0.5, 0.5, -0.5},
                                           {-0.5, 0.5, -0.5},
                                           {-0.5, -0.5, 0.5},
                                           {0.5, -0.5, 0.5},
                                           {0.5, 0.5, 0.5},
                                           {-0.5, 0.5, 0.5}});
    return p;
}

const Polyhedron& tetrahedron() {
    // One corner on +x, the others a third of the radius behind it.
    static const Polyhedron p = withFaces({{1, 0, 0},
                                           {-1.0 / 3, 2 * std::sqrt(2.0) / 3, 0},
                                           {-1.0 / 3, -std::sqrt(2.0) / 3, std::sqrt(6.0) / 3},
                                           {-1.0 / 3, -std::sqrt(2.0) / 3, -std::sqrt(6.0) / 3}});
    return p;
}

const Polyhedron& octahedron() {
    static const Polyhedron p = withFaces({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
    return p;
}

const Polyhedron& icosahedron() {
    // Corners on +x and -x, and two rings of five at x = +-1/sqrt(5), turned 36 degrees apart.
    static const Polyhedron p = [] {
        std::vector<Vec> corners{{1, 0, 0}, {-1, 0, 0}};
        const double x = 1 / std::sqrt(5.0), r = 2 / std::sqrt(5.0);
        for (int k = 0; k < 5; ++k) {
            const double a = 2 * M_PI * k / 5, b = a + M_PI / 5;
            corners.push_back({x, r * std::cos(a), r * std::sin(a)});
            corners.push_back({-x, r * std::cos(b), r * std::sin(b)});
        }
        return withFaces(corners);
    }();
    return p;
}

const Polyhedron& dodecahedron() {
    // The cube's corners and three golden rectangles: radius sqrt(3).
    static const Polyhedron p = [] {
        const double phi = (1 + std::sqrt(5.0)) / 2, inverse = 1 / phi;
        std::vector<Vec> corners;
        for (double s : {-1.0, 1.0})
            for (double t : {-1.0, 1.0}) {
                corners.push_back({0, s * inverse, t * phi});
                corners.push_back({s * inverse, t * phi, 0});
                corners.push_back({s * phi, 0, t * inverse});
                for (double u : {-1.0, 1.0}) corners.push_back({s, t, u});
            }
        return withFaces(corners);
    }();
    return p;
}

const Polyhedron& rhombicDodecahedron() {
    // freeglut's: poles on z, a ring of four at z = +-1/2 on the axes and four at z = 0 between.
    static const Polyhedron p = [] {
        const double h = std::sqrt(0.5);
        return withFaces({{0, 0, 1},
                          {h, 0, 0.5},
                          {0, h, 0.5},
                          {-h, 0, 0.5},
                          {0, -h, 0.5},
                          {h, h, 0},
                          {-h, h, 0},
                          {-h, -h, 0},
                          {h, -h, 0},
                          {h, 0, -0.5},
                          {0, h, -0.5},
                          {-h, 0, -0.5},
                          {0, -h, -0.5},
                          {0, 0, -1}});
    }();
    return p;
}

// Each face as a polygon (solid) or a closed outline (wire), scaled and moved.
void draw(const Polyhedron& p, bool wire, double scale = 1, const Vec& offset = {0, 0, 0}) {
    for (const Face& face : p.faces) {
        glBegin(wire ? GL_LINE_LOOP : GL_POLYGON);
        glNormal3dv(face.normal.data());
        for (int i : face.corners) {
            const Vec& c = p.corners[static_cast<std::size_t>(i)];
            glVertex3d(offset[0] + scale * c[0], offset[1] + scale * c[1], offset[2] + scale * c[2]);
        }
        glEnd();
    }
}

// Four half-size sponges at the tetrahedron's corners, down to tetrahedra. Past 8 levels
// (65536 tetrahedra, far below a pixel each) deeper ones would only take time.
constexpr int kMaxSpongeLevels = 8;

void sponge(int levels, const Vec& offset, double scale, bool wire) {
    levels = std::min(levels, kMaxSpongeLevels);
    if (levels <= 0) return draw(tetrahedron(), wire, scale, offset);
    for (const Vec& corner : tetrahedron().corners) {
        const double half = scale / 2;
        sponge(levels - 1, {offset[0] + half * corner[0], offset[1] + half * corner[1], offset[2] + half * corner[2]},
               half, wire);
    }
}

}  // namespace

void glutWireCube(double size) { draw(cube(), true, size); }
void glutSolidCube(double size) { draw(cube(), false, size); }
void glutWireTetrahedron() { draw(tetrahedron(), true); }
void glutSolidTetrahedron() { draw(tetrahedron(), false); }
void glutWireOctahedron() { draw(octahedron(), true); }
void glutSolidOctahedron() { draw(octahedron(), false); }
void glutWireDodecahedron() { draw(dodecahedron(), true); }
void glutSolidDodecahedron() { draw(dodecahedron(), false); }
void glutWireIcosahedron() { draw(icosahedron(), true); }
void glutSolidIcosahedron() { draw(icosahedron(), false); }
void glutWireRhombicDodecahedron() { draw(rhombicDodecahedron(), true); }
void glutSolidRhombicDodecahedron() { draw(rhombicDodecahedron(), false); }
void glutWireSierpinskiSponge(int levels, double offset[3], double scale) {
    sponge(levels, offset ? Vec{offset[0], offset[1], offset[2]} : Vec{0, 0, 0}, scale, true);
}
void glutSolidSierpinskiSponge(int levels, double offset[3], double scale) {
    sponge(levels, offset ? Vec{offset[0], offset[1], offset[2]} : Vec{0, 0, 0}, scale, false);
}
