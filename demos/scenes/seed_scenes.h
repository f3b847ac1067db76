#pragma once

namespace scenes {

void drawRotatingCube(int width, int height, int frame);
void drawTwoCubesDepth(int width, int height, int frame);
void drawTwoCubesNoDepth(int width, int height, int frame);
void drawConcaveHexahedronDepth(int width, int height, int frame);
void drawConcaveHexahedronNoDepth(int width, int height, int frame);
void drawIntersectingQuadsDepth(int width, int height, int frame);
void drawIntersectingQuadsNoDepth(int width, int height, int frame);

}  // namespace scenes
