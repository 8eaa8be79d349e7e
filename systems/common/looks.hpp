#pragma once
// The looks registry: every look that needs pipelines of its own (a scene, a drop model) adds one entry
// from its plugin, and start-up and the look switch (systems/common/look_switch.hpp) go through the
// entries instead of naming each look. A new look is then its folder, one choice in params.def and one
// plugin line in systems/puddle/puddle_plugin.cpp (docs/architecture.md, "Adding a look").

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gpu/device.hpp"
#include "systems/common/shown_look.hpp"
#include "util/result.hpp"

namespace puddle::systems {

struct LookEntry {
    Scene scene = Scene::puddle;
    std::optional<DropModel> drops;  // set for a drop model of the puddle; any drops for another scene
    // Builds the look's pipelines now (start-up, when the config chose it): a broken shader stops
    // start-up with its message.
    std::function<Result<void>(gpu::Device&)> prepare;
    // Has them built off the frame thread (render::PipelineCache::request); true once all are ready.
    // Called every frame while the look is chosen and not yet shown.
    std::function<bool(gpu::Device&)> request;
    // Whether the rain overlay's streaks (overlay.rain) fall in front of this look. The window's glass is
    // in focus and the rain beyond it is not, so sharp streaks there would be wrong.
    bool takes_rain_overlay = true;

    bool matches(const ShownLook& look) const {
        return look.scene == scene && (!drops || look.drops == *drops);
    }
};

// Resource, filled by the looks' plugins at start-up and read-only afterwards. The entries' functions hold
// references to their looks' resources, which live as long as the world.
struct Looks {
    std::vector<LookEntry> entries;

    // The entry that draws `look`, or null for a look that needs none of its own (the puddle with pulse
    // drops: its passes are built with the wave field).
    const LookEntry* find(const ShownLook& look) const;
    // Whether `look` has the rain overlay's streaks when overlay.rain is on (LookEntry::takes_rain_overlay;
    // a look without an entry does).
    bool takes_rain_overlay(const ShownLook& look) const;
};

// Start-up, after every look's plugin: builds the pipelines of the look the config chose.
Result<void> prepare_chosen_look(gpu::Device& device, const Looks& looks, const ShownLook& chosen);

}  // namespace puddle::systems
