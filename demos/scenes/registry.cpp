#include <vector>

#include "bench_scenes.h"
#include "course_scenes.h"
#include "primitive_scenes.h"
#include "scene.h"
#include "seed_scenes.h"

namespace scenes {

std::span<const Scene> allScenes() {
    static const std::vector<Scene> scenes{
        {"course-f1", "course F1: a quad with one color per vertex, translated, rotated, scaled", drawCourseF1},
        {"course-f2", "course F2: F1 and F3 together", drawCourseF2},
        {"course-f3", "course F3: a red 5-vertex GL_POLYGON", drawCourseF3},
        {"course-f4", "course F4: a sphere mesh loaded from an OBJ file, culling and depth", drawCourseF4},
        {"cube", "rotating cube, six colored faces, back-face culling and depth test", drawRotatingCube},
        {"two-cubes", "two cubes at different depths, depth test on", drawTwoCubesDepth},
        {"two-cubes-nodepth", "two cubes, depth test off: the far one paints over the near one", drawTwoCubesNoDepth},
        {"concave-hexahedron", "a hexahedron whose faces overlap, culling and depth test", drawConcaveHexahedronDepth},
        {"concave-hexahedron-nodepth", "the concave hexahedron with culling only", drawConcaveHexahedronNoDepth},
        {"xmutual", "two intersecting quads, depth test on", drawIntersectingQuadsDepth},
        {"xmutual-nodepth", "two intersecting quads, depth test off", drawIntersectingQuadsNoDepth},
        {"smooth-fan", "a smooth-shaded triangle fan", drawSmoothFan},
        {"polygon5", "a red 5-vertex GL_POLYGON", drawPolygon5},
        {"near-plane", "a quad mesh crossing the near plane, perspective and depth", drawNearPlaneMesh},
        {"modes-flat", "every triangle mode, flat shading", drawAllModesFlat},
        {"modes-smooth", "every triangle mode, smooth shading", drawAllModesSmooth},
        {"lines-points", "line strips of widths 1-3, a line loop, points of sizes 1-4", drawLinesAndPoints},
        {"wireframe-cube", "the cube in glPolygonMode GL_LINE with culling", drawWireframeCube},
        {"bench-torus", "benchmark: a 65k-triangle smooth torus, depth and culling", drawBenchTorus},
        {"bench-fill", "benchmark: 32 full-window depth-tested quads (fill rate)", drawBenchFill},
        {"bench-cubes", "benchmark: 1000 cubes drawn with push/translate/rotate", drawBenchCubes},
        {"bench-tiny", "benchmark: 100k tiny triangles", drawBenchTiny},
        {"bench-gears", "benchmark: three flat-shaded gears", drawBenchGears},
        {"bench-gears-lists", "benchmark: the three gears from display lists", drawBenchGearsLists},
        {"bench-mesh", "benchmark: a 100k-triangle terrain through glDrawElements", drawBenchMesh},
        {"bench-lit-torus", "benchmark: a 16k-triangle torus lit by a spot and a directional light, specular",
         drawBenchLitTorus},
        {"bench-fog-terrain", "benchmark: the 100k-triangle terrain under LINEAR fog, depth-tested",
         drawBenchFogTerrain},
        {"bench-fog-textured-terrain",
         "benchmark: the fogged terrain with a repeating ground texture (64x64 mipmaps, LINEAR_MIPMAP_LINEAR, "
         "MODULATE)",
         drawBenchFogTexturedTerrain},
        {"bench-particles", "benchmark: 2000 alpha-blended quads and points, depth-tested without writes",
         drawBenchParticles},
        {"bench-textured-cubes", "benchmark: the 1000 cubes textured (64x64 mipmaps, LINEAR_MIPMAP_LINEAR, MODULATE)",
         drawBenchTexturedCubes},
        {"bench-draw-pixels", "benchmark: a 256x256 RGBA image drawn with glDrawPixels, zoomed over the window",
         drawBenchDrawPixels},
    };
    return scenes;
}

const Scene* findScene(std::string_view name) {
    for (const Scene& scene : allScenes())
        if (scene.name == name) return &scene;
    return nullptr;
}

}  // namespace scenes
