# Compile time is a budget (issue 29): what each choice saves is measured in the README
# ("Development"), with the commands that measure it.
#
# - ccache, when installed (scripts/setup.sh installs it), caches every compilation: a rebuild
#   after `git checkout`, a second build folder of the same compiler and flags, or the next CI
#   run on the same machine reuse the objects. Depend mode (no preprocessor run: the compiler's
#   own -MD list) keeps a cold cache nearly free; the sloppiness lets precompiled headers be
#   cached. Paths below the checkout are hashed relative to it (base_dir, no hash of the build
#   folder's own path): a clean checkout elsewhere -- CI's, a fresh clone -- reuses the objects
#   an earlier build of the same sources made. So no compile definition may hold a path of the
#   checkout (tests/TestPaths.h); Qt6::Test's own two (QT_TESTCASE_SOURCEDIR and _BUILDDIR,
#   used by QFINDTESTDATA only, which no test uses) are left out of the hash.
# - lld links (when installed): several times faster than ld.bfd, which matters most for the
#   relinks after an edit.
# - Precompiled headers per layer (awb_precompile): Eigen for the core, Qt for the others.
# - Unity builds (awb_unity) for the Qt layers, whose files are short and mostly Qt headers;
#   not for the core, whose files are the ones edited most and each already long.
# AWB_FAST_BUILD=OFF turns precompiled headers and unity builds off, so that a file that does
# not include what it uses shows (each file then compiles alone with only its own includes).

option(AWB_FAST_BUILD "Precompiled headers and unity builds" ON)
option(AWB_CCACHE "Compile through ccache when it is installed" ON)

find_program(AWB_CCACHE_PROGRAM ccache)
if(AWB_CCACHE AND AWB_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env CCACHE_DEPEND=1
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=1
        CCACHE_IGNOREOPTIONS=-DQT_TESTCASE_*
        ${AWB_CCACHE_PROGRAM})
endif()

include(CheckLinkerFlag)
check_linker_flag(CXX -fuse-ld=lld AWB_HAVE_LLD)
if(AWB_HAVE_LLD)
    add_link_options(-fuse-ld=lld)
endif()

# Precompiles the given headers for `target` (PRIVATE: the target's own sources only).
function(awb_precompile target)
    if(AWB_FAST_BUILD)
        target_precompile_headers(${target} PRIVATE ${ARGN})
    endif()
endfunction()

# Compiles the sources of `target` in batches of `batch` files.
function(awb_unity target batch)
    if(AWB_FAST_BUILD)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
    endif()
endfunction()
