#pragma once
// The procedural sky's drifting clouds (assets/cloud_layer.hpp): the layer's tile on the GPU and where it
// has drifted to. The puddle shader lays it over a cube made with room for it (Environment::cloud_room).

#include <glm/vec2.hpp>

#include "assets/cloud_layer.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct Clouds {
    gpu::Texture layer;  // assets::cloud_layer_image: coverage in R, tiling, mipmapped
    gpu::Sampler sampler;
    assets::CloudLight light;
    // Layer coordinates (in tiles, each in [0, 1)) the drift has moved the clouds by, toward +x and +z.
    glm::vec2 offset{0.0f};
};

// Makes the tile (a 256x256 image, a few milliseconds) and uploads it; a GPU error is an error with exit
// code 5.
Result<void> build_clouds(gpu::Device& device, Clouds& clouds);

// Render stage, before the looks: the clouds have drifted environment.cloud_drift deck heights a minute
// toward +x and +z (0.8, 0.6) since the simulation began, computed from the clock's time (not summed frame by
// frame) so that every screen of a wall shows the same sky and months lose no precision. A new
// environment.cloud_drift moves them to where that speed would have taken them.
void cloud_drift_system(const params::Params& params, const FrameClock& clock, Clouds& clouds);

}  // namespace puddle::systems
