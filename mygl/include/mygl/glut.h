/* MyGL's GLUT: freeglut's API for what course programs call, in C and C++. Replace
 * `#include <GL/glut.h>` (or <GL/freeglut.h>) with `#include <mygl/glut.h>` and link mygl::glut;
 * no other line changes. Every gl* and glu* call goes through the loaded GL table (<glad/gl.h>),
 * and the environment chooses the backend:
 *   MYGL_BACKEND=mygl (default) | osmesa | compare   (compare: MyGL, checked against OSMesa)
 *   MYGL_CAPTURE=N:DIR   headless: every glutSwapBuffers (or display callback) is a frame; N
 *                        frames go to DIR/frame-NNN-*.png, then the program exits
 * Without MYGL_CAPTURE a GLFW window shows the frames (MYGL_SCREENSHOT=FILE.png saves what the
 * window shows after its first frame, then exits). The names and values are freeglut's. */
#ifndef MYGL_GLUT_H
#define MYGL_GLUT_H

#include <stdlib.h> /* GLUT's header brings exit() to its programs */

#include <glad/gl.h>
#include <mygl/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FREEGLUT 1
#define GLUT_API_VERSION 4
#define FREEGLUT_VERSION_2_0 1
#define GLUT_XLIB_IMPLEMENTATION 13

/* Display mode bits (glutInitDisplayMode) */
#define GLUT_RGB 0x0000
#define GLUT_RGBA 0x0000
#define GLUT_INDEX 0x0001
#define GLUT_SINGLE 0x0000
#define GLUT_DOUBLE 0x0002
#define GLUT_ACCUM 0x0004
#define GLUT_ALPHA 0x0008
#define GLUT_DEPTH 0x0010
#define GLUT_STENCIL 0x0020
#define GLUT_MULTISAMPLE 0x0080
#define GLUT_STEREO 0x0100
#define GLUT_LUMINANCE 0x0200
#define GLUT_AUX 0x1000
#define GLUT_AUX1 0x1000
#define GLUT_AUX2 0x2000
#define GLUT_AUX3 0x4000
#define GLUT_AUX4 0x8000
#define GLUT_SRGB 0x1000
#define GLUT_BORDERLESS 0x0800
#define GLUT_CAPTIONLESS 0x0400

/* Mouse buttons and states */
#define GLUT_LEFT_BUTTON 0x0000
#define GLUT_MIDDLE_BUTTON 0x0001
#define GLUT_RIGHT_BUTTON 0x0002
#define GLUT_DOWN 0x0000
#define GLUT_UP 0x0001
#define GLUT_LEFT 0x0000
#define GLUT_ENTERED 0x0001

/* Special keys */
#define GLUT_KEY_F1 0x0001
#define GLUT_KEY_F2 0x0002
#define GLUT_KEY_F3 0x0003
#define GLUT_KEY_F4 0x0004
#define GLUT_KEY_F5 0x0005
#define GLUT_KEY_F6 0x0006
#define GLUT_KEY_F7 0x0007
#define GLUT_KEY_F8 0x0008
#define GLUT_KEY_F9 0x0009
#define GLUT_KEY_F10 0x000A
#define GLUT_KEY_F11 0x000B
#define GLUT_KEY_F12 0x000C
#define GLUT_KEY_LEFT 0x0064
#define GLUT_KEY_UP 0x0065
#define GLUT_KEY_RIGHT 0x0066
#define GLUT_KEY_DOWN 0x0067
#define GLUT_KEY_PAGE_UP 0x0068
#define GLUT_KEY_PAGE_DOWN 0x0069
#define GLUT_KEY_HOME 0x006A
#define GLUT_KEY_END 0x006B
#define GLUT_KEY_INSERT 0x006C
#define GLUT_KEY_NUM_LOCK 0x006D
#define GLUT_KEY_BEGIN 0x006E
#define GLUT_KEY_DELETE 0x006F
#define GLUT_KEY_SHIFT_L 0x0070
#define GLUT_KEY_SHIFT_R 0x0071
#define GLUT_KEY_CTRL_L 0x0072
#define GLUT_KEY_CTRL_R 0x0073
#define GLUT_KEY_ALT_L 0x0074
#define GLUT_KEY_ALT_R 0x0075
#define GLUT_KEY_SUPER_L 0x0076
#define GLUT_KEY_SUPER_R 0x0077

/* glutGetModifiers */
#define GLUT_ACTIVE_SHIFT 0x0001
#define GLUT_ACTIVE_CTRL 0x0002
#define GLUT_ACTIVE_ALT 0x0004
#define GLUT_ACTIVE_SUPER 0x0008

/* Menu, visibility and window status callbacks */
#define GLUT_MENU_NOT_IN_USE 0x0000
#define GLUT_MENU_IN_USE 0x0001
#define GLUT_NOT_VISIBLE 0x0000
#define GLUT_VISIBLE 0x0001
#define GLUT_HIDDEN 0x0000
#define GLUT_FULLY_RETAINED 0x0001
#define GLUT_PARTIALLY_RETAINED 0x0002
#define GLUT_FULLY_COVERED 0x0003

/* Colour index components and layers */
#define GLUT_RED 0x0000
#define GLUT_GREEN 0x0001
#define GLUT_BLUE 0x0002
#define GLUT_NORMAL 0x0000
#define GLUT_OVERLAY 0x0001

/* glutGet */
#define GLUT_WINDOW_X 0x0064
#define GLUT_WINDOW_Y 0x0065
#define GLUT_WINDOW_WIDTH 0x0066
#define GLUT_WINDOW_HEIGHT 0x0067
#define GLUT_WINDOW_BUFFER_SIZE 0x0068
#define GLUT_WINDOW_STENCIL_SIZE 0x0069
#define GLUT_WINDOW_DEPTH_SIZE 0x006A
#define GLUT_WINDOW_RED_SIZE 0x006B
#define GLUT_WINDOW_GREEN_SIZE 0x006C
#define GLUT_WINDOW_BLUE_SIZE 0x006D
#define GLUT_WINDOW_ALPHA_SIZE 0x006E
#define GLUT_WINDOW_ACCUM_RED_SIZE 0x006F
#define GLUT_WINDOW_ACCUM_GREEN_SIZE 0x0070
#define GLUT_WINDOW_ACCUM_BLUE_SIZE 0x0071
#define GLUT_WINDOW_ACCUM_ALPHA_SIZE 0x0072
#define GLUT_WINDOW_DOUBLEBUFFER 0x0073
#define GLUT_WINDOW_RGBA 0x0074
#define GLUT_WINDOW_PARENT 0x0075
#define GLUT_WINDOW_NUM_CHILDREN 0x0076
#define GLUT_WINDOW_COLORMAP_SIZE 0x0077
#define GLUT_WINDOW_NUM_SAMPLES 0x0078
#define GLUT_WINDOW_STEREO 0x0079
#define GLUT_WINDOW_CURSOR 0x007A
#define GLUT_WINDOW_FORMAT_ID 0x007B
#define GLUT_INIT_STATE 0x007C
#define GLUT_WINDOW_SRGB 0x007D
#define GLUT_SCREEN_WIDTH 0x00C8
#define GLUT_SCREEN_HEIGHT 0x00C9
#define GLUT_SCREEN_WIDTH_MM 0x00CA
#define GLUT_SCREEN_HEIGHT_MM 0x00CB
#define GLUT_MENU_NUM_ITEMS 0x012C
#define GLUT_DISPLAY_MODE_POSSIBLE 0x0190
#define GLUT_INIT_WINDOW_X 0x01F4
#define GLUT_INIT_WINDOW_Y 0x01F5
#define GLUT_INIT_WINDOW_WIDTH 0x01F6
#define GLUT_INIT_WINDOW_HEIGHT 0x01F7
#define GLUT_INIT_DISPLAY_MODE 0x01F8
#define GLUT_ACTION_ON_WINDOW_CLOSE 0x01F9
#define GLUT_WINDOW_BORDER_WIDTH 0x01FA
#define GLUT_WINDOW_BORDER_HEIGHT 0x01FB
#define GLUT_VERSION 0x01FC
#define GLUT_RENDERING_CONTEXT 0x01FD
#define GLUT_DIRECT_RENDERING 0x01FE
#define GLUT_FULL_SCREEN 0x01FF
#define GLUT_ELAPSED_TIME 0x02BC
#define GLUT_INIT_MAJOR_VERSION 0x0200
#define GLUT_INIT_MINOR_VERSION 0x0201
#define GLUT_INIT_FLAGS 0x0202
#define GLUT_INIT_PROFILE 0x0203
#define GLUT_SKIP_STALE_MOTION_EVENTS 0x0204
#define GLUT_GEOMETRY_VISUALIZE_NORMALS 0x0205

/* glutSetOption values */
#define GLUT_ACTION_EXIT 0
#define GLUT_ACTION_GLUTMAINLOOP_RETURNS 1
#define GLUT_ACTION_CONTINUE_EXECUTION 2
#define GLUT_CREATE_NEW_CONTEXT 0
#define GLUT_USE_CURRENT_CONTEXT 1
#define GLUT_DEBUG 0x0001
#define GLUT_FORWARD_COMPATIBLE 0x0002
#define GLUT_CORE_PROFILE 0x0001
#define GLUT_COMPATIBILITY_PROFILE 0x0002

/* glutDeviceGet */
#define GLUT_HAS_KEYBOARD 0x0258
#define GLUT_HAS_MOUSE 0x0259
#define GLUT_HAS_SPACEBALL 0x025A
#define GLUT_HAS_DIAL_AND_BUTTON_BOX 0x025B
#define GLUT_HAS_TABLET 0x025C
#define GLUT_NUM_MOUSE_BUTTONS 0x025D
#define GLUT_NUM_SPACEBALL_BUTTONS 0x025E
#define GLUT_NUM_BUTTON_BOX_BUTTONS 0x025F
#define GLUT_NUM_DIALS 0x0260
#define GLUT_NUM_TABLET_BUTTONS 0x0261
#define GLUT_DEVICE_IGNORE_KEY_REPEAT 0x0262
#define GLUT_DEVICE_KEY_REPEAT 0x0263
#define GLUT_HAS_JOYSTICK 0x0264
#define GLUT_OWNS_JOYSTICK 0x0265
#define GLUT_JOYSTICK_BUTTONS 0x0266
#define GLUT_JOYSTICK_AXES 0x0267
#define GLUT_JOYSTICK_POLL_RATE 0x0268

/* glutLayerGet */
#define GLUT_OVERLAY_POSSIBLE 0x0320
#define GLUT_LAYER_IN_USE 0x0321
#define GLUT_HAS_OVERLAY 0x0322
#define GLUT_TRANSPARENT_INDEX 0x0323
#define GLUT_NORMAL_DAMAGED 0x0324
#define GLUT_OVERLAY_DAMAGED 0x0325

/* glutSetKeyRepeat */
#define GLUT_KEY_REPEAT_OFF 0x0000
#define GLUT_KEY_REPEAT_ON 0x0001
#define GLUT_KEY_REPEAT_DEFAULT 0x0002

/* glutSetCursor */
#define GLUT_CURSOR_RIGHT_ARROW 0x0000
#define GLUT_CURSOR_LEFT_ARROW 0x0001
#define GLUT_CURSOR_INFO 0x0002
#define GLUT_CURSOR_DESTROY 0x0003
#define GLUT_CURSOR_HELP 0x0004
#define GLUT_CURSOR_CYCLE 0x0005
#define GLUT_CURSOR_SPRAY 0x0006
#define GLUT_CURSOR_WAIT 0x0007
#define GLUT_CURSOR_TEXT 0x0008
#define GLUT_CURSOR_CROSSHAIR 0x0009
#define GLUT_CURSOR_UP_DOWN 0x000A
#define GLUT_CURSOR_LEFT_RIGHT 0x000B
#define GLUT_CURSOR_TOP_SIDE 0x000C
#define GLUT_CURSOR_BOTTOM_SIDE 0x000D
#define GLUT_CURSOR_LEFT_SIDE 0x000E
#define GLUT_CURSOR_RIGHT_SIDE 0x000F
#define GLUT_CURSOR_TOP_LEFT_CORNER 0x0010
#define GLUT_CURSOR_TOP_RIGHT_CORNER 0x0011
#define GLUT_CURSOR_BOTTOM_RIGHT_CORNER 0x0012
#define GLUT_CURSOR_BOTTOM_LEFT_CORNER 0x0013
#define GLUT_CURSOR_INHERIT 0x0064
#define GLUT_CURSOR_NONE 0x0065
#define GLUT_CURSOR_FULL_CROSSHAIR 0x0066

/* Fonts: handles are the addresses of these objects, as in freeglut on X11. */
extern void* glutStrokeRoman;
extern void* glutStrokeMonoRoman;
extern void* glutBitmap9By15;
extern void* glutBitmap8By13;
extern void* glutBitmapTimesRoman10;
extern void* glutBitmapTimesRoman24;
extern void* glutBitmapHelvetica10;
extern void* glutBitmapHelvetica12;
extern void* glutBitmapHelvetica18;
#define GLUT_STROKE_ROMAN ((void*)&glutStrokeRoman)
#define GLUT_STROKE_MONO_ROMAN ((void*)&glutStrokeMonoRoman)
#define GLUT_BITMAP_9_BY_15 ((void*)&glutBitmap9By15)
#define GLUT_BITMAP_8_BY_13 ((void*)&glutBitmap8By13)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void*)&glutBitmapTimesRoman10)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void*)&glutBitmapTimesRoman24)
#define GLUT_BITMAP_HELVETICA_10 ((void*)&glutBitmapHelvetica10)
#define GLUT_BITMAP_HELVETICA_12 ((void*)&glutBitmapHelvetica12)
#define GLUT_BITMAP_HELVETICA_18 ((void*)&glutBitmapHelvetica18)

/* Initialisation and the main loop */
void glutInit(int* argcp, char** argv);
void glutInitWindowPosition(int x, int y);
void glutInitWindowSize(int width, int height);
void glutInitDisplayMode(unsigned int displayMode);
void glutInitDisplayString(const char* displayMode);
void glutInitContextVersion(int majorVersion, int minorVersion);
void glutInitContextFlags(int flags);
void glutInitContextProfile(int profile);
void glutMainLoop(void);
void glutMainLoopEvent(void);
void glutLeaveMainLoop(void);
void glutExit(void);
void glutSetOption(GLenum optionFlag, int value);

/* Windows (one window; what a headless run cannot show is accepted and ignored) */
int glutCreateWindow(const char* title);
void glutDestroyWindow(int window);
void glutSetWindow(int window);
int glutGetWindow(void);
void glutSetWindowTitle(const char* title);
void glutSetIconTitle(const char* title);
void glutReshapeWindow(int width, int height);
void glutPositionWindow(int x, int y);
void glutShowWindow(void);
void glutHideWindow(void);
void glutIconifyWindow(void);
void glutPushWindow(void);
void glutPopWindow(void);
void glutFullScreen(void);
void glutLeaveFullScreen(void);
void glutFullScreenToggle(void);
void glutPostRedisplay(void);
void glutPostWindowRedisplay(int window);
void glutSwapBuffers(void);
void glutWarpPointer(int x, int y);
void glutSetCursor(int cursor);
void glutIgnoreKeyRepeat(int ignore);
void glutSetKeyRepeat(int repeatMode);

/* Callbacks */
void glutDisplayFunc(void (*callback)(void));
void glutReshapeFunc(void (*callback)(int width, int height));
void glutKeyboardFunc(void (*callback)(unsigned char key, int x, int y));
void glutKeyboardUpFunc(void (*callback)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*callback)(int key, int x, int y));
void glutSpecialUpFunc(void (*callback)(int key, int x, int y));
void glutMouseFunc(void (*callback)(int button, int state, int x, int y));
void glutMouseWheelFunc(void (*callback)(int wheel, int direction, int x, int y));
void glutMotionFunc(void (*callback)(int x, int y));
void glutPassiveMotionFunc(void (*callback)(int x, int y));
void glutEntryFunc(void (*callback)(int state));
void glutVisibilityFunc(void (*callback)(int state));
void glutWindowStatusFunc(void (*callback)(int state));
void glutIdleFunc(void (*callback)(void));
void glutTimerFunc(unsigned int milliseconds, void (*callback)(int value), int value);
void glutMenuStateFunc(void (*callback)(int state));
void glutMenuStatusFunc(void (*callback)(int status, int x, int y));
void glutCloseFunc(void (*callback)(void));
void glutWMCloseFunc(void (*callback)(void));

/* State */
int glutGet(GLenum query);
int glutDeviceGet(GLenum query);
int glutLayerGet(GLenum query);
int glutGetModifiers(void);
int glutExtensionSupported(const char* extension);

/* Menus (in the window a right click opens them as a list; headless they are accepted) */
int glutCreateMenu(void (*callback)(int value));
void glutDestroyMenu(int menu);
int glutGetMenu(void);
void glutSetMenu(int menu);
void glutAddMenuEntry(const char* label, int value);
void glutAddSubMenu(const char* label, int subMenu);
void glutChangeToMenuEntry(int item, const char* label, int value);
void glutChangeToSubMenu(int item, const char* label, int subMenu);
void glutRemoveMenuItem(int item);
void glutAttachMenu(int button);
void glutDetachMenu(int button);

/* Fonts: bitmap fonts draw with glBitmap at the raster position, stroke fonts with lines */
void glutBitmapCharacter(void* font, int character);
int glutBitmapWidth(void* font, int character);
int glutBitmapHeight(void* font);
int glutBitmapLength(void* font, const unsigned char* string);
void glutBitmapString(void* font, const unsigned char* string);
void glutStrokeCharacter(void* font, int character);
int glutStrokeWidth(void* font, int character);
GLfloat glutStrokeWidthf(void* font, int character);
GLfloat glutStrokeHeight(void* font);
int glutStrokeLength(void* font, const unsigned char* string);
GLfloat glutStrokeLengthf(void* font, const unsigned char* string);
void glutStrokeString(void* font, const unsigned char* string);

/* Shapes, with normals (the teapot also with texture coordinates) */
void glutWireCube(double size);
void glutSolidCube(double size);
void glutWireSphere(double radius, GLint slices, GLint stacks);
void glutSolidSphere(double radius, GLint slices, GLint stacks);
void glutWireCone(double base, double height, GLint slices, GLint stacks);
void glutSolidCone(double base, double height, GLint slices, GLint stacks);
void glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutWireCylinder(double radius, double height, GLint slices, GLint stacks);
void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks);
void glutWireTetrahedron(void);
void glutSolidTetrahedron(void);
void glutWireOctahedron(void);
void glutSolidOctahedron(void);
void glutWireDodecahedron(void);
void glutSolidDodecahedron(void);
void glutWireIcosahedron(void);
void glutSolidIcosahedron(void);
void glutWireRhombicDodecahedron(void);
void glutSolidRhombicDodecahedron(void);
void glutWireSierpinskiSponge(int levels, double offset[3], double scale);
void glutSolidSierpinskiSponge(int levels, double offset[3], double scale);
void glutWireTeapot(double size);
void glutSolidTeapot(double size);

#ifdef __cplusplus
}
#endif

#endif /* MYGL_GLUT_H */
