#pragma once

namespace scenes {

void drawSmoothFan(int width, int height, int frame);
void drawPolygon5(int width, int height, int frame);
void drawNearPlaneMesh(int width, int height, int frame);
// Every glBegin triangle mode side by side, flat or smooth.
void drawAllModesFlat(int width, int height, int frame);
void drawAllModesSmooth(int width, int height, int frame);
void drawLinesAndPoints(int width, int height, int frame);
void drawWireframeCube(int width, int height, int frame);

}  // namespace scenes
