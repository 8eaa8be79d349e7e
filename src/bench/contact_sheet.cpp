// puddle-contact-sheet: every preset, and the ocean and the street, rendered headless after the same time
// and tiled into one PNG, to compare the looks at a glance (docs/benchmarks.md, "Contact sheet").
//
//   build/puddle-contact-sheet [--seconds S] [--tile WIDTHxHEIGHT] [--columns N] [--config FILE] SHEET.png
//
// Each tile is what `puddle --backend headless --preset NAME --frames (S x 60)` would write, scaled to the
// tile by rendering at its size; the legend (tile -> look) is printed one line each, left to right and
// top to bottom.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/engine.hpp"
#include "app/startup.hpp"
#include "assets/image_io.hpp"
#include "params/param_types.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace {

using namespace puddle;

struct Look {
    std::string label;   // for the legend
    std::string preset;  // empty: none
    std::vector<std::string> sets;
};

// The looks on the sheet: the default, each preset by name, then the other scenes.
std::vector<Look> looks_to_show(const app::CliOptions& base) {
    std::vector<Look> looks{{"default", "", {}}};
    const auto tuning = app::load_tuning(base, app::StartFor::check);
    if (tuning)
        for (const std::string& name : tuning->layers.presets().names()) looks.push_back({name, name, {}});
    // Every other scene params.def lists, so a new look is on the sheet without naming it here.
    for (const std::string_view scene : params::choice_names<params::SceneKind>())
        if (scene != params::choice_name(params::SceneKind::puddle))
            looks.push_back(
                {fmt::format("scene.kind = {}", scene), "", {fmt::format("scene.kind={}", scene)}});
    return looks;
}

Result<assets::Image> render_look(const app::CliOptions& base, const Look& look, glm::ivec2 tile,
                                  int frames) {
    app::CliOptions o = base;
    o.preset = look.preset;
    o.sets.insert(o.sets.end(), look.sets.begin(), look.sets.end());
    auto tuning = app::load_tuning(o, app::StartFor::check);
    if (!tuning) return tuning.error();
    platform::DisplayOptions display{.backend = platform::BackendKind::Headless, .size = tile};
    auto engine = app::Engine::create(tuning->layers.compose(), display, {}, {systems::add_puddle_plugin});
    if (!engine) return engine.error();
    for (int i = 0; i < frames; ++i)
        if (auto r = (*engine)->frame(1.0 / 60.0); !r) return r.error();
    return (*engine)->read_frame();
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 10.0;
    std::string tile_text = "640x360", output, config;
    int columns = 3;
    CLI::App cli{"Every preset, the ocean and the street after the same time, tiled into one PNG",
                 "puddle-contact-sheet"};
    cli.add_option("--seconds", seconds, "Simulated seconds before each tile is taken (default 10)")
        ->check(CLI::Range(0.0, 600.0));
    cli.add_option("--tile", tile_text, "Size of one tile, WIDTHxHEIGHT (default 640x360)");
    cli.add_option("--columns", columns, "Tiles a row (default 3)")->check(CLI::Range(1, 16));
    cli.add_option("--config", config, "A config file whose presets folder is shown too");
    cli.add_option("SHEET", output, "Where the PNG goes")->required();
    CLI11_PARSE(cli, argc, argv);
    spdlog::set_level(spdlog::level::warn);

    unsigned w = 0, h = 0;
    if (std::sscanf(tile_text.c_str(), "%ux%u", &w, &h) != 2 || w < 16 || h < 16 || w > 3840 || h > 2160) {
        std::fprintf(stderr, "puddle-contact-sheet: --tile %s: expected WIDTHxHEIGHT, 16x16 to 3840x2160\n",
                     tile_text.c_str());
        return 2;
    }
    const glm::ivec2 tile(static_cast<int>(w), static_cast<int>(h));
    // Said before a minute of rendering, not after it.
    const std::filesystem::path folder = std::filesystem::absolute(output).parent_path();
    if (std::error_code ec; !std::filesystem::is_directory(folder, ec)) {
        std::fprintf(stderr, "puddle-contact-sheet: %s: the folder %s does not exist\n", output.c_str(),
                     folder.string().c_str());
        return 2;
    }
    app::CliOptions base;
    base.config_path = config;
    const std::vector<Look> looks = looks_to_show(base);
    const int rows = (static_cast<int>(looks.size()) + columns - 1) / columns;
    assets::Image sheet = assets::Image::make(tile.x * columns, tile.y * rows);
    std::fill(sheet.data.begin(), sheet.data.end(), std::uint8_t{0});
    for (std::size_t i = 0; i < sheet.data.size(); i += 4) sheet.data[i + 3] = 255;

    const int frames = static_cast<int>(seconds * 60.0 + 0.5);
    for (std::size_t i = 0; i < looks.size(); ++i) {
        const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
        std::printf("row %d, column %d: %s\n", row + 1, col + 1, looks[i].label.c_str());
        std::fflush(stdout);
        auto image = render_look(base, looks[i], tile, frames);
        if (!image) {
            std::fprintf(stderr, "puddle-contact-sheet: %s: %s (tile left black)\n", looks[i].label.c_str(),
                         image.error().message.c_str());
            continue;
        }
        for (int y = 0; y < tile.y; ++y)
            std::copy_n(image->pixel8(0, y), 4 * tile.x, sheet.pixel8(col * tile.x, row * tile.y + y));
    }
    if (auto r = assets::write_png(output, sheet); !r) {
        std::fprintf(stderr, "puddle-contact-sheet: %s\n", r.error().message.c_str());
        return 1;
    }
    std::printf("contact sheet: %s (%zu looks after %g s, %dx%d tiles)\n",
                std::filesystem::absolute(output).string().c_str(), looks.size(), seconds, tile.x, tile.y);
    return 0;
}
