#include "assets/environment_images.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <system_error>

#include "assets/cube_cross.hpp"
#include "assets/cubemap_loader.hpp"
#include "assets/image_io.hpp"
#include "assets/procedural.hpp"

namespace puddle::assets {
namespace {

Result<std::array<std::string, 6>> split_six(const std::string& spec) {
    std::array<std::string, 6> paths;
    std::size_t start = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        const std::size_t bar = spec.find('|', start);
        if ((i < 5) == (bar == std::string::npos))
            return make_error(
                ExitCode::Asset,
                "environment.image: expected a folder, one image or six paths (px, nx, py, ny, pz, nz), "
                "got '{}'",
                spec);
        paths[i] = spec.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
        start = bar + 1;
    }
    return paths;
}

// One image is a panorama (2:1) or a cube cross (4:3 or 3:4); anything else is refused.
Result<void> check_single_image_shape(const std::string& path, int w, int h) {
    if (cross_layout(w, h) != CrossLayout::None || w == 2 * h) return {};
    return make_error(
        ExitCode::Asset,
        "environment.image: {} is {}x{}: expected an equirectangular panorama twice as wide as high "
        "(2:1, e.g. 2048x1024), or a cube cross (4:3 or 3:4)",
        path, w, h);
}

// One image: a panorama or a cross, told apart by its proportions. The shape is checked on the header
// first, so a wrong file is refused without decoding it; then again on the pixels, should the file
// have changed in between.
Result<EnvironmentImages> load_single_image(const std::string& path) {
    auto header = probe_color_image(path);
    if (!header) return header.error();
    if (auto shape = check_single_image_shape(path, header->width, header->height); !shape)
        return shape.error();
    auto image = read_color_image(path);
    if (!image) return image.error();
    if (auto shape = check_single_image_shape(path, image->width, image->height); !shape)
        return shape.error();
    EnvironmentImages env;
    env.source = path;
    if (const CrossLayout layout = cross_layout(image->width, image->height); layout != CrossLayout::None) {
        auto cube = split_cube_cross(*image, layout, path);
        if (!cube) return cube.error();
        env.faces = std::move(cube).value();
        return env;
    }
    env.panorama = std::move(image).value();
    return env;
}

}  // namespace

Result<EnvironmentImages> load_environment_images(const std::string& spec, int procedural_face_size,
                                                  SkyClouds procedural_clouds) {
    EnvironmentImages env;
    Result<CubeImages> cube = CubeImages{};
    std::error_code ec;
    if (spec.empty()) {
        cube = night_sky_cubemap(std::clamp(procedural_face_size, 1, procedural_sky_max_face_size), 7,
                                 procedural_clouds);
    } else if (spec.find('|') != std::string::npos) {
        auto paths = split_six(spec);
        if (!paths) return paths.error();
        cube = load_cubemap_faces(*paths);
    } else if (std::filesystem::is_directory(spec, ec)) {
        cube = load_cubemap_folder(spec);
    } else {
        return load_single_image(spec);
    }
    if (!cube) return cube.error();
    env.source = cube->source;
    env.faces = std::move(cube).value();
    return env;
}

}  // namespace puddle::assets
