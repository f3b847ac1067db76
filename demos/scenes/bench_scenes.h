#pragma once

namespace scenes {

// The benchmark's scenes: each stresses one part of the pipeline.
void drawBenchTorus(int width, int height, int frame);       // 65k smooth triangles, depth and culling
void drawBenchFill(int width, int height, int frame);        // 32 full-window quads, depth-tested: fill rate
void drawBenchCubes(int width, int height, int frame);       // 1000 cubes with push/translate/rotate
void drawBenchTiny(int width, int height, int frame);        // 100k tiny triangles
void drawBenchGears(int width, int height, int frame);       // three gears: flat-shaded strips and quads
void drawBenchGearsLists(int width, int height, int frame);  // the same gears from display lists
void drawBenchMesh(int width, int height, int frame);        // a 100k-triangle mesh through glDrawElements
void drawBenchLitTorus(int width, int height, int frame);    // 16k triangles lit by a spot and a directional light
void drawBenchFogTerrain(int width, int height, int frame);  // the mesh's terrain under LINEAR fog
void drawBenchFogTexturedTerrain(int width, int height,
                                 int frame);                    // the fogged terrain with a mipmapped ground texture
void drawBenchParticles(int width, int height, int frame);      // 2000 alpha-blended quads and points over a floor
void drawBenchTexturedCubes(int width, int height, int frame);  // bench-cubes textured: mipmaps, LINEAR_MIPMAP_LINEAR
void drawBenchDrawPixels(int width, int height, int frame);     // a 256x256 RGBA image, zoomed over the window

}  // namespace scenes
