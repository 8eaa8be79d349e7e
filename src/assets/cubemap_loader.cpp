#include "assets/cubemap_loader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <system_error>
#include <utility>

#include "assets/image_io.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

// Looked for in this order; the first one present wins.
constexpr std::array<const char*, 10> face_extensions{"png", "jpg",  "jpeg", "hdr", "exr",
                                                      "tif", "tiff", "bmp",  "tga", "webp"};

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string looked_for(const char* face) {
    std::string list;
    for (const char* ext : face_extensions) {
        if (!list.empty()) list += ", ";
        list += std::string(face) + "." + ext;
    }
    return list;
}

// Names faces in messages briefly when they share a folder ("px.jpg"), in full when they do not.
std::string short_name(const fs::path& path, const fs::path& beside) {
    return path.parent_path() == beside.parent_path() ? path.filename().string() : path.string();
}

// GL requires square faces of one size; say which file breaks that and against what. `sizes` are
// width, height pairs in face order.
Result<void> check_face_sizes(const std::array<std::string, 6>& paths,
                              const std::array<std::pair<int, int>, 6>& sizes) {
    const auto [w0, h0] = sizes[0];
    if (w0 != h0)
        return make_error(ExitCode::Asset,
                          "cubemap: {} is {}x{}: all six faces must be square and the same size", paths[0],
                          w0, h0);
    for (std::size_t i = 1; i < paths.size(); ++i) {
        const auto [w, h] = sizes[i];
        if (w != w0 || h != h0)
            return make_error(
                ExitCode::Asset,
                "cubemap: {} is {}x{} but {} is {}x{}: all six faces must be square and the same size",
                paths[i], w, h, short_name(paths[0], paths[i]), w0, h0);
    }
    return {};
}

Result<CubeImages> load_faces(const std::array<std::string, 6>& paths, std::string source) {
    // Every header first: a face of the wrong size is refused before any face is decoded.
    std::array<std::pair<int, int>, 6> sizes;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        auto header = probe_color_image(paths[i]);
        if (!header) return header.error();
        sizes[i] = {header->width, header->height};
    }
    if (auto fit = check_face_sizes(paths, sizes); !fit) return fit.error();

    CubeImages cube;
    cube.source = std::move(source);
    for (std::size_t i = 0; i < paths.size(); ++i) {
        auto image = read_color_image(paths[i]);
        if (!image) return image.error();
        cube.faces[i] = std::move(image).value();
        sizes[i] = {cube.faces[i].width, cube.faces[i].height};
    }
    // Again on the pixels, should a file have changed since its header was read.
    if (auto fit = check_face_sizes(paths, sizes); !fit) return fit.error();
    // One HDR face makes the cube HDR: the 8-bit ones are decoded to linear to join it.
    const bool any_hdr = std::any_of(cube.faces.begin(), cube.faces.end(),
                                     [](const Image& f) { return f.format == PixelFormat::RGBA32F; });
    if (any_hdr)
        for (Image& face : cube.faces) face = to_linear_float(face);
    return cube;
}

}  // namespace

Result<CubeImages> load_cubemap_folder(const std::string& folder) {
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    if (ec) return make_error(ExitCode::Asset, "cubemap: {}: cannot open: {}", folder, ec.message());
    if (!fs::is_directory(status)) return make_error(ExitCode::Asset, "cubemap: {}: not a folder", folder);

    // Index the folder once by lower-case name, so PX.JPG is found as px.jpg; sorted for a stable pick.
    std::map<std::string, fs::path> by_name;
    std::vector<fs::path> entries;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        entries.push_back(it->path());
    if (ec) return make_error(ExitCode::Asset, "cubemap: {}: cannot list: {}", folder, ec.message());
    std::sort(entries.begin(), entries.end());
    for (const fs::path& entry : entries) by_name.emplace(lower(entry.filename().string()), entry);

    std::array<std::string, 6> paths;
    for (std::size_t i = 0; i < cube_face_names.size(); ++i) {
        const char* face = cube_face_names[i];
        for (const char* ext : face_extensions) {
            auto found = by_name.find(std::string(face) + "." + ext);
            if (found != by_name.end()) {
                paths[i] = found->second.string();
                break;
            }
        }
        if (paths[i].empty())
            return make_error(ExitCode::Asset, "cubemap: {}: no face image for '{}' (looked for {})", folder,
                              face, looked_for(face));
    }
    return load_faces(paths, folder);
}

Result<CubeImages> load_cubemap_faces(const std::array<std::string, 6>& paths) {
    // Logs show the common folder when there is one, else every path.
    const fs::path parent = fs::path(paths[0]).parent_path();
    const bool one_folder = std::all_of(paths.begin(), paths.end(), [&](const std::string& p) {
        return fs::path(p).parent_path() == parent;
    });
    std::string source;
    if (one_folder) {
        source = parent.empty() ? std::string(".") : parent.string();
    } else {
        for (const std::string& p : paths) source += (source.empty() ? "" : ", ") + p;
    }
    return load_faces(paths, source);
}

}  // namespace puddle::assets
