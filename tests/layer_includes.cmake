# ctest layer_includes: each layer's files include only what its row of docs/architecture.md's table may use.
#
# The table is written once, in CMakeLists.txt's puddle_layer(NAME SOURCES... USES...) calls; tests/CMakeLists.txt
# passes it here as LAYERS, "name|folder|use,...|source,...|headers" entries joined by "!". A library's sources
# are read, and its folder's headers too where the last field says `headers` (libpuddle-images.so shares
# src/assets with the assets layer and owns no header there). In each file:
# - `#include "<folder>/..."` of another layer needs that layer in USES (src/util is everyone's);
# - a package's header (table below) needs that package's target in USES.
# The static libraries are linked PRIVATE and every layer is linked once with --no-undefined, but a header-only
# use (an inline function, a template) reaches past both; this check does not.
#
# cmake -DSOURCE_DIR=<repo> -DLAYERS=<list> -P layer_includes.cmake

cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR LAYERS)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "layer_includes.cmake: -D${var}=... is required")
    endif()
endforeach()

string(REPLACE "!" ";" LAYERS "${LAYERS}")

# Package target -> the headers that belong to it (regular expressions on the include's path); a header is
# allowed when any package it belongs to is used.
set(package_headers
    "PkgConfig::EGL|^(EGL|KHR)/"
    "PkgConfig::GLESV2|^(GLES[23]?|KHR)/"
    "PkgConfig::GBM|^gbm\\.h$"
    "PkgConfig::DRM|^(xf86drm|xf86drmMode|drm_fourcc|drm|drm_mode)\\.h$|^libdrm/"
    "puddle_drm_headers|^drm_fourcc\\.h$"
    "PkgConfig::X11|^X11/"
    "PkgConfig::GPIOD|^gpiod\\.h$"
    "PkgConfig::JPEG|^(jpeglib|jerror|turbojpeg)\\.h$"
    "PkgConfig::PNG|^png\\.h$"
    "PkgConfig::OIIO|^OpenImageIO/"
    "PkgConfig::MOSQUITTO|^mosquitto\\.h$"
    "nlohmann_json::nlohmann_json|^nlohmann/"
    "tomlplusplus::tomlplusplus|^toml\\+\\+/"
    "CLI11::CLI11|^CLI/")

# Layer folders, so that an include's first path parts name the layer it reaches.
set(folders "")
foreach(entry IN LISTS LAYERS)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 1 folder)
    list(APPEND folders ${folder})
endforeach()

set(failed "")
set(checked 0)
foreach(entry IN LISTS LAYERS)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 0 name)
    list(GET parts 1 folder)
    list(GET parts 2 uses)
    list(GET parts 3 sources)
    list(GET parts 4 with_headers)
    string(REPLACE "," ";" uses "${uses}")
    string(REPLACE "," ";" sources "${sources}")
    set(allowed_folders ${folder} src/util)
    foreach(use IN LISTS uses)
        if(use MATCHES "^puddle_(.+)$")
            set(used_layer ${CMAKE_MATCH_1})
            foreach(other IN LISTS LAYERS)
                if(other MATCHES "^${used_layer}\\|([^|]+)")
                    list(APPEND allowed_folders ${CMAKE_MATCH_1})
                endif()
            endforeach()
        endif()
    endforeach()

    set(files ${sources})
    if(with_headers STREQUAL "headers")
        file(GLOB_RECURSE headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${folder}/*.hpp ${SOURCE_DIR}/${folder}/*.h)
        list(APPEND files ${headers})
    endif()
    foreach(file IN LISTS files)
        math(EXPR checked "${checked} + 1")
        file(STRINGS ${SOURCE_DIR}/${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
        set(line_failed FALSE)
        foreach(line IN LISTS includes)
            string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*$" "\\1" path "${line}")
            # Another layer's header?
            foreach(other_folder IN LISTS folders)
                string(FIND "${path}" "${other_folder}/" at)
                if(NOT at EQUAL 0)
                    string(REGEX REPLACE "^src/" "" short "${other_folder}")
                    string(FIND "${path}" "${short}/" at)
                    if(NOT at EQUAL 0 OR short STREQUAL other_folder)
                        continue()
                    endif()
                endif()
                if(NOT other_folder IN_LIST allowed_folders)
                    message("layer_includes: ${file}: #include \"${path}\": layer `${name}` (${folder}) may not use ${other_folder}")
                    set(line_failed TRUE)
                endif()
            endforeach()
            # A package's header?
            set(owners "")
            set(used FALSE)
            foreach(package_entry IN LISTS package_headers)
                string(FIND "${package_entry}" "|" bar)
                string(SUBSTRING "${package_entry}" 0 ${bar} package)
                math(EXPR start "${bar} + 1")
                string(SUBSTRING "${package_entry}" ${start} -1 pattern)
                if(path MATCHES "${pattern}")
                    list(APPEND owners ${package})
                    if(package IN_LIST uses)
                        set(used TRUE)
                    endif()
                endif()
            endforeach()
            if(owners AND NOT used)
                list(JOIN owners " or " owners)
                message("layer_includes: ${file}: #include <${path}>: `${name}` (${folder}) does not link ${owners}")
                set(line_failed TRUE)
            endif()
        endforeach()
        if(line_failed)
            list(APPEND failed ${file})
        endif()
    endforeach()
endforeach()

list(LENGTH failed n_failed)
if(n_failed GREATER 0)
    message(FATAL_ERROR "layer_includes: ${n_failed} of ${checked} files include what their layer may not use")
endif()
list(REMOVE_DUPLICATES folders)
message("layer_includes: ${checked} files in ${folders} include only what their library uses")
