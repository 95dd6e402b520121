// For fully static executables (cmake/FastStart.cmake, ag_fully_static),
// linked with --wrap=dlopen. Such a program loads no library: our own
// callers refuse first (common/static_program.h), and those in the static
// archives (OpenCV's OpenCL and plugin loaders, SQLite's extensions) are
// never reached by ag-render. Answering "not found" here keeps glibc's
// static dlopen out of the link: it could only load libraries built for the
// very glibc it was linked with, beside the program's own copy, and the
// linker warned about it at every build.

extern "C" void* __wrap_dlopen(const char* /*file*/, int /*mode*/) { return nullptr; }
