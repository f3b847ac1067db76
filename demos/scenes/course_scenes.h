#pragma once

namespace scenes {

// The course framework's scenes, switched with F1..F4 there.
void drawCourseF1(int width, int height, int frame);  // a quad, one color per vertex, transformed
void drawCourseF2(int width, int height, int frame);  // F1 and F3 together
void drawCourseF3(int width, int height, int frame);  // a red 5-vertex GL_POLYGON
void drawCourseF4(int width, int height, int frame);  // a triangle mesh loaded from an OBJ file

}  // namespace scenes
