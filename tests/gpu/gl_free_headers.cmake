# ctest gpu_headers_gl_free: every public header compiles alone without reaching a GL or EGL header.
#
# Public: every .hpp/.h under src/ and systems/ except src/platform/ and the gpu layer's private GL
# headers, src/gpu/gl.hpp and src/gpu/gl_*.hpp (only src/gpu/*.cpp, src/platform and their tests include
# those). Each public header is compiled on its own (-fsyntax-only) with an include directory in front
# whose GLES3/, GLES2/, EGL/ and KHR/ headers are `#error`s, so a GL include anywhere below it, however
# indirect, fails with the chain of includes that reached it.
#
# cmake -DCXX=<compiler> -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch dir> -P gl_free_headers.cmake

cmake_minimum_required(VERSION 3.25)

foreach(var CXX SOURCE_DIR WORK_DIR)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "gl_free_headers.cmake: -D${var}=... is required")
    endif()
endforeach()

set(poison_dir ${WORK_DIR}/poison)
set(marker "puddle: a public header reached a GL/EGL header")
foreach(h GLES3/gl3.h GLES3/gl31.h GLES3/gl32.h GLES3/gl3platform.h GLES2/gl2.h GLES2/gl2ext.h
          GLES2/gl2platform.h EGL/egl.h EGL/eglext.h EGL/eglplatform.h KHR/khrplatform.h)
    file(WRITE ${poison_dir}/${h} "#error \"${marker} (${h}); include it only from src/gpu/gl*.hpp, src/gpu/*.cpp and src/platform\"\n")
endforeach()

file(GLOB_RECURSE headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/src/*.hpp ${SOURCE_DIR}/src/*.h
     ${SOURCE_DIR}/systems/*.hpp ${SOURCE_DIR}/systems/*.h)
list(FILTER headers EXCLUDE REGEX "^src/platform/")
list(FILTER headers EXCLUDE REGEX "^src/gpu/gl(_[a-z0-9_]+)?\\.hpp$")
list(SORT headers)

set(failed "")
foreach(header IN LISTS headers)
    string(MAKE_C_IDENTIFIER ${header} tu_name)
    set(tu ${WORK_DIR}/${tu_name}.cpp)
    file(WRITE ${tu} "#include \"${SOURCE_DIR}/${header}\"\n")
    execute_process(
        COMMAND ${CXX} -std=c++20 -fsyntax-only -Wfatal-errors -DGLM_FORCE_CXX17 -DPUDDLE_VERSION="0"
                -I${poison_dir} -I${SOURCE_DIR}/src -I${SOURCE_DIR} ${tu}
        RESULT_VARIABLE rc
        OUTPUT_VARIABLE out
        ERROR_VARIABLE out)
    if(rc EQUAL 0)
        continue()
    endif()
    list(APPEND failed ${header})
    if(out MATCHES "${marker}")
        message("gpu_headers_gl_free: ${header} reaches a GL/EGL header; the includes that lead there:")
    else()
        message("gpu_headers_gl_free: ${header} does not compile on its own:")
    endif()
    # The include chain and the first error (-Wfatal-errors: the only one) are enough to find the culprit.
    string(REPLACE ";" "," out "${out}")
    string(REPLACE "\n" ";" lines "${out}")
    list(SUBLIST lines 0 12 head)
    list(JOIN head "\n" head)
    message("${head}\n")
endforeach()

# Sources outside src/gpu and src/platform may not include GL, EGL or the gpu layer's private GL headers
# either: without them a .cpp cannot call gl* (DESIGN.md: "gl* calls live in src/gpu and src/platform").
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/src/*.cpp ${SOURCE_DIR}/systems/*.cpp)
list(FILTER sources EXCLUDE REGEX "^src/(gpu|platform)/")
set(gl_include_pattern "#[ \t]*include[ \t]*[<\"](GLES[23]?/|EGL/|KHR/|gpu/gl\\.hpp|gpu/gl_)")
foreach(source IN LISTS sources)
    file(STRINGS ${SOURCE_DIR}/${source} hits REGEX "${gl_include_pattern}")
    if(hits)
        list(APPEND failed ${source})
        message("gpu_headers_gl_free: ${source} includes GL or EGL: ${hits}")
    endif()
endforeach()
list(LENGTH sources sources_checked)

list(LENGTH headers checked)
math(EXPR checked "${checked} + ${sources_checked}")
list(LENGTH failed n_failed)
if(n_failed GREATER 0)
    list(JOIN failed ", " failed_list)
    message(FATAL_ERROR "gpu_headers_gl_free: ${n_failed} of ${checked} public headers and sources fail: ${failed_list}")
endif()
message("gpu_headers_gl_free: ${checked} public headers and sources outside src/gpu and src/platform are free of GL and EGL")
