#include "course_scenes.h"

#include <glad/gl.h>
#include <mygl/glu.h>
#include <tiny_obj_loader.h>

#include <stdexcept>
#include <vector>

#include "scene.h"

namespace scenes {
namespace {

void quad(int frame) {
    glPushMatrix();
    glTranslatef(-0.45f, 0.1f, 0.0f);
    glRotatef(20.0f + 9.0f * static_cast<float>(frame), 0.0f, 0.0f, 1.0f);
    glScalef(0.8f, 0.6f, 1.0f);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(-0.5f, -0.5f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(0.5f, -0.5f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(0.5f, 0.5f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(-0.5f, 0.5f);
    glEnd();
    glPopMatrix();
}

void redPolygon() {
    glColor3f(1.0f, 0.0f, 0.0f);
    glBegin(GL_POLYGON);
    glVertex2f(0.35f, -0.55f);
    glVertex2f(0.85f, -0.4f);
    glVertex2f(0.9f, 0.15f);
    glVertex2f(0.55f, 0.5f);
    glVertex2f(0.2f, 0.05f);
    glEnd();
}

struct Mesh {
    std::vector<float> positions, normals;  // three floats per corner, three corners per triangle
};

// The OBJ file shipped with the demos (a generated UV sphere), loaded once.
const Mesh& sphereMesh() {
    static const Mesh mesh = [] {
        tinyobj::ObjReader reader;
        const std::string path = std::string(MYGL_SCENE_DATA_DIR) + "/sphere.obj";
        if (!reader.ParseFromFile(path)) throw std::runtime_error("cannot load " + path + ": " + reader.Error());
        const tinyobj::attrib_t& attrib = reader.GetAttrib();
        Mesh m;
        for (const tinyobj::shape_t& shape : reader.GetShapes())
            for (const tinyobj::index_t& index : shape.mesh.indices)
                for (int k = 0; k < 3; ++k) {
                    m.positions.push_back(attrib.vertices[static_cast<std::size_t>(3 * index.vertex_index + k)]);
                    m.normals.push_back(attrib.normals[static_cast<std::size_t>(3 * index.normal_index + k)]);
                }
        return m;
    }();
    return mesh;
}

}  // namespace

void drawCourseF1(int width, int height, int frame) {
    beginFrame(width, height, false, false);
    quad(frame);
}

void drawCourseF2(int width, int height, int frame) {
    beginFrame(width, height, false, false);
    quad(frame);
    redPolygon();
}

void drawCourseF3(int width, int height, int) {
    beginFrame(width, height, false, false);
    redPolygon();
}

void drawCourseF4(int width, int height, int frame) {
    beginFrame(width, height, true, true);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(45.0, static_cast<double>(width) / height, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(0.0, 0.8, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(15.0f + 6.0f * static_cast<float>(frame), 0.0f, 1.0f, 0.0f);
    const Mesh& mesh = sphereMesh();
    glBegin(GL_TRIANGLES);  // colored by the normal, as no lighting is modeled
    for (std::size_t i = 0; i + 2 < mesh.positions.size(); i += 3) {
        glColor3f(0.5f + 0.5f * mesh.normals[i], 0.5f + 0.5f * mesh.normals[i + 1], 0.5f + 0.5f * mesh.normals[i + 2]);
        glVertex3fv(&mesh.positions[i]);
    }
    glEnd();
}

}  // namespace scenes
