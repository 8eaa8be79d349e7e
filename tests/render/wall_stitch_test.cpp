// Video walls: the screens of a 2x2 wall, each a headless engine of its own rendering its tile
// of the view at the same step, join into the picture of the whole view rendered by one engine, for every
// scene, with bezels and with portrait screens; in mirror mode every screen shows the whole picture.
// Tolerance: the golden images' (tests/systems/golden_test.cpp): mean channel difference at most 1.5 of
// 255, at most 1% of pixels off by more than 32. A tile that rendered its own full frustum, vignette,
// horizon or rain (the code before the wall) repeats the whole picture four times smaller and fails by far.
// Each case writes its stitched picture to test-output/wall_<case>.png, to be looked at.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "assets/image_io.hpp"
#include "support/golden.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr glm::ivec2 tile_size{96, 64};  // one screen's upright picture, pixels (portrait walls: 64x96)
constexpr int columns = 2, rows = 2;

struct SceneCase {
    const char* name;
    std::vector<std::string> sets;
    int frames;  // at 60 fps; the wave field needs a few dozen steps to show ripples
};

// A failure names the case, not its bytes.
void PrintTo(const SceneCase& scene, std::ostream* os) {
    *os << scene.name;
}

// Every scene and drop model, and the rain overlay (over the puddle).
const std::vector<SceneCase>& scene_cases() {
    static const std::vector<SceneCase> cases{
        {"puddle_pulse", {}, 30},
        {"puddle_analytic", {"drops.model=analytic"}, 4},
        {"puddle_grid", {"drops.model=grid"}, 4},
        {"ocean", {"scene.kind=ocean"}, 4},
        {"street", {"scene.kind=street"}, 4},
        {"window", {"scene.kind=window"}, 4},
        {"rain_overlay", {"overlay.rain=true", "overlay.rain_opacity=1"}, 30},
    };
    return cases;
}

// The last of `frames` frames of a headless screen of `size` pixels with these --set values.
assets::Image render(const std::vector<std::string>& sets, glm::ivec2 size, int frames) {
    params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
    apply_sets(p, sets);
    auto engine = make_engine(p, size);
    if (!engine) return {};
    return render_frames(*engine, frames);
}

// The --set values that make a screen the tile (column, row) of the wall.
std::vector<std::string> tile_sets(std::vector<std::string> sets, int column, int row, glm::ivec2 bezel,
                                   int rotation = 0) {
    for (const std::string& s :
         {"wall.columns=" + std::to_string(columns), "wall.rows=" + std::to_string(rows),
          "wall.column=" + std::to_string(column), "wall.row=" + std::to_string(row),
          "wall.bezel_x=" + std::to_string(bezel.x), "wall.bezel_y=" + std::to_string(bezel.y),
          "wall.rotation=" + std::to_string(rotation)})
        sets.push_back(s);
    return sets;
}

// The upright picture of a screen whose picture was turned a quarter clockwise `turns` times (as seen
// on it): each quarter turned back counter-clockwise, so the screen's right edge is the picture's top.
assets::Image unturn(assets::Image screen, int turns) {
    for (int t = 0; t < turns; ++t) {
        assets::Image upright = assets::Image::make(screen.height, screen.width);
        for (int v = 0; v < upright.height; ++v)
            for (int u = 0; u < upright.width; ++u) {
                const std::uint8_t* from = screen.pixel8(screen.width - 1 - v, u);
                std::copy(from, from + 4, upright.pixel8(u, v));
            }
        screen = std::move(upright);
    }
    return screen;
}

// The rectangle of `image` at (x, y), top left, of `size` pixels.
assets::Image crop(const assets::Image& image, int x, int y, glm::ivec2 size) {
    assets::Image out = assets::Image::make(size.x, size.y);
    for (int row = 0; row < size.y; ++row) {
        const std::uint8_t* from = image.pixel8(x, y + row);
        std::copy(from, from + 4 * size.x, out.pixel8(0, row));
    }
    return out;
}

void paste(assets::Image& into, const assets::Image& tile, int x, int y) {
    for (int row = 0; row < tile.height; ++row) {
        const std::uint8_t* from = tile.pixel8(0, row);
        std::copy(from, from + 4 * tile.width, into.pixel8(x, y + row));
    }
}

void expect_within_golden_tolerance(const assets::Image& actual, const assets::Image& expected,
                                    const std::string& what) {
    const ImageDiff d = compare_images(actual, expected, 32);
    EXPECT_LE(d.mean_abs_diff, 1.5) << what << " (max channel difference " << d.max_channel_diff << ")";
    EXPECT_LE(d.fraction_over, 0.01) << what;
}

// Renders the wall's four screens, each showing an `upright` tile (`turns` quarter turns on its display,
// so its display is the tile turned) and the whole view; each tile, turned upright, must equal its crop of
// the whole view, bezel gaps left out. Returns the tiles pasted where they sit in the wall, the gaps black.
assets::Image check_wall(const SceneCase& scene, glm::ivec2 bezel, int turns = 0,
                         glm::ivec2 upright = tile_size) {
    const glm::ivec2 whole_size =
        glm::ivec2(columns, rows) * upright + glm::ivec2(columns - 1, rows - 1) * bezel;
    const assets::Image whole = render(scene.sets, whole_size, scene.frames);
    assets::Image stitched = assets::Image::make(whole_size.x, whole_size.y);
    for (std::size_t i = 3; i < stitched.data.size(); i += 4) stitched.data[i] = 255;  // opaque black gaps
    if (whole.empty()) {
        ADD_FAILURE() << "the whole view did not render";
        return stitched;
    }
    const glm::ivec2 display = turns % 2 ? glm::ivec2(upright.y, upright.x) : upright;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const assets::Image tile = unturn(
                render(tile_sets(scene.sets, column, row, bezel, turns), display, scene.frames), turns);
            if (tile.width != upright.x || tile.height != upright.y) {
                ADD_FAILURE() << "tile " << column << ", " << row << " did not render";
                continue;
            }
            const glm::ivec2 at = glm::ivec2(column, row) * (upright + bezel);  // rows from the top
            expect_within_golden_tolerance(tile, crop(whole, at.x, at.y, upright),
                                           std::string(scene.name) + ": tile column " +
                                               std::to_string(column) + ", row " + std::to_string(row));
            paste(stitched, tile, at.x, at.y);
        }
    if (bezel == glm::ivec2(0))
        expect_within_golden_tolerance(stitched, whole, std::string(scene.name) + ": stitched");
    return stitched;
}

void keep_for_inspection(const assets::Image& image, const std::string& name) {
    const auto path = output_dir() / ("wall_" + name + ".png");
    EXPECT_TRUE(assets::write_png(path.string(), image).ok()) << path;
}

class SeamlessWall : public ::testing::TestWithParam<SceneCase> {};

// Bezels 0: the four tiles side by side are the whole view.
TEST_P(SeamlessWall, StitchedTilesEqualTheWholeView) {
    keep_for_inspection(check_wall(GetParam(), {0, 0}), GetParam().name);
}

// Bezels of 10 and 6 pixels: each tile is the whole view's crop beside the gaps (what the frames hide).
// The default look's stitched wall is also a golden image: docs/video-walls.md shows it.
TEST_P(SeamlessWall, TilesBesideBezelsEqualTheirCropOfTheWholeView) {
    const assets::Image stitched = check_wall(GetParam(), {10, 6});
    keep_for_inspection(stitched, std::string(GetParam().name) + "_bezels");
    if (std::string(GetParam().name) == "puddle_pulse") check_golden("wall_2x2_bezels", stitched);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SeamlessWall, ::testing::ValuesIn(scene_cases()),
                         [](const auto& scene) { return std::string(scene.param.name); });

// A wall of portrait screens: each display is a landscape 96x64 turned on its side (wall.rotation = 1),
// so its picture is an upright 64x96 tile; turned back, the tiles are their crops of the 138x198 view.
TEST(SeamlessWallRotated, PortraitScreensShowTheirTilesUpright) {
    for (const SceneCase& scene : {scene_cases()[0], scene_cases()[4]})
        keep_for_inspection(check_wall(scene, {10, 6}, 1, {64, 96}), std::string(scene.name) + "_rotated");
}

// Mirror mode: every screen, whatever its column and row, shows the whole picture at its own size.
TEST(MirrorWall, EveryScreenShowsTheWholePicture) {
    const SceneCase& scene = scene_cases()[4];  // the street: its horizon and vignette are in screen space
    const assets::Image whole = render(scene.sets, tile_size, scene.frames);
    ASSERT_FALSE(whole.empty());
    for (const auto& [column, row] : {std::pair{0, 0}, std::pair{1, 1}}) {
        std::vector<std::string> sets = tile_sets(scene.sets, column, row, {10, 6});
        sets.push_back("wall.mode=mirror");
        expect_within_golden_tolerance(
            render(sets, tile_size, scene.frames), whole,
            "mirror: column " + std::to_string(column) + ", row " + std::to_string(row));
    }
    // The same screen in tile mode shows only its quarter: far from the whole picture.
    const ImageDiff tiled =
        compare_images(render(tile_sets(scene.sets, 1, 1, {10, 6}), tile_size, scene.frames), whole, 32);
    EXPECT_GT(tiled.mean_abs_diff, 1.5);
}

}  // namespace
}  // namespace puddle::test
