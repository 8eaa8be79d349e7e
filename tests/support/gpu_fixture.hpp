#pragma once
// GPU tests: a headless Engine (Mesa surfaceless EGL; llvmpipe in CI) with chosen parameters.

#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>

#include "app/engine.hpp"
#include "systems/puddle_plugin.hpp"
#include "params/param_store.hpp"

namespace puddle::test {

// Parameters from "name=value" strings, as --set takes them; a bad one fails the test.
params::Params make_params(std::initializer_list<std::string> sets);

// A headless engine of the given size; fails the test (and returns null) when EGL cannot start.
std::unique_ptr<app::Engine> make_engine(const params::Params& params, glm::ivec2 size = {192, 108},
                                         const gpu::DeviceOptions& device = {});

// Runs `frames` frames of `dt` seconds; returns the last frame.
assets::Image render_frames(app::Engine& engine, int frames, double dt = 1.0 / 60.0);

}  // namespace puddle::test
