// For fully static executables (cmake/FastStart.cmake, ag_fully_static),
// linked with --wrap for these two functions. crtbeginT.o, the start file of
// a -static link, registers the program's .eh_frame with libgcc, whose
// unwinder then searches that registry before anything else and, at the
// first exception, sorts every FDE of the program: 87 M instructions (7 ms)
// in ag-render, whose command line throws for --help and for every error.
// Unregistered, the unwinder asks glibc's _dl_find_object for the
// PT_GNU_EH_FRAME header (the link adds it with --eh-frame-hdr), whose table
// is sorted at link time, as in a dynamically linked program.

extern "C" {

void __wrap___register_frame_info(const void* /*begin*/, void* /*object*/) {}

// What crtbeginT.o's exit code calls for the object it registered: nothing
// to remove.
void* __wrap___deregister_frame_info(const void* /*begin*/) { return nullptr; }

}  // extern "C"
