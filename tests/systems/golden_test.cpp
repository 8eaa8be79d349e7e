// Golden images: whole pictures for several parameter sets, compared with tests/golden/*.png
// (support/golden.hpp: the tolerance, and how to regenerate them after an intended change of look).
#include "support/golden.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

struct GoldenCase {
    const char* name;
    std::initializer_list<std::string> sets;
};

constexpr glm::ivec2 golden_size{480, 270};

TEST(Golden, DefaultNightPuddle) {
    // The program's own defaults throughout (the README shows this picture).
    check_golden("default", render_with({}, 90, golden_size));
}

TEST(Golden, MurkyPondOnCobblesRaymarched) {
    check_golden("murky_pond", render_with({"ground.checkerboard=false", "water.turbidity=0.08",
                                            "water.tint=0.05,0.09,0.04", "puddle.depth=8",
                                            "render.method=raymarch", "rain.rate=1.5"},
                                           90, golden_size));
}

TEST(Golden, DownpourMirrorTurnedSky) {
    check_golden("downpour",
                 render_with({"rain.rate=14", "rain.drift=0.3", "rain.intensity=0.25", "water.reflectivity=1",
                              "environment.rotation=2.5", "look.fog_density=0.02", "look.vignette=0.8",
                              "camera.position=25,10,0", "camera.target=-40,2,0"},
                             90, golden_size));
}

// An HDR environment (made here: a city at night whose windows are 4 to 16 times brighter than white,
// written as a Radiance .hdr like a Poly Haven download) reflected in the rain: the HDR picture of
// docs/environments.md.
TEST(Golden, HdrCityLightsInTheRain) {
    TempDir dir;
    const std::string sky = (dir / "city.hdr").string();
    write_float_image(sky, city_lights_panorama(1024));
    check_golden("hdr_city_lights",
                 render_with({"environment.image=" + sky, "camera.position=0,9,34", "camera.target=0,3,-10",
                              "rain.rate=4", "water.reflectivity=1", "ground.checkerboard=false",
                              "look.fog_density=0.004"},
                             90, golden_size));
}

// Scenes and drop models, smaller: one picture each, also shown in docs/scenes.md. None of them
// needs the wave field to settle (they are functions of time), so a few frames suffice.
constexpr glm::ivec2 scene_golden_size{320, 180};

// The default camera looks out to the horizon; the reference's (0, 5, 5) looks down at the water.
TEST(Golden, OceanScene) {
    check_golden("ocean", render_with({"scene.kind=ocean"}, 4, scene_golden_size));
}

TEST(Golden, OceanSceneFromTheReferencesCamera) {
    check_golden("ocean_looking_down",
                 render_with({"scene.kind=ocean", "ocean.camera_position=0,5,5", "ocean.camera_target=0,0,0"},
                             4, scene_golden_size));
}

TEST(Golden, RainyStreetWithRainOverlay) {
    check_golden("street", render_with({"scene.kind=street", "overlay.rain=true"}, 4, scene_golden_size));
}

// Rain on a window at night: beads, running drops and the city's lights out of focus behind the glass.
TEST(Golden, RainOnAWindow) {
    check_golden("window", render_with({"scene.kind=window"}, 4, scene_golden_size));
}

TEST(Golden, PuddleAnalyticRipples) {
    check_golden("analytic", render_with({"drops.model=analytic"}, 4, scene_golden_size));
}

TEST(Golden, PuddleGridDrops) {
    check_golden("grid", render_with({"drops.model=grid"}, 4, scene_golden_size));
}

}  // namespace
}  // namespace puddle::test
