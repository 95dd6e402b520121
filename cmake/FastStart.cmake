# Fast start-up for the pipeline's executables (docs/performance.md,
# "Start-up"). A map of lab_a's size is drawn or computed in tens of
# milliseconds, while loading the 28 shared libraries of a stage executable
# took 40 ms of CPU on the development machine: every library is mapped and
# relocated (Debian links them with BIND_NOW), each page it writes is a page
# fault (15-40 us on a virtual machine), and libopencv_imgproc.so alone runs
# a static initialiser that fills 1 MB of interpolation tables no stage uses.
#
# ag_fast_start(TARGET) links an executable
# - with the static archives that the Debian -dev packages of install-deps.sh
#   ship (libopencv_core.a, libopencv_imgproc.a, libprotobuf.a,
#   libsqlite3.a, libnettle.a, libzstd.a, libpng16.a, libz.a): the linker
#   takes only the object files used, resolves them at link time, and runs
#   only their initialisers;
# - without OpenCV's OpenGL interop (opengl_absent.cc answers its three glX
#   calls), so libGLX and the six X11 libraries behind it are not loaded;
# - as a position-dependent executable (-no-pie): a position-independent one
#   relocates its 0.5 MB of vtables and constant tables at every start, one
#   copy-on-write page fault per page. The cost: the executable itself is not
#   placed at a random address (its libraries, heap and stack still are).
# OpenCV's TBB backend, LAPACK, BLAS and LCM stay shared but are loaded on
# first use (common/lazy_libraries.cc); yaml-cpp is static too; libstdc++ and
# glibc stay shared (ag-render links them statically: ag_fully_static below).
#
# Everything else (the image-codecs module, tests, tools that link
# libopencv_imgcodecs) keeps the shared libraries: libopencv_imgcodecs.so
# needs the shared OpenCV core, and two copies of it in one process would
# share global state half-way. A fast-start executable that still loads the
# codecs (ag-import on a BMP or PGM, via libag_image_codecs.so) gets a
# separate, complete shared OpenCV behind that module; cv::Mat crosses the
# boundary through its allocator's virtual functions, as before.
#
# -DAG_FAST_START=OFF links every executable as before.
option(AG_FAST_START "link the pipeline's executables statically and non-PIE for a fast start-up"
  ON)

set(_ag_fast "$<BOOL:$<TARGET_PROPERTY:AG_FAST_START>>")
set(_ag_shared "$<NOT:${_ag_fast}>")

# ag_dependency(NAME SHARED_TARGET STATIC_ARCHIVE [STATIC_EXTRA...]): an
# interface target that links SHARED_TARGET, or STATIC_ARCHIVE and
# STATIC_EXTRA in a target marked by ag_fast_start. Its compile-time usage
# requirements (include directories, definitions) are SHARED_TARGET's.
function(ag_dependency name shared static)
  add_library(${name} INTERFACE)
  target_include_directories(${name} SYSTEM INTERFACE
    $<TARGET_PROPERTY:${shared},INTERFACE_INCLUDE_DIRECTORIES>)
  target_compile_definitions(${name} INTERFACE
    $<TARGET_PROPERTY:${shared},INTERFACE_COMPILE_DEFINITIONS>)
  set(libraries "$<${_ag_shared}:${shared}>")
  if(AG_FAST_START)
    foreach(library ${static} ${ARGN})
      list(APPEND libraries "$<${_ag_fast}:${library}>")
    endforeach()
  endif()
  target_link_libraries(${name} INTERFACE ${libraries})
endfunction()

# The static archive beside a shared library's file, e.g. libz.a for
# libz.so.1.2.13: its path in ${out}, or a fatal error.
function(ag_static_archive out name)
  find_library(${out} NAMES lib${name}.a)
  if(NOT ${out})
    message(FATAL_ERROR "AG_FAST_START: lib${name}.a not found (its -dev package ships it)")
  endif()
  set(${out} ${${out}} PARENT_SCOPE)
endfunction()

if(AG_FAST_START)
  foreach(name opencv_core opencv_imgproc protobuf sqlite3 nettle zstd png16 z)
    string(TOUPPER ${name} upper)
    ag_static_archive(AG_STATIC_${upper} ${name})
  endforeach()
  # The run-time names: libopencv-core406 brings liblapack.so.3 and
  # libblas.so.3, but not the -dev packages' liblapack.so and libblas.so.
  find_library(AG_TBB_LIBRARY tbb REQUIRED)
  find_library(AG_LAPACK_LIBRARY NAMES liblapack.so.3 lapack REQUIRED)
  find_library(AG_BLAS_LIBRARY NAMES libblas.so.3 blas REQUIRED)
  add_library(ag_opengl_absent STATIC ${CMAKE_SOURCE_DIR}/common/opengl_absent.cc)
  # GMP and MPFR (CGAL's exact numbers; libgmp-dev and libmpfr-dev come with
  # libcgal-dev) from their archives too: two shared libraries fewer, about
  # 0.6 ms of every start. CGAL's FindGMP and FindMPFR (in stages/) take
  # these variables as found and link what they name.
  find_library(AG_GMP_LIBRARY gmp REQUIRED)
  find_library(AG_GMPXX_LIBRARY gmpxx REQUIRED)
  find_library(AG_MPFR_LIBRARY mpfr REQUIRED)
  ag_static_archive(AG_STATIC_GMP gmp)
  ag_static_archive(AG_STATIC_GMPXX gmpxx)
  ag_static_archive(AG_STATIC_MPFR mpfr)
  find_path(GMP_INCLUDE_DIR gmp.h REQUIRED)
  find_path(GMPXX_INCLUDE_DIR gmpxx.h REQUIRED)
  find_path(MPFR_INCLUDE_DIR mpfr.h REQUIRED)
  set(GMP_LIBRARIES "$<IF:${_ag_fast},${AG_STATIC_GMP},${AG_GMP_LIBRARY}>")
  # GMP's C++ classes (CGAL's FindGMPXX) too: a fully static executable
  # (ag_fully_static) cannot link a shared library.
  set(GMPXX_LIBRARIES "$<IF:${_ag_fast},${AG_STATIC_GMPXX},${AG_GMPXX_LIBRARY}>")
  set(MPFR_LIBRARIES "$<IF:${_ag_fast},${AG_STATIC_MPFR},${AG_MPFR_LIBRARY}>")
  # TBB, LAPACK and BLAS are loaded on first use (common/lazy_libraries.cc):
  # OpenCV's static core calls them (cv::parallel_for_, cv::solve, cv::gemm),
  # but most runs of ag-render, ag-inspect and the stages never do, and
  # loading them (with libgfortran and libquadmath) was 2.5-3 ms of every
  # start (docs/performance.md, "Start-up"). lazy_libraries.sh
  # writes an entry point for each of their functions that the OpenCV
  # archives call (x86-64 only; elsewhere they are linked as before).
  # LCM too, with an entry point for each of its functions (--all): our own
  # code calls it, and ag-run only when it publishes; with glib and pcre2
  # behind it, it was 3 of the 9 libraries ag-run loaded at every start
  # (docs/performance.md, "Start-up"). Debian ships no liblcm.a.
  find_library(AG_LCM_LIBRARY NAMES liblcm.so.1 lcm REQUIRED)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$")
    set(entries ${CMAKE_BINARY_DIR}/lazy_library_entries.cc)
    execute_process(
      COMMAND sh ${CMAKE_SOURCE_DIR}/cmake/lazy_libraries.sh ${entries}.new ${CMAKE_NM}
        ${AG_STATIC_OPENCV_CORE} ${AG_STATIC_OPENCV_IMGPROC}
        -- ${AG_TBB_LIBRARY} ${AG_LAPACK_LIBRARY} ${AG_BLAS_LIBRARY} --all ${AG_LCM_LIBRARY}
      RESULT_VARIABLE status)
    if(status)
      message(FATAL_ERROR "AG_FAST_START: cmake/lazy_libraries.sh failed")
    endif()
    # Written only when it changed: configuring a built tree again relinks
    # nothing.
    execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${entries}.new ${entries})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
      ${CMAKE_SOURCE_DIR}/cmake/lazy_libraries.sh)
    add_library(ag_lazy_libraries STATIC ${CMAKE_SOURCE_DIR}/common/lazy_libraries.cc ${entries})
    target_include_directories(ag_lazy_libraries PRIVATE ${CMAKE_SOURCE_DIR})
    target_link_libraries(ag_lazy_libraries PRIVATE ${CMAKE_DL_LIBS})
    set(AG_OPENCV_RUNTIME ag_lazy_libraries)
    set(AG_LCM_RUNTIME ag_lazy_libraries)
  else()
    set(AG_OPENCV_RUNTIME "${AG_TBB_LIBRARY}" "${AG_LAPACK_LIBRARY}" "${AG_BLAS_LIBRARY}")
    set(AG_LCM_RUNTIME PkgConfig::LCM)
  endif()
  # yaml-cpp (ag-import's map_server YAML) from libyaml-cpp-dev's archive.
  ag_static_archive(AG_STATIC_YAML_CPP yaml-cpp)
endif()

# Static OpenCV is one item for both modules, imgproc before core (the
# linker takes from an archive only what is already asked for, and CMake does
# not order raw archive paths): libopencv_imgproc.a adds nothing to a target
# that uses core only. Then what libopencv_core.a needs beyond itself: TBB
# (cv::parallel_for_), LAPACK and BLAS (cv::solve and friends), loaded on
# first use; zlib (cv::FileStorage), and the glX answers.
ag_dependency(opencv_core opencv_core_shared "${AG_STATIC_OPENCV_IMGPROC}"
  "${AG_STATIC_OPENCV_CORE}" ag_opengl_absent ${AG_OPENCV_RUNTIME} "${AG_STATIC_Z}"
  ${CMAKE_DL_LIBS} Threads::Threads)
ag_dependency(opencv_imgproc opencv_imgproc_shared opencv_core)
ag_dependency(ag_protobuf protobuf::libprotobuf "${AG_STATIC_PROTOBUF}" "${AG_STATIC_Z}"
  Threads::Threads)
ag_dependency(ag_sqlite SQLite::SQLite3 "${AG_STATIC_SQLITE3}" ${CMAKE_DL_LIBS} Threads::Threads
  m)
ag_dependency(ag_crypto PkgConfig::NETTLE "${AG_STATIC_NETTLE}")
ag_dependency(ag_zstd zstd::libzstd_shared "${AG_STATIC_ZSTD}")
ag_dependency(ag_png PNG::PNG "${AG_STATIC_PNG16}" "${AG_STATIC_Z}" m)
ag_dependency(ag_yaml_cpp yaml-cpp "${AG_STATIC_YAML_CPP}")
# LCM's C API, loaded on first use (above); glib's headers come with it.
ag_dependency(ag_lcm PkgConfig::LCM "${AG_LCM_RUNTIME}" ${CMAKE_DL_LIBS})

# libopencv_imgcodecs.so loads the shared OpenCV core: not in a fast-start
# executable (see above); the link fails naming this rule.
add_library(opencv_imgcodecs INTERFACE)
target_link_libraries(opencv_imgcodecs INTERFACE
  "$<${_ag_shared}:opencv_imgcodecs_shared>"
  "$<${_ag_fast}:ag_fast_start_executables_cannot_link_opencv_imgcodecs>")
target_include_directories(opencv_imgcodecs SYSTEM INTERFACE
  $<TARGET_PROPERTY:opencv_imgcodecs_shared,INTERFACE_INCLUDE_DIRECTORIES>)

# ag_fast_start(TARGET...): marks executables for the static, non-PIE link.
function(ag_fast_start)
  if(NOT AG_FAST_START)
    return()
  endif()
  foreach(target ${ARGN})
    set_property(TARGET ${target} PROPERTY AG_FAST_START ON)
    target_link_options(${target} PRIVATE -no-pie)
  endforeach()
endfunction()

# ag_fast_start_own_runtime(TARGET...): a fast-start executable that also
# links libstdc++ and libgcc statically, which saves about 3 ms of every
# start (resolving libstdc++'s thousands of symbols; docs/performance.md,
# "Start-up"). Only for a program that never loads a shared library
# that brings libstdc++.so: it would hold a second C++ runtime. So the program
# calls cv::setNumThreads(0) first (OpenCV then never loads TBB) and never
# reaches the image-codecs module (ag-render: its pictures are 8-bit, which
# libpng writes directly).
function(ag_fast_start_own_runtime)
  if(NOT AG_FAST_START)
    return()
  endif()
  foreach(target ${ARGN})
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
  endforeach()
endfunction()

# ag_fully_static(TARGET...): a fast-start executable with its own runtime
# (above) that links glibc statically too (-static): no dynamic loader, no
# libc.so or libm.so to map and relocate. lab_a's import picture took 1.4 ms
# less CPU of 10.4 (docs/performance.md, "Start-up"). Such a program
# loads no library at run time: common/lazy_libraries.cc refuses to (its
# callers, TBB's, LAPACK's and LCM's, are never reached in ag-render), it
# must never read an image through the codecs module, and its dlopen finds
# nothing (common/no_dynamic_loading.cc).
function(ag_fully_static)
  if(NOT AG_FAST_START)
    return()
  endif()
  foreach(target ${ARGN})
    ag_fast_start_own_runtime(${target})
    # Exceptions unwind through the link-time table of PT_GNU_EH_FRAME, not
    # libgcc's registry of frames (common/no_frame_registry.cc); dlopen finds
    # nothing (common/no_dynamic_loading.cc).
    target_sources(${target} PRIVATE ${CMAKE_SOURCE_DIR}/common/no_frame_registry.cc
      ${CMAKE_SOURCE_DIR}/common/no_dynamic_loading.cc)
    target_link_options(${target} PRIVATE -static -Wl,--eh-frame-hdr
      -Wl,--wrap=__register_frame_info -Wl,--wrap=__deregister_frame_info -Wl,--wrap=dlopen)
  endforeach()
endfunction()
