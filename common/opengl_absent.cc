// OpenCV's OpenGL interop (cv::ogl) in an executable linked with
// libopencv_core.a (cmake/FastStart.cmake): Debian builds OpenCV with OpenGL,
// so libopencv_core.a's opengl.cpp.o asks GLX for OpenGL's functions. No
// code of this project uses cv::ogl; these answers keep libGLX and the six
// X11 libraries behind it out of every start-up. Should cv::ogl ever be
// called, OpenCV finds no OpenGL context and no function, and throws
// cv::Exception as it does on a machine without OpenGL.

extern "C" {

// glXGetProcAddressARB: no OpenGL function is available.
void* glXGetProcAddressARB(const unsigned char* /*name*/) { return nullptr; }

// glXGetCurrentContext and glXGetCurrentDisplay: there is no current context.
void* glXGetCurrentContext() { return nullptr; }
void* glXGetCurrentDisplay() { return nullptr; }

}  // extern "C"
